"""Component toast.ToasterActuator for the python-timesync platform (generated)."""

from __future__ import annotations

from collections.abc import Mapping
from typing import ClassVar

from maa_behavior import Behavior, Emit
from maa_timesync import AtomicComponent


class ToasterActuatorBehaviorBase(Behavior):
    """Behavior of toast.ToasterActuator: its compute block (generated)."""

    TIMING = "sync"
    IN_PORTS = ("leverDown",)
    OUT_PORTS = ()
    DELAYED = frozenset()

    def __init__(self, emit: Emit, params: Mapping[str, object] | None = None) -> None:
        super().__init__(emit, params)
        self._last: dict[str, object] = {}
        self.leverDown: bool | None = None

    def _emit(self, port: str, value: object) -> None:
        if value is not None:
            self._last[port] = value
        super()._emit(port, value)

    def step(self, inputs: Mapping[str, object]) -> None:
        self.leverDown = self._in(inputs, "leverDown", False)  # type: ignore[assignment]


def _behavior() -> type[ToasterActuatorBehaviorBase]:
    from toast.toaster_actuator_impl import ToasterActuatorBehavior

    return ToasterActuatorBehavior


class ToasterActuator(AtomicComponent):
    """Component type toast.ToasterActuator (generated)."""

    NAME = "toast.ToasterActuator"
    IN_PORTS = ("leverDown",)
    OUT_PORTS = ()
    PORT_TYPES: ClassVar[Mapping[str, object]] = {"leverDown": "boolean"}
    PARAMETERS = ()
    BEHAVIOR = _behavior()
