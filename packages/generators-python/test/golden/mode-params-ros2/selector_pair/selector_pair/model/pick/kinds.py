"""Data types of the class diagram pick.Kinds (generated)."""

from __future__ import annotations

from enum import Enum


class Kind(Enum):
    """Enumeration pick.Kinds.Kind (generated)."""

    SLOW = 0
    FAST = 1
