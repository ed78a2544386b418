"""Component toast.ToastServiceRobot for the python-timesync platform (generated)."""

from __future__ import annotations

from collections.abc import Mapping
from typing import ClassVar

from maa_timesync import ComponentType, ComposedComponent
from toast.arm_controller import ArmController
from toast.color_sensor import ColorSensor
from toast.controller import Controller
from toast.distance_sensor import DistanceSensor
from toast.plate_locator import PlateLocator
from toast.toaster_actuator import ToasterActuator
from toast.toaster_controller import ToasterController


class ToastServiceRobot(ComposedComponent):
    """Component type toast.ToastServiceRobot (generated)."""

    NAME = "toast.ToastServiceRobot"
    IN_PORTS = ()
    OUT_PORTS = ()
    PORT_TYPES: ClassVar[Mapping[str, object]] = {}
    PARAMETERS = ()
    CONNECTORS = (
        ("dist", "value", (("ctrl", "distance"),)),
        ("color", "value", (("ctrl", "color"),)),
        ("ctrl", "toaster", (("toasterCtrl", "cmd"),)),
        ("toasterCtrl", "leverDown", (("toaster", "leverDown"),)),
        ("ctrl", "arm", (("arm", "cmd"),)),
        ("plate", "angle", (("arm", "angle"),)),
        ("plate", "height", (("arm", "height"),)),
        ("arm", "status", (("ctrl", "armStatus"),)),
    )

    @classmethod
    def subcomponents(cls, params: Mapping[str, object]) -> list[tuple[str, type[ComponentType], dict[str, object]]]:
        del params
        return [
            ("dist", DistanceSensor, {}),
            ("color", ColorSensor, {}),
            ("plate", PlateLocator, {}),
            ("ctrl", Controller, {"threshold": 25}),
            ("toasterCtrl", ToasterController, {}),
            ("toaster", ToasterActuator, {}),
            ("arm", ArmController, {}),
        ]
