"""Component hall.Wing for the python-timesync platform (generated)."""

from __future__ import annotations

from collections.abc import Mapping
from typing import ClassVar

from hall.lamp__no_dimmable import Lamp__no_dimmable
from maa_timesync import ComponentType, ComposedComponent


class Wing(ComposedComponent):
    """Component type hall.Wing (generated)."""

    NAME = "hall.Wing"
    IN_PORTS = ("level",)
    OUT_PORTS = ("brightness",)
    PORT_TYPES: ClassVar[Mapping[str, object]] = {"level": "int", "brightness": "int"}
    PARAMETERS = ()
    FEATURES: ClassVar[Mapping[str, bool]] = {"dimmed": False}
    CONNECTORS = (
        ("", "level", (("lamp", "level"),)),
        ("lamp", "brightness", (("", "brightness"),)),
    )

    @classmethod
    def subcomponents(cls, params: Mapping[str, object]) -> list[tuple[str, type[ComponentType], dict[str, object]]]:
        del params
        return [
            ("lamp", Lamp__no_dimmable, {}),
        ]
