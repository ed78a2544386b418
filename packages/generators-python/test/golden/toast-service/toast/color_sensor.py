"""Component toast.ColorSensor for the python-timesync platform (generated)."""

from __future__ import annotations

from collections.abc import Mapping
from typing import ClassVar

from maa_behavior import Behavior, Emit
from maa_timesync import AtomicComponent
from toast.types.types import ToastColor


class ColorSensorBehaviorBase(Behavior):
    """Behavior of toast.ColorSensor: its compute block (generated)."""

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


def _behavior() -> type[ColorSensorBehaviorBase]:
    from toast.color_sensor_impl import ColorSensorBehavior

    return ColorSensorBehavior


class ColorSensor(AtomicComponent):
    """Component type toast.ColorSensor (generated)."""

    NAME = "toast.ColorSensor"
    IN_PORTS = ()
    OUT_PORTS = ("value",)
    PORT_TYPES: ClassVar[Mapping[str, object]] = {"value": ToastColor}
    PARAMETERS = ()
    BEHAVIOR = _behavior()
