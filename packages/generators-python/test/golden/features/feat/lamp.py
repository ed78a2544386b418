"""Component feat.Lamp for the python-timesync platform (generated)."""

from __future__ import annotations

from collections.abc import Mapping
from typing import ClassVar

from feat.lamp_behavior import LampBehavior
from maa_timesync import AtomicComponent


class Lamp(AtomicComponent):
    """Component type feat.Lamp (generated)."""

    NAME = "feat.Lamp"
    IN_PORTS = ("press", "level")
    OUT_PORTS = ("log", "brightness")
    PORT_TYPES: ClassVar[Mapping[str, object]] = {"press": "boolean", "level": "int", "log": "String", "brightness": "int"}
    PARAMETERS = ()
    BEHAVIOR = LampBehavior
