"""Data types of the class diagram feat.types.Data (generated)."""

from __future__ import annotations

from dataclasses import dataclass
from enum import Enum
from typing import Generic, TypeVar


class Mode(Enum):
    """Enumeration feat.types.Data.Mode (generated)."""

    OFF = 0
    SLOW = 1
    FAST = 2


T = TypeVar("T")


@dataclass
class Pair(Generic[T]):
    """Class feat.types.Data.Pair (generated)."""

    first: T | None = None
    second: T | None = None
    rest: list[T] | None = None


@dataclass
class Reading:
    """Class feat.types.Data.Reading (generated)."""

    value: int = 0
    quality: float = 0.0
    label: str = ""
    mode: Mode = Mode.OFF
