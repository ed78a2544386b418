"""Component toast.ArmController for the python-timesync platform (generated)."""

from __future__ import annotations

from collections.abc import Mapping
from typing import ClassVar

from maa_timesync import AtomicComponent
from toast.arm_controller_behavior import ArmControllerBehavior
from toast.types.types import ArmProgram, ArmStatus


class ArmController(AtomicComponent):
    """Component type toast.ArmController (generated)."""

    NAME = "toast.ArmController"
    IN_PORTS = ("cmd", "angle", "height")
    OUT_PORTS = ("status",)
    PORT_TYPES: ClassVar[Mapping[str, object]] = {"cmd": ArmProgram, "angle": "int", "height": "int", "status": ArmStatus}
    PARAMETERS = ()
    BEHAVIOR = ArmControllerBehavior
