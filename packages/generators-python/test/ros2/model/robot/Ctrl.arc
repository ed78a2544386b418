package robot;

import robot.types.*;

component Ctrl(Mode mode, double gain = 1.0, boolean verbose = true, double bias = 0) {
  port in int raw,
       in int limit,
       <<delayed>> out Mode level,
       out Reading reading,
       out Pair<Integer, Mode> pair;

  int count = 0;

  <<sync>> automaton {
    initial { level = Mode.SLOW; } state Low;
    state High;
    Low -> High [raw * gain > limit] / { level = mode; count++; };
    High -> Low [raw * gain <= limit] / { level = Mode.SLOW; };
  }
}
