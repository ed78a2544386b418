"""Component gear.Scale for the python-timesync platform (generated)."""

from __future__ import annotations

from collections.abc import Mapping
from typing import ClassVar

from maa_behavior import Behavior, Emit
from maa_timesync import AtomicComponent


class ScaleBehavior(Behavior):
    """Behavior of gear.Scale: its compute block (generated)."""

    TIMING = "sync"
    IN_PORTS = ("i",)
    OUT_PORTS = ("o",)
    DELAYED = frozenset()

    def __init__(self, emit: Emit, params: Mapping[str, object] | None = None) -> None:
        super().__init__(emit, params)
        self._last: dict[str, object] = {}
        self.factor: int = self._params.get("factor", None)  # type: ignore[assignment]
        self.i: int | None = None

    def _emit(self, port: str, value: object) -> None:
        if value is not None:
            self._last[port] = value
        super()._emit(port, value)

    def step(self, inputs: Mapping[str, object]) -> None:
        self.i = self._in(inputs, "i", 0)  # type: ignore[assignment]
        self._emit("o", (self.i * self.factor))


class Scale(AtomicComponent):
    """Component type gear.Scale (generated)."""

    NAME = "gear.Scale"
    IN_PORTS = ("i",)
    OUT_PORTS = ("o",)
    PORT_TYPES: ClassVar[Mapping[str, object]] = {"i": "int", "o": "int"}
    PARAMETERS = ("factor",)
    BEHAVIOR = ScaleBehavior
