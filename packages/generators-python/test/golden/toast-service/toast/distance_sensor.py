"""Component toast.DistanceSensor for the python-timesync platform (generated)."""

from __future__ import annotations

from collections.abc import Mapping
from typing import ClassVar

from maa_behavior import Behavior, Emit
from maa_timesync import AtomicComponent


class DistanceSensorBehaviorBase(Behavior):
    """Behavior of toast.DistanceSensor: its compute block (generated)."""

    TIMING = "sync"
    IN_PORTS = ()
    OUT_PORTS = ("value",)
    DELAYED = frozenset()

    def __init__(self, emit: Emit, params: Mapping[str, object] | None = None) -> None:
        super().__init__(emit, params)
        self._last: dict[str, object] = {}

    def _emit(self, port: str, value: object) -> None:
        if value is not None:
            self._last[port] = value
        super()._emit(port, value)

    def step(self, inputs: Mapping[str, object]) -> None:
        del inputs


def _behavior() -> type[DistanceSensorBehaviorBase]:
    from toast.distance_sensor_impl import DistanceSensorBehavior

    return DistanceSensorBehavior


class DistanceSensor(AtomicComponent):
    """Component type toast.DistanceSensor (generated)."""

    NAME = "toast.DistanceSensor"
    IN_PORTS = ()
    OUT_PORTS = ("value",)
    PORT_TYPES: ClassVar[Mapping[str, object]] = {"value": "int"}
    PARAMETERS = ()
    BEHAVIOR = _behavior()
