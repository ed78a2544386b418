package robot;

import robot.types.*;

component Unit(Mode mode, double gain) {
  port in int raw,
       in int limit,
       out Mode level;

  Ctrl ctrl(mode, gain);
  Logger log;

  raw -> ctrl.raw;
  limit -> ctrl.limit;
  ctrl.level -> level;
  ctrl.reading -> log.reading;
  ctrl.pair -> log.pair;
}
