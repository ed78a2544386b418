"""Java's primitive casts (maa_behavior.jcast): the values javac's programs compute."""

from __future__ import annotations

import math

import pytest

from maa_behavior import jcast


@pytest.mark.parametrize(
    ("value", "target", "expected"),
    [
        (98, "char", 98),
        (-1, "char", 0xFFFF),
        (65536 + 65, "char", 65),
        ("a", "int", 97),
        (97.9, "char", 97),
        (300, "byte", 44),
        (200, "byte", -56),
        (40000, "short", -25536),
        (2**31, "int", -(2**31)),
        (2**63, "long", -(2**63)),
        (-2.7, "int", -2),
        (2.7, "int", 2),
        (1e20, "int", 2**31 - 1),
        (-1e20, "int", -(2**31)),
        (1e20, "long", 2**63 - 1),
        (math.nan, "int", 0),
        (math.inf, "long", 2**63 - 1),
        (1e10, "short", -1),
        (97, "double", 97.0),
        (True, "boolean", True),
    ],
)
def test_jcast(value: object, target: str, expected: object) -> None:
    result = jcast(value, target)
    assert result == expected
    assert type(result) is type(expected)


def test_jcast_float_rounds_to_single_precision() -> None:
    assert jcast(0.1, "float") == 0.10000000149011612
