"""Component hall.Wing__dimmed for the python-timesync platform (generated)."""

from __future__ import annotations

from collections.abc import Mapping
from typing import ClassVar

from hall.lamp import Lamp
from maa_timesync import ComponentType, ComposedComponent


class Wing__dimmed(ComposedComponent):
    """Component type hall.Wing__dimmed (generated)."""

    NAME = "hall.Wing__dimmed"
    IN_PORTS = ("level",)
    OUT_PORTS = ("brightness",)
    PORT_TYPES: ClassVar[Mapping[str, object]] = {"level": "int", "brightness": "int"}
    PARAMETERS = ()
    FEATURES: ClassVar[Mapping[str, bool]] = {"dimmed": True}
    CONNECTORS = (
        ("", "level", (("lamp", "level"),)),
        ("lamp", "brightness", (("", "brightness"),)),
    )

    @classmethod
    def subcomponents(cls, params: Mapping[str, object]) -> list[tuple[str, type[ComponentType], dict[str, object]]]:
        del params
        return [
            ("lamp", Lamp, {}),
        ]
