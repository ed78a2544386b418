package robot;

import robot.types.*;

<<handwritten>> component Logger {
  port <<sync>> in Reading reading,
       <<sync>> in Pair<Integer, Mode> pair;
}
