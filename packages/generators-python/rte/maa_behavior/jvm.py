"""Java value semantics the model expressions rely on (division, remainder, strings, float)."""

from __future__ import annotations

import enum
import math
import struct


def f32(value: float) -> float:
    """Rounds to the nearest IEEE 754 single-precision value (Java ``float``)."""
    if math.isnan(value) or math.isinf(value):
        return value
    try:
        result: float = struct.unpack("f", struct.pack("f", value))[0]
    except OverflowError:
        return math.copysign(math.inf, value)
    return result


def jdiv(a: object, b: object) -> object:
    """Java ``/``: integer division truncates toward zero; otherwise IEEE division."""
    if isinstance(a, int) and isinstance(b, int) and not isinstance(a, bool):
        if b == 0:
            raise ZeroDivisionError("/ by zero")
        q = abs(a) // abs(b)
        return q if (a >= 0) == (b >= 0) else -q
    x = float(a)  # type: ignore[arg-type]
    y = float(b)  # type: ignore[arg-type]
    if y == 0.0:
        if x == 0.0 or math.isnan(x):
            return math.nan
        return math.copysign(math.inf, x) * math.copysign(1.0, y)
    return x / y


def jmod(a: object, b: object) -> object:
    """Java ``%``: the remainder has the sign of the dividend."""
    if isinstance(a, int) and isinstance(b, int):
        if b == 0:
            raise ZeroDivisionError("% by zero")
        r = abs(a) % abs(b)
        return r if a >= 0 else -r
    return math.fmod(float(a), float(b))  # type: ignore[arg-type]


def jushr(a: int, b: int) -> int:
    """Java ``>>>`` on 32-bit ints."""
    return (a & 0xFFFFFFFF) >> (b & 31)


def jstr(value: object) -> str:
    """Java's ``String.valueOf``."""
    if value is None:
        return "null"
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, enum.Enum):
        return value.name
    if isinstance(value, float):
        if math.isnan(value):
            return "NaN"
        if math.isinf(value):
            return "Infinity" if value > 0 else "-Infinity"
        return repr(value)
    return str(value)


def jconcat(a: object, b: object) -> str:
    """Java string concatenation with ``+``."""
    return jstr(a) + jstr(b)


_BITS = {"byte": 8, "short": 16, "char": 16, "int": 32, "long": 64}


def jcast(value: object, target: str) -> object:
    """Java's cast to a primitive type ``(target) value`` (JLS 5.1.2-5.1.4).

    Characters are their codes (ints); a cast to ``char`` keeps the low 16 bits unsigned, to
    ``byte``/``short``/``int``/``long`` the low bits in two's complement. A floating-point value
    is first truncated toward zero to ``int`` (``long`` for a cast to ``long``), saturating at the
    range's ends, NaN giving 0.
    """
    if target == "boolean":
        return value
    if isinstance(value, str) and len(value) == 1:
        value = ord(value)
    if target == "double":
        return float(value)  # type: ignore[arg-type]
    if target == "float":
        return f32(float(value))  # type: ignore[arg-type]
    bits = _BITS[target]
    if isinstance(value, float):
        wide = 64 if target == "long" else 32
        low, high = -(1 << (wide - 1)), (1 << (wide - 1)) - 1
        if math.isnan(value):
            n = 0
        elif math.isinf(value):
            n = high if value > 0 else low
        else:
            n = max(low, min(high, int(value)))
    else:
        n = int(value)  # type: ignore[call-overload]
    n &= (1 << bits) - 1
    if target != "char" and n >= 1 << (bits - 1):
        n -= 1 << bits
    return n


def jordinal(value: enum.Enum) -> int:
    """Java's ``Enum.ordinal()``."""
    return list(type(value)).index(value)
