"""Handwritten DistanceSensor for the python-timesync platform: the simulator's /sensors/distance.

Copied into the timesync build by timesync.Components (a `<Name>.timesync.py` next to the model).
"""

from __future__ import annotations

from collections.abc import Mapping

from maa_timesync.lockstep import platform
from toast.distance_sensor import DistanceSensorBehaviorBase


class DistanceSensorBehavior(DistanceSensorBehaviorBase):
    """Emits the latest distance in millimetres once per time slice."""

    def step(self, inputs: Mapping[str, object]) -> None:
        msg = platform().latest("/sensors/distance")
        if msg is not None:
            self._emit("value", int(msg["data"]))
