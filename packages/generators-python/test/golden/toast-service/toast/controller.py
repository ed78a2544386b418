"""Component toast.Controller for the python-timesync platform (generated)."""

from __future__ import annotations

from collections.abc import Mapping
from typing import ClassVar

from maa_timesync import AtomicComponent
from toast.controller_behavior import ControllerBehavior
from toast.types.types import ArmProgram, ArmStatus, ToastColor, ToasterCmd


class Controller(AtomicComponent):
    """Component type toast.Controller (generated)."""

    NAME = "toast.Controller"
    IN_PORTS = ("distance", "color", "armStatus")
    OUT_PORTS = ("toaster", "arm")
    PORT_TYPES: ClassVar[Mapping[str, object]] = {"distance": "int", "color": ToastColor, "armStatus": ArmStatus, "toaster": ToasterCmd, "arm": ArmProgram}
    PARAMETERS = ("threshold",)
    BEHAVIOR = ControllerBehavior

    @classmethod
    def defaults(cls, params: Mapping[str, object]) -> dict[str, object]:
        params = dict(params)
        params.setdefault("threshold", 30)
        return params
