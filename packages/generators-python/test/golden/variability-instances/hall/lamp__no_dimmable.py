"""Component hall.Lamp__no_dimmable for the python-timesync platform (generated)."""

from __future__ import annotations

from collections.abc import Mapping
from typing import ClassVar

from maa_behavior import Behavior, Emit
from maa_timesync import AtomicComponent


class Lamp__no_dimmableBehavior(Behavior):
    """Behavior of hall.Lamp__no_dimmable: its compute block (generated)."""

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
        self._emit("brightness", (100 if (self.level > 0) else 0))


class Lamp__no_dimmable(AtomicComponent):
    """Component type hall.Lamp__no_dimmable (generated)."""

    NAME = "hall.Lamp__no_dimmable"
    IN_PORTS = ("level",)
    OUT_PORTS = ("brightness",)
    PORT_TYPES: ClassVar[Mapping[str, object]] = {"level": "int", "brightness": "int"}
    PARAMETERS = ()
    FEATURES: ClassVar[Mapping[str, bool]] = {"dimmable": False}
    BEHAVIOR = Lamp__no_dimmableBehavior
