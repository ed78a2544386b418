"""Component gear.Gearbox for the python-timesync platform (generated)."""

from __future__ import annotations

from collections.abc import Mapping
from typing import ClassVar

from gear.scale import Scale
from gear.total import Total
from maa_timesync import ComponentType
from maa_timesync.modes import ModeComponent, port_value
from maa_timesync.runtime import Connector


class Gearbox(ModeComponent):
    """Component type gear.Gearbox (generated)."""

    NAME = "gear.Gearbox"
    IN_PORTS = ("speed",)
    OUT_PORTS = ("o", "total")
    PORT_TYPES: ClassVar[Mapping[str, object]] = {"speed": "int", "o": "int", "total": "int"}
    PARAMETERS = ()
    CONNECTORS = (
    )
    MODES = ("First", "Second")
    INITIAL_MODE = "First"
    MODE_TIMING = "sync"
    MODE_SUBCOMPONENTS: ClassVar[Mapping[str, tuple[str, ...]]] = {
        "First": ("s1",),
        "Second": ("s10", "t"),
    }
    MODE_CONNECTORS: ClassVar[Mapping[str, tuple[Connector, ...]]] = {
        "First": (("", "speed", (("s1", "i"),)), ("s1", "o", (("", "o"),))),
        "Second": (("", "speed", (("s10", "i"),)), ("s10", "o", (("", "o"), ("t", "i"))), ("t", "o", (("", "total"),))),
    }

    @classmethod
    def mode_transition(cls, mode: str, trigger: str | None, inputs: Mapping[str, object], params: Mapping[str, object]) -> tuple[int, str] | None:
        del trigger, params
        if mode == "First" and (port_value(inputs, "speed", 0) < 0):
            return 0, "Second"
        if mode == "Second" and (port_value(inputs, "speed", 0) == 0):
            return 1, "First"
        return None

    @classmethod
    def subcomponents(cls, params: Mapping[str, object]) -> list[tuple[str, type[ComponentType], dict[str, object]]]:
        del params
        return [
            ("s1", Scale, {"factor": 1}),
            ("s10", Scale, {"factor": 10}),
            ("t", Total, {}),
        ]
