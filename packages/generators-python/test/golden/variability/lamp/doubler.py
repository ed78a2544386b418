"""Component lamp.Doubler for the python-timesync platform (generated)."""

from __future__ import annotations

from collections.abc import Mapping
from typing import ClassVar

from maa_behavior import Behavior, Emit
from maa_timesync import AtomicComponent


class DoublerBehavior(Behavior):
    """Behavior of lamp.Doubler: its compute block (generated)."""

    TIMING = "sync"
    IN_PORTS = ("i",)
    OUT_PORTS = ("o",)
    DELAYED = frozenset()

    def __init__(self, emit: Emit, params: Mapping[str, object] | None = None) -> None:
        super().__init__(emit, params)
        self._last: dict[str, object] = {}
        self.i: int | None = None

    def _emit(self, port: str, value: object) -> None:
        if value is not None:
            self._last[port] = value
        super()._emit(port, value)

    def step(self, inputs: Mapping[str, object]) -> None:
        self.i = self._in(inputs, "i", 0)  # type: ignore[assignment]
        self._emit("o", (self.i * 2))


class Doubler(AtomicComponent):
    """Component type lamp.Doubler (generated)."""

    NAME = "lamp.Doubler"
    IN_PORTS = ("i",)
    OUT_PORTS = ("o",)
    PORT_TYPES: ClassVar[Mapping[str, object]] = {"i": "int", "o": "int"}
    PARAMETERS = ()
    BEHAVIOR = DoublerBehavior
