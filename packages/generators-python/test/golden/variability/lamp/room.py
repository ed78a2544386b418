"""Component lamp.Room for the python-timesync platform (generated)."""

from __future__ import annotations

from collections.abc import Mapping
from typing import ClassVar

from lamp.doubler import Doubler
from lamp.lamp import Lamp
from maa_timesync import ComponentType, ComposedComponent


class Room(ComposedComponent):
    """Component type lamp.Room (generated)."""

    NAME = "lamp.Room"
    IN_PORTS = ("level",)
    OUT_PORTS = ("brightness",)
    PORT_TYPES: ClassVar[Mapping[str, object]] = {"level": "int", "brightness": "int"}
    PARAMETERS = ()
    FEATURES: ClassVar[Mapping[str, bool]] = {"dim": True}
    CONNECTORS = (
        ("", "level", (("doubler", "i"),)),
        ("doubler", "o", (("lamp", "level"),)),
        ("lamp", "brightness", (("", "brightness"),)),
    )

    @classmethod
    def subcomponents(cls, params: Mapping[str, object]) -> list[tuple[str, type[ComponentType], dict[str, object]]]:
        del params
        return [
            ("lamp", Lamp, {}),
            ("doubler", Doubler, {}),
        ]
