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
#: Port topics of the lock-step mode (ROS 2 names): "<instance path>.<out port>" of atomic instances
#: and "<in port>" of the root -> (topic, ROS 2 message type).
PORT_TOPICS: dict[str, tuple[str, str]] = {
    "dist.value": ("/toast_service_robot/dist/value", "std_msgs/msg/Int32"),
    "color.value": ("/toast_service_robot/color/value", "std_msgs/msg/String"),
    "plate.angle": ("/toast_service_robot/plate/angle", "std_msgs/msg/Int32"),
    "plate.height": ("/toast_service_robot/plate/height", "std_msgs/msg/Int32"),
    "ctrl.toaster": ("/toast_service_robot/ctrl/toaster", "std_msgs/msg/String"),
    "ctrl.arm": ("/toast_service_robot/ctrl/arm", "std_msgs/msg/String"),
    "toasterCtrl.leverDown": ("/toast_service_robot/toaster_ctrl/lever_down", "std_msgs/msg/Bool"),
    "arm.status": ("/toast_service_robot/arm/status", "std_msgs/msg/String"),
}
#: ROS 2 node names of the atomic instances and mode components (keys of /maa/automaton_states).
NODE_NAMES: dict[str, str] = {
    "dist": "/toast_service_robot/dist",
    "color": "/toast_service_robot/color",
    "plate": "/toast_service_robot/plate",
    "ctrl": "/toast_service_robot/ctrl",
    "toasterCtrl": "/toast_service_robot/toaster_ctrl",
    "toaster": "/toast_service_robot/toaster",
    "arm": "/toast_service_robot/arm",
}

#: The automata table (@maa/protocol AutomatonEntry, for the IDE): instance path -> its entry as JSON.
AUTOMATA: dict[str, str] = {
    "ctrl": "{\"instancePath\":\"ctrl\",\"node\":\"/toast_service_robot/ctrl\",\"component\":\"toast.Controller\",\"file\":\"toast/Controller.arc\",\"states\":[{\"path\":\"Idle\",\"line\":16},{\"path\":\"Loading\",\"line\":17},{\"path\":\"Toasting\",\"line\":18},{\"path\":\"Serving\",\"line\":19}],\"transitions\":[{\"index\":0,\"from\":\"Idle\",\"to\":\"Loading\",\"label\":\"[distance < threshold] / { arm = ArmProgram.LOAD_BREAD; }\",\"line\":22,\"column\":5},{\"index\":1,\"from\":\"Loading\",\"to\":\"Toasting\",\"label\":\"[armStatus == ArmStatus.DONE] / { toaster = ToasterCmd.START; }\",\"line\":23,\"column\":5},{\"index\":2,\"from\":\"Toasting\",\"to\":\"Serving\",\"label\":\"[color == ToastColor.GOLDEN] / { toaster = ToasterCmd.STOP; arm = ArmProgram.PICKUP_AND_DEPLOY; }\",\"line\":24,\"column\":5},{\"index\":3,\"from\":\"Serving\",\"to\":\"Idle\",\"label\":\"[armStatus == ArmStatus.DONE] / { served++; }\",\"line\":25,\"column\":5}]}",
    "toasterCtrl": "{\"instancePath\":\"toasterCtrl\",\"node\":\"/toast_service_robot/toaster_ctrl\",\"component\":\"toast.ToasterController\",\"file\":\"toast/ToasterController.arc\",\"states\":[{\"path\":\"Off\",\"line\":13},{\"path\":\"On\",\"line\":14}],\"transitions\":[{\"index\":0,\"from\":\"On\",\"to\":\"On\",\"label\":\"[cmd != ToasterCmd.STOP && slices < maxSlices] / { slices++; }\",\"line\":19,\"column\":7},{\"index\":1,\"from\":\"Off\",\"to\":\"On\",\"label\":\"[cmd == ToasterCmd.START]\",\"line\":22,\"column\":5},{\"index\":2,\"from\":\"On\",\"to\":\"Off\",\"label\":\"[cmd == ToasterCmd.STOP]\",\"line\":23,\"column\":5},{\"index\":3,\"from\":\"On\",\"to\":\"Off\",\"label\":\"[slices >= maxSlices]\",\"line\":24,\"column\":5}]}",
}


def create_controller(parameters: Mapping[str, object]) -> LockstepApp:
    """The simulator's lock-step factory (lockstep.json)."""
    return LockstepApp(ROOT, parameters, PORT_TOPICS, NODE_NAMES, AUTOMATA)
