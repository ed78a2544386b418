"""Component hall.Lamp for the python-timesync platform (generated)."""

from __future__ import annotations

from collections.abc import Mapping
from typing import ClassVar

from maa_behavior import Behavior, Emit, jdiv
from maa_timesync import AtomicComponent


class LampBehavior(Behavior):
    """Behavior of hall.Lamp: its compute block (generated)."""

    TIMING = "sync"
    IN_PORTS = ("level",)
    OUT_PORTS = ("brightness",)
    DELAYED = frozenset()

    def __init__(self, emit: Emit, params: Mapping[str, object] | None = None) -> None:
        super().__init__(emit, params)
        self._last: dict[str, object] = {}
        self.level: int | None = None

    def _emit(self, port: str, value: object) -> None:
        if value is not None:
            self._last[port] = value
        super()._emit(port, value)

    def step(self, inputs: Mapping[str, object]) -> None:
        self.level = self._in(inputs, "level", 0)  # type: ignore[assignment]
        self._emit("brightness", jdiv(self.level, 2))


class Lamp(AtomicComponent):
    """Component type hall.Lamp (generated)."""

    NAME = "hall.Lamp"
    IN_PORTS = ("level",)
    OUT_PORTS = ("brightness",)
    PORT_TYPES: ClassVar[Mapping[str, object]] = {"level": "int", "brightness": "int"}
    PARAMETERS = ()
    FEATURES: ClassVar[Mapping[str, bool]] = {"dimmable": True}
    BEHAVIOR = LampBehavior
