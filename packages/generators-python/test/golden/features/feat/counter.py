"""Component feat.Counter for the python-timesync platform (generated)."""

from __future__ import annotations

from collections.abc import Mapping
from typing import ClassVar

from feat.types.data import Mode, Reading
from maa_behavior import Behavior, Emit, jconcat, jdiv
from maa_timesync import AtomicComponent


class CounterBehavior(Behavior):
    """Behavior of feat.Counter: its compute block (generated)."""

    TIMING = "sync"
    IN_PORTS = ("inc", "mode")
    OUT_PORTS = ("total", "text", "reading", "pair")
    DELAYED = frozenset({"total"})

    def __init__(self, emit: Emit, params: Mapping[str, object] | None = None) -> None:
        super().__init__(emit, params)
        self._last: dict[str, object] = {}
        self.step_: int = self._params.get("step", 2)  # type: ignore[assignment]
        self.sum: int = 0
        self.inc: int | None = None
        self.mode: Mode | None = None

    def _emit(self, port: str, value: object) -> None:
        if value is not None:
            self._last[port] = value
        super()._emit(port, value)

    def init(self) -> None:
        self._emit("total", 0)
        self._emit("text", "start")

    def step(self, inputs: Mapping[str, object]) -> None:
        self.inc = self._in(inputs, "inc", 0)  # type: ignore[assignment]
        self.mode = inputs.get("mode")  # type: ignore[assignment]
        if (self.mode == Mode.FAST):
            self.sum = (self.sum + (self.inc * self.step_))
        else:
            if (self.mode != Mode.OFF):
                self.sum = (self.sum + self.inc)
        k = 0
        while (k < 2):
            self.sum = (self.sum + 0)
            k = (k + 1)
        self._emit("total", jdiv(self.sum, 3))
        self._emit("text", jconcat("sum=", self.sum))


class Counter(AtomicComponent):
    """Component type feat.Counter (generated)."""

    NAME = "feat.Counter"
    IN_PORTS = ("inc", "mode")
    OUT_PORTS = ("total", "text", "reading", "pair")
    PORT_TYPES: ClassVar[Mapping[str, object]] = {"inc": "int", "mode": Mode, "total": "int", "text": "String", "reading": Reading, "pair": "Pair<Integer>"}
    PARAMETERS = ("step",)
    BEHAVIOR = CounterBehavior

    @classmethod
    def defaults(cls, params: Mapping[str, object]) -> dict[str, object]:
        params = dict(params)
        params.setdefault("step", 2)
        return params
