package robot;

import robot.types.*;

/* Golden-file model of the ros2.* generators: nesting, a root in port, arguments, generics. */
component Robot {
  port in int limit,
       out Mode level;

  Sensor sensor;
  Scale scale(3);
  Unit unit(Mode.FAST, 2.5);

  sensor.value -> scale.raw;
  scale.scaled -> unit.raw;
  limit -> unit.limit;
  unit.level -> level;
}
