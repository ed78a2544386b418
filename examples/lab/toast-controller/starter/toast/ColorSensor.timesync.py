"""Handwritten ColorSensor for the python-timesync platform: the simulator's /sensors/color.

Copied into the timesync build by timesync.Components (a `<Name>.timesync.py` next to the model).
"""

from __future__ import annotations

from collections.abc import Mapping

from maa_timesync.lockstep import platform
from toast.color_sensor import ColorSensorBehaviorBase
from toast.types.types import ToastColor


class ColorSensorBehavior(ColorSensorBehaviorBase):
    """Emits the toast colour the slot sensor sees, once per time slice."""

    def step(self, inputs: Mapping[str, object]) -> None:
        msg = platform().latest("/sensors/color")
        if msg is not None and msg.get("data") in ToastColor.__members__:
            self._emit("value", ToastColor[msg["data"]])
