"""Data types of the class diagram toast.types.Types (generated)."""

from __future__ import annotations

from enum import Enum


class ArmProgram(Enum):
    """Enumeration toast.types.Types.ArmProgram (generated)."""

    NONE = 0
    LOAD_BREAD = 1
    PICKUP_AND_DEPLOY = 2


class ArmStatus(Enum):
    """Enumeration toast.types.Types.ArmStatus (generated)."""

    IDLE = 0
    BUSY = 1
    DONE = 2


class ToastColor(Enum):
    """Enumeration toast.types.Types.ToastColor (generated)."""

    WHITE = 0
    GOLDEN = 1
    BURNT = 2


class ToasterCmd(Enum):
    """Enumeration toast.types.Types.ToasterCmd (generated)."""

    START = 0
    STOP = 1
