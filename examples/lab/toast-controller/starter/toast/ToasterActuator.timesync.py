"""Handwritten ToasterActuator for the python-timesync platform: the simulator's /toaster/command.

Copied into the timesync build by timesync.Components (a `<Name>.timesync.py` next to the model).
"""

from __future__ import annotations

from collections.abc import Mapping

from maa_timesync.lockstep import platform
from toast.toaster_actuator import ToasterActuatorBehaviorBase


class ToasterActuatorBehavior(ToasterActuatorBehaviorBase):
    """Publishes START when the lever goes down and STOP when it is released (on changes only)."""

    def step(self, inputs: Mapping[str, object]) -> None:
        lever = inputs.get("leverDown")
        if isinstance(lever, bool) and lever != getattr(self, "_down", None):
            self._down = lever
            platform().publish("/toaster/command", {"data": "START" if lever else "STOP"})
