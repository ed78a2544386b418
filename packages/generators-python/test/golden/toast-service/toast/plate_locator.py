"""Component toast.PlateLocator for the python-timesync platform (generated)."""

from __future__ import annotations

from collections.abc import Mapping
from typing import ClassVar

from maa_behavior import Behavior, Emit
from maa_timesync import AtomicComponent


class PlateLocatorBehaviorBase(Behavior):
    """Behavior of toast.PlateLocator: its compute block (generated)."""

    TIMING = "sync"
    IN_PORTS = ()
    OUT_PORTS = ("angle", "height")
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


def _behavior() -> type[PlateLocatorBehaviorBase]:
    from toast.plate_locator_impl import PlateLocatorBehavior

    return PlateLocatorBehavior


class PlateLocator(AtomicComponent):
    """Component type toast.PlateLocator (generated)."""

    NAME = "toast.PlateLocator"
    IN_PORTS = ()
    OUT_PORTS = ("angle", "height")
    PORT_TYPES: ClassVar[Mapping[str, object]] = {"angle": "int", "height": "int"}
    PARAMETERS = ()
    BEHAVIOR = _behavior()
