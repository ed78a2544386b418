"""Handwritten PlateLocator for the python-timesync platform: where the simulator's plate stands.

Copied into the timesync build by timesync.Components (a `<Name>.timesync.py` next to the model).
"""

from __future__ import annotations

from collections.abc import Mapping

from toast.plate_locator import PlateLocatorBehaviorBase

PLATE_ANGLE_DEG = -120  # docs/simulation.md, "Locations": the plate
PLATE_HEIGHT_CM = 9


class PlateLocatorBehavior(PlateLocatorBehaviorBase):
    """Emits the plate's base angle (deg) and gripper height (cm) once per time slice."""

    def step(self, inputs: Mapping[str, object]) -> None:
        self._emit("angle", PLATE_ANGLE_DEG)
        self._emit("height", PLATE_HEIGHT_CM)
