"""The application Features (feat.Features) on the python-timesync platform (generated)."""

from __future__ import annotations

from collections.abc import Mapping
from enum import Enum

from feat.counter import Counter as _feat_counter
from feat.features import Features as _feat_features
from feat.lamp import Lamp as _feat_lamp
from feat.types.data import Mode
from maa_timesync import ComponentType
from maa_timesync.lockstep import LockstepApp

APPLICATION = "Features"
ROOT = _feat_features
COMPONENTS: dict[str, type[ComponentType]] = {
    "feat.Counter": _feat_counter,
    "feat.Features": _feat_features,
    "feat.Lamp": _feat_lamp,
}
ENUMS: dict[str, type[Enum]] = {
    "Mode": Mode,
}


def create_controller(parameters: Mapping[str, object]) -> LockstepApp:
    """The simulator's lock-step factory (lockstep.json)."""
    return LockstepApp(ROOT, parameters)
