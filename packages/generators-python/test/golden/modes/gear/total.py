"""Component gear.Total for the python-timesync platform (generated)."""

from __future__ import annotations

from collections.abc import Mapping
from typing import ClassVar

from maa_behavior import Behavior, Emit
from maa_timesync import AtomicComponent


class TotalBehavior(Behavior):
    """Behavior of gear.Total: its compute block (generated)."""

    TIMING = "sync"
    IN_PORTS = ("i",)
    OUT_PORTS = ("o",)
    DELAYED = frozenset()

    def __init__(self, emit: Emit, params: Mapping[str, object] | None = None) -> None:
        super().__init__(emit, params)
        self._last: dict[str, object] = {}
        self.sum: int = 0
        self.i: int | None = None

    def _emit(self, port: str, value: object) -> None:
        if value is not None:
            self._last[port] = value
        super()._emit(port, value)

    def step(self, inputs: Mapping[str, object]) -> None:
        self.i = self._in(inputs, "i", 0)  # type: ignore[assignment]
        self.sum = (self.sum + self.i)
        self._emit("o", self.sum)


class Total(AtomicComponent):
    """Component type gear.Total (generated)."""

    NAME = "gear.Total"
    IN_PORTS = ("i",)
    OUT_PORTS = ("o",)
    PORT_TYPES: ClassVar[Mapping[str, object]] = {"i": "int", "o": "int"}
    PARAMETERS = ()
    BEHAVIOR = TotalBehavior
