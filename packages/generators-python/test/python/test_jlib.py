"""maa_behavior.jlib beyond the values test/java-library.test.ts compares with Java: the exceptions
Java throws, NaN and signed zeros, wrap-around, Java's HashSet order and receivers of class-diagram types."""

from __future__ import annotations

import math
from dataclasses import dataclass

import pytest

from maa_behavior.jlib import JavaException, JDate, JOptional, jcall, jfield, jformat, jhash, jstatic


def test_exceptions_java_throws() -> None:
    with pytest.raises(JavaException, match="IndexOutOfBounds"):
        jcall([1, 2], "get", (2,))
    with pytest.raises(JavaException, match="StringIndexOutOfBounds"):
        jcall("abc", "substring", (2, 1))
    with pytest.raises(JavaException, match="NoSuchElementException"):
        jcall(JOptional(), "get")
    with pytest.raises(JavaException, match="NumberFormatException"):
        jstatic("java.lang.Integer", "parseInt", ("2147483648",))
    with pytest.raises(JavaException, match="NumberFormatException"):
        jstatic("java.lang.Integer", "parseInt", (" 1",))
    with pytest.raises(JavaException, match="NullPointerException"):
        jcall(None, "length")
    with pytest.raises(JavaException, match="NullPointerException"):
        jstatic("java.util.Optional", "of", (None,))


def test_floating_point_edges() -> None:
    assert jformat(math.nan) == "NaN"
    assert jformat(-math.inf) == "-Infinity"
    assert jformat(-0.0) == "-0.0"
    assert jstatic("java.lang.Double", "compare", (math.nan, math.inf)) == 1
    assert jstatic("java.lang.Double", "compare", (-0.0, 0.0)) == -1
    assert math.isnan(jstatic("java.lang.Math", "sqrt", (-1.0,)))  # type: ignore[arg-type]
    assert jstatic("java.lang.Math", "pow", (10.0, 400.0)) == math.inf
    assert jstatic("java.lang.Math", "round", (0.49999999999999994,)) == 0
    assert jstatic("java.lang.Math", "round", (math.nan,)) == 0
    assert jcall(math.nan, "intValue") == 0
    assert jcall(1e30, "longValue") == 2**63 - 1
    assert jcall(math.nan, "equals", (math.nan,)) is True  # Double.equals, unlike ==


def test_wrap_around_and_hints() -> None:
    assert jcall(2**31, "intValue") == -(2**31)
    assert jstatic("java.lang.Long", "sum", (jfield("java.lang.Long", "MAX_VALUE"), 1)) == -(2**63)
    assert jhash(-1, "long") == 0
    assert jhash(-1, "int") == -1
    assert jformat(97, "char") == "a"
    assert jcall(ord("b"), "compareTo", (ord("a"),), "Character") == 1


def test_java_hash_order_of_sets_and_maps() -> None:
    assert jformat({"c", "a", "b"}) == "[a, b, c]"
    assert jformat({20, 3, 17}) == "[17, 3, 20]"  # buckets of a 16-slot table: 1, 3, 4
    assert jformat({"b": 1, "a": 2}) == "{a=2, b=1}"
    assert jcall({"b": 1, "a": 2}, "values") == [2, 1]


@dataclass
class Box:
    size: int

    def get(self) -> int:
        return self.size


def test_receivers_of_class_diagram_types() -> None:
    box = Box(3)
    assert jcall(box, "get") == 3  # its own method, although `get` is a library method name
    assert jcall(box, "equals", (Box(3),)) is True
    assert jcall(box, "toString") == str(box)


def test_dates() -> None:
    d = JDate(1000)
    jcall(d, "setTime", (5000,))
    assert jcall(d, "getTime") == 5000
    assert jcall(d, "after", (JDate(0),)) is True
    assert jformat(JDate(0)) == "Thu Jan 01 00:00:00 UTC 1970"
