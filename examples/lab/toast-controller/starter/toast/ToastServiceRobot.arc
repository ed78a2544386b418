package toast;

import toast.types.*;

/*
 * The paper's ToastServiceRobot: when someone puts a plate in front of the robot, its arm
 * puts bread into the toaster, the toaster runs until the toast is golden, and the arm delivers
 * the toast to the plate. Sensors and actuators are platform components written by hand; the
 * Controller and the ToasterController are automata, the ArmController runs RobotArm programs.
 */
component ToastServiceRobot {
  DistanceSensor dist;
  ColorSensor color;
  PlateLocator plate;
  Controller ctrl(25);
  ToasterController toasterCtrl;
  ToasterActuator toaster;
  ArmController arm;

  dist.value -> ctrl.distance;
  color.value -> ctrl.color;
  ctrl.toaster -> toasterCtrl.cmd;
  toasterCtrl.leverDown -> toaster.leverDown;
  ctrl.arm -> arm.cmd;
  plate.angle -> arm.angle;
  plate.height -> arm.height;
  arm.status -> ctrl.armStatus;
}
