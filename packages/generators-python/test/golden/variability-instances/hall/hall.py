"""Component hall.Hall for the python-timesync platform (generated)."""

from __future__ import annotations

from collections.abc import Mapping
from typing import ClassVar

from hall.lamp import Lamp
from hall.lamp__no_dimmable import Lamp__no_dimmable
from hall.wing import Wing
from hall.wing__dimmed import Wing__dimmed
from maa_timesync import ComponentType, ComposedComponent


class Hall(ComposedComponent):
    """Component type hall.Hall (generated)."""

    NAME = "hall.Hall"
    IN_PORTS = ("level",)
    OUT_PORTS = ("dimmed", "plain", "third", "east", "west")
    PORT_TYPES: ClassVar[Mapping[str, object]] = {"level": "int", "dimmed": "int", "plain": "int", "third": "int", "east": "int", "west": "int"}
    PARAMETERS = ()
    CONNECTORS = (
        ("", "level", (("a", "level"), ("b", "level"), ("c", "level"), ("w1", "level"), ("w2", "level"))),
        ("a", "brightness", (("", "dimmed"),)),
        ("b", "brightness", (("", "plain"),)),
        ("c", "brightness", (("", "third"),)),
        ("w1", "brightness", (("", "east"),)),
        ("w2", "brightness", (("", "west"),)),
    )

    @classmethod
    def subcomponents(cls, params: Mapping[str, object]) -> list[tuple[str, type[ComponentType], dict[str, object]]]:
        del params
        return [
            ("a", Lamp, {}),
            ("b", Lamp__no_dimmable, {}),
            ("c", Lamp, {}),
            ("w1", Wing, {}),
            ("w2", Wing__dimmed, {}),
        ]
