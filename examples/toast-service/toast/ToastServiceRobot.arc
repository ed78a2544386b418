package toast;

import toast.types.*;

/*
 * The paper's ToastServiceRobot: a robot arm takes bread to a toaster, runs the toaster and
 * delivers the toast to a plate. Sensors and actuators are platform components written by hand;
 * the Controller is an automaton.
 */
component ToastServiceRobot {
  DistanceSensor dist;
  ColorSensor color;
  Controller ctrl(25);
  ArmController arm;
  ToasterActuator toaster;

  dist.value -> ctrl.distance;
  color.value -> ctrl.color;
  ctrl.toaster -> toaster.cmd;
  ctrl.arm -> arm.cmd;
  arm.status -> ctrl.armStatus;
}
