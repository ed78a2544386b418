"""The application TR (toast.ToastServiceRobot) on the python-timesync platform (generated)."""

from __future__ import annotations

from collections.abc import Mapping
from enum import Enum

from maa_timesync import ComponentType
from maa_timesync.lockstep import LockstepApp
from toast.arm_controller import ArmController as _toast_arm_controller
from toast.color_sensor import ColorSensor as _toast_color_sensor
from toast.controller import Controller as _toast_controller
from toast.distance_sensor import DistanceSensor as _toast_distance_sensor
from toast.plate_locator import PlateLocator as _toast_plate_locator
from toast.toast_service_robot import ToastServiceRobot as _toast_toast_service_robot
from toast.toaster_actuator import ToasterActuator as _toast_toaster_actuator
from toast.toaster_controller import ToasterController as _toast_toaster_controller
from toast.types.types import ArmProgram, ArmStatus, ToastColor, ToasterCmd

APPLICATION = "TR"
ROOT = _toast_toast_service_robot
COMPONENTS: dict[str, type[ComponentType]] = {
    "toast.ArmController": _toast_arm_controller,
    "toast.ColorSensor": _toast_color_sensor,
    "toast.Controller": _toast_controller,
    "toast.DistanceSensor": _toast_distance_sensor,
    "toast.PlateLocator": _toast_plate_locator,
    "toast.ToastServiceRobot": _toast_toast_service_robot,
    "toast.ToasterActuator": _toast_toaster_actuator,
    "toast.ToasterController": _toast_toaster_controller,
}
ENUMS: dict[str, type[Enum]] = {
    "ArmProgram": ArmProgram,
    "ArmStatus": ArmStatus,
    "ToastColor": ToastColor,
    "ToasterCmd": ToasterCmd,
}


def create_controller(parameters: Mapping[str, object]) -> LockstepApp:
    """The simulator's lock-step factory (lockstep.json)."""
    return LockstepApp(ROOT, parameters)
