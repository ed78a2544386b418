"""Data types of the class diagram robot.types.Types (generated)."""

from __future__ import annotations

from dataclasses import dataclass
from enum import Enum
from typing import Generic, TypeVar


class Mode(Enum):
    """Enumeration robot.types.Types.Mode (generated)."""

    SLOW = 0
    FAST = 1


A = TypeVar("A")
B = TypeVar("B")


@dataclass
class Pair(Generic[A, B]):
    """Class robot.types.Types.Pair (generated)."""

    first: A | None = None
    second: B | None = None


@dataclass
class Reading:
    """Class robot.types.Types.Reading (generated)."""

    value: int = 0
    mode: Mode = Mode.SLOW
    history: list[float] | None = None
