"""The JDK library of the models (``java.lang`` boxes and ``String``, ``Math``, ``java.util``) in Python.

Generated code calls library methods through :func:`jcall` (instance methods), :func:`jstatic`
(static methods and constructors, written ``Type.Type(...)`` in models) and :func:`jfield`
(static attributes such as ``Integer.MAX_VALUE``). Values keep their Python representation:
``boolean`` is ``bool``, the integral types and ``char`` are ``int`` (a ``char`` is its code; a
one-character ``str`` is accepted too), ``float``/``double`` are ``float``, ``String`` is ``str``,
lists and queues are ``list``, sets ``set``, maps ``dict``; ``Optional``, ``Date`` and
``Iterator`` have the classes below. Where Python cannot tell Java types apart (``int`` and
``long``, ``float`` and ``double``), the generator passes the receiver's declared type as
``hint`` when it knows it (``hashCode``, ``toString``).

The library the checker knows is ``packages/language-adl/src/types/builtin-library.ts``; a test
(``test/java-library.test.ts``) calls every method of it here and compares with Java.
"""

from __future__ import annotations

import math
import struct
import time
from collections.abc import Callable
from dataclasses import dataclass
from decimal import Decimal

from maa_behavior.jvm import f32

_INT_MIN, _INT_MAX = -(2**31), 2**31 - 1
_LONG_MIN, _LONG_MAX = -(2**63), 2**63 - 1


class JavaException(Exception):
    """A Java exception the library would throw (the message names the Java exception class)."""


@dataclass(eq=True, frozen=True)
class JOptional:
    """``java.util.Optional``: ``value`` is ``None`` for an empty optional."""

    value: object = None


@dataclass(eq=True)
class JDate:
    """``java.util.Date``: milliseconds since 1970-01-01T00:00:00Z."""

    time: int


class JIterator:
    """``java.util.Iterator`` over a snapshot of a collection."""

    def __init__(self, items: list[object]) -> None:
        self._items = items
        self._next = 0

    def has_next(self) -> bool:
        return self._next < len(self._items)

    def next(self) -> object:
        if not self.has_next():
            raise JavaException("java.util.NoSuchElementException")
        self._next += 1
        return self._items[self._next - 1]


def _wrap(v: int, bits: int) -> int:
    """Two's-complement wrap-around of an integral value to ``bits`` bits."""
    m = 1 << bits
    v &= m - 1
    return v - m if v >= m >> 1 else v


def _code(c: object) -> int:
    """The code of a ``char`` (an ``int`` or a one-character ``str``)."""
    if isinstance(c, str):
        return ord(c)
    if isinstance(c, int):
        return c
    raise TypeError(f"not a char: {c!r}")


def _char(code: int) -> int:
    """A ``char`` value as the generated code represents it (its code)."""
    return code & 0xFFFF


def _digits(d: float, float32: bool) -> tuple[str, int]:
    """Decimal digits and exponent (``d.ddd * 10**exp``) of Java's ``toString``: the fewest that read back
    as ``d``, but at least two significant ones (Java prints ``4.9E-324``, not ``5.0E-324``)."""
    text = repr(d)
    for p in range(1, 17):
        candidate = f"{d:.{p}e}"
        back = float(candidate)
        if (f32(back) if float32 else back) == d:
            text = candidate
            break
    _, digits, exp = Decimal(text).normalize().as_tuple()
    ds = "".join(str(x) for x in digits) or "0"
    return ds, int(exp) + len(ds) - 1


def _float_text(d: float, float32: bool = False) -> str:
    """Java's ``Double.toString`` (``Float.toString`` for ``float32``)."""
    if math.isnan(d):
        return "NaN"
    if math.isinf(d):
        return "Infinity" if d > 0 else "-Infinity"
    if d == 0.0:
        return "-0.0" if math.copysign(1.0, d) < 0 else "0.0"
    sign = "-" if d < 0 else ""
    ds, exp = _digits(abs(d), float32)
    if 1e-3 <= abs(d) < 1e7:
        if exp >= 0:
            whole = ds[: exp + 1].ljust(exp + 1, "0")
            frac = ds[exp + 1 :] or "0"
        else:
            whole = "0"
            frac = "0" * (-exp - 1) + ds
        return f"{sign}{whole}.{frac}"
    return f"{sign}{ds[0]}.{ds[1:] or '0'}E{exp}"


_FLOAT_HINTS = {"float", "Float"}
_CHAR_HINTS = {"char", "Character"}


def _java_order(items: list[object]) -> list[object]:
    """The iteration order of a ``java.util.HashSet``/``HashMap`` holding ``items`` (added in this order)."""
    capacity = 16
    while len(items) > capacity * 3 // 4:
        capacity *= 2

    def bucket(x: object) -> int:
        h = jhash(x) & 0xFFFFFFFF
        return (h ^ (h >> 16)) & (capacity - 1)

    return sorted(items, key=bucket)


def jformat(value: object, hint: str | None = None) -> str:
    """Java's ``String.valueOf`` of a value whose static type is ``hint`` (when known)."""
    if value is None:
        return "null"
    if isinstance(value, bool):
        return "true" if value else "false"
    base = (hint or "").split("<")[0]
    if base in _CHAR_HINTS:
        return chr(_code(value))
    if isinstance(value, str):
        return value
    if isinstance(value, float):
        return _float_text(value, base in _FLOAT_HINTS)
    if isinstance(value, int):
        return str(value)
    if isinstance(value, list):
        return "[" + ", ".join(jformat(x) for x in value) + "]"
    if isinstance(value, set):
        return "[" + ", ".join(jformat(x) for x in _java_order(sorted(value, key=_stable))) + "]"
    if isinstance(value, dict):
        return "{" + ", ".join(f"{jformat(k)}={jformat(value[k])}" for k in _java_order(list(value))) + "}"
    if isinstance(value, JOptional):
        return "Optional.empty" if value.value is None else f"Optional[{jformat(value.value)}]"
    if isinstance(value, JDate):
        stamp = time.gmtime(value.time // 1000)
        return time.strftime("%a %b %d %H:%M:%S UTC %Y", stamp)
    name = getattr(value, "name", None)
    if isinstance(name, str) and type(value).__module__ != "builtins" and hasattr(type(value), "__members__"):
        return name
    return str(value)


def _stable(x: object) -> tuple[str, str]:
    """A deterministic order of set elements (Python's set order depends on the hash seed)."""
    return (type(x).__name__, repr(x))


def _string_hash(s: str) -> int:
    h = 0
    for unit in s.encode("utf-16-be").hex(" ", 2).split():
        h = _wrap(31 * h + int(unit, 16), 32)
    return h


def _long_hash(v: int) -> int:
    v = _wrap(v, 64)
    return _wrap(v ^ ((v & 0xFFFFFFFFFFFFFFFF) >> 32), 32)


def _double_hash(d: float) -> int:
    bits = struct.unpack(">q", struct.pack(">d", math.nan if math.isnan(d) else d))[0]
    return _long_hash(bits)


def _float_hash(d: float) -> int:
    return int(struct.unpack(">i", struct.pack(">f", math.nan if math.isnan(d) else d))[0])


def jhash(value: object, hint: str | None = None) -> int:
    """Java's ``hashCode`` of a value whose static type is ``hint`` (when known)."""
    base = (hint or "").split("<")[0]
    if value is None:
        return 0
    if isinstance(value, bool):
        return 1231 if value else 1237
    if base in _CHAR_HINTS:
        return _code(value)
    if isinstance(value, int):
        if base in ("long", "Long") or not (_INT_MIN <= value <= _INT_MAX):
            return _long_hash(value)
        return value
    if isinstance(value, float):
        return _float_hash(value) if base in _FLOAT_HINTS else _double_hash(value)
    if isinstance(value, str):
        return _string_hash(value)
    if isinstance(value, list):
        h = 1
        for x in value:
            h = _wrap(31 * h + jhash(x), 32)
        return h
    if isinstance(value, set):
        return _wrap(sum(jhash(x) for x in value), 32)
    if isinstance(value, dict):
        return _wrap(sum(jhash(k) ^ jhash(v) for k, v in value.items()), 32)
    if isinstance(value, JOptional):
        return jhash(value.value)
    if isinstance(value, JDate):
        return _long_hash(value.time)
    return _wrap(hash(value), 32)


def _compare(a: object, b: object) -> int:
    if a is None or b is None:
        raise JavaException("java.lang.NullPointerException")
    if isinstance(a, str) and isinstance(b, str):
        ua, ub = a.encode("utf-16-be"), b.encode("utf-16-be")
        for i in range(0, min(len(ua), len(ub)), 2):
            x, y = int.from_bytes(ua[i : i + 2], "big"), int.from_bytes(ub[i : i + 2], "big")
            if x != y:
                return x - y
        return (len(ua) - len(ub)) // 2
    if isinstance(a, bool) and isinstance(b, bool):
        return (a > b) - (a < b)
    if isinstance(a, JDate) and isinstance(b, JDate):
        return (a.time > b.time) - (a.time < b.time)
    if isinstance(a, float) or isinstance(b, float):
        return _compare_double(float(a), float(b))  # type: ignore[arg-type]
    if isinstance(a, int) and isinstance(b, int):
        return (a > b) - (a < b)
    raise JavaException(f"java.lang.ClassCastException: {type(a).__name__} is not comparable")


def _compare_double(a: float, b: float) -> int:
    """``Double.compare``: NaN above everything, -0.0 below 0.0."""
    if math.isnan(a) or math.isnan(b):
        return 0 if math.isnan(a) and math.isnan(b) else (1 if math.isnan(a) else -1)
    if a == b:
        return (math.copysign(1, a) > math.copysign(1, b)) - (math.copysign(1, a) < math.copysign(1, b))
    return 1 if a > b else -1


def _equals(a: object, b: object) -> bool:
    if isinstance(a, bool) != isinstance(b, bool):
        return False
    if isinstance(a, float) and isinstance(b, float):
        return _compare_double(a, b) == 0
    if isinstance(a, float) != isinstance(b, float):
        return False
    return a == b


def _index(xs: list[object], i: int) -> int:
    if not 0 <= i < len(xs):
        raise JavaException(f"java.lang.IndexOutOfBoundsException: Index {i} out of bounds for length {len(xs)}")
    return i


def _substring(s: str, begin: int, end: int | None = None) -> str:
    stop = len(s) if end is None else end
    if begin < 0 or stop > len(s) or begin > stop:
        raise JavaException(f"java.lang.StringIndexOutOfBoundsException: begin {begin}, end {stop}, length {len(s)}")
    return s[begin:stop]


def _parse_int(s: str, bits: int) -> int:
    text = s.strip() if s == s.strip() else "x"
    try:
        v = int(text, 10) if text and text.lstrip("+-").isdigit() else None
    except ValueError:
        v = None
    if v is None or _wrap(v, bits) != v:
        raise JavaException(f'java.lang.NumberFormatException: For input string: "{s}"')
    return v


def _parse_float(s: str) -> float:
    text = s.strip().rstrip("dDfF")
    try:
        return float(text)
    except ValueError:
        raise JavaException(f'java.lang.NumberFormatException: For input string: "{s}"') from None


def _list_remove(xs: list[object], o: object) -> bool:
    for i, x in enumerate(xs):
        if _equals(x, o):
            del xs[i]
            return True
    return False


def _index_of(xs: list[object], o: object, last: bool = False) -> int:
    found = [i for i, x in enumerate(xs) if _equals(x, o)]
    if not found:
        return -1
    return found[-1] if last else found[0]


def _collection_add(c: list[object] | set[object], e: object) -> bool:
    if isinstance(c, set):
        if e in c:
            return False
        c.add(e)
        return True
    c.append(e)
    return True


def _remove_key(m: dict[object, object], k: object) -> object:
    return m.pop(k, None)


def _put(m: dict[object, object], k: object, v: object) -> object:
    old = m.get(k)
    m[k] = v
    return old


def _set_at(xs: list[object], i: int, e: object) -> object:
    old = xs[_index(xs, i)]
    xs[i] = e
    return old


def _opt_get(o: JOptional) -> object:
    if o.value is None:
        raise JavaException("java.util.NoSuchElementException: No value present")
    return o.value


def _set_time(d: JDate, t: int) -> None:
    d.time = t


def _is_java_space(c: int) -> bool:
    if chr(c) in " \t\n\x0b\f\r\x1c\x1d\x1e\x1f":
        return True
    return chr(c).isspace() and c not in (0xA0, 0x2007, 0x202F) and c > 0x7F


Method = Callable[..., object]

#: Instance methods by Python representation and name/arity.
_OBJECT: dict[str, Method] = {
    "equals/1": _equals,
    "hashCode/0": lambda v, hint=None: jhash(v, hint),
    "toString/0": lambda v, hint=None: jformat(v, hint),
    "compareTo/1": _compare,
}

_NUMBER: dict[str, Method] = {
    "byteValue/0": lambda v: _wrap(int(v), 8),
    "shortValue/0": lambda v: _wrap(int(v), 16),
    "intValue/0": lambda v: _java_int(v, 32),
    "longValue/0": lambda v: _java_int(v, 64),
    "floatValue/0": lambda v: f32(float(v)),
    "doubleValue/0": float,
    "booleanValue/0": bool,
    "charValue/0": lambda v: _char(_code(v)),
    "isNaN/0": lambda v: math.isnan(v),
    "isInfinite/0": lambda v: math.isinf(v),
}

_STRING: dict[str, Method] = {
    "length/0": len,
    "isEmpty/0": lambda s: len(s) == 0,
    "charAt/1": lambda s, i: (
        _char(ord(s[i]))
        if 0 <= i < len(s)
        else _raise(f"java.lang.StringIndexOutOfBoundsException: index {i}, length {len(s)}")
    ),
    "substring/1": _substring,
    "substring/2": _substring,
    "startsWith/1": lambda s, p: s.startswith(p),
    "endsWith/1": lambda s, p: s.endswith(p),
    "contains/1": lambda s, x: x in s,
    "indexOf/1": lambda s, x: s.find(x),
    "lastIndexOf/1": lambda s, x: s.rfind(x),
    "equalsIgnoreCase/1": lambda s, o: (
        isinstance(o, str) and len(s) == len(o) and (s.upper() == o.upper() or s.lower() == o.lower())
    ),
    "replace/2": lambda s, a, b: s.replace(a, b),
    "repeat/1": lambda s, n: s * n if n >= 0 else _raise(f"java.lang.IllegalArgumentException: count is negative: {n}"),
    "toUpperCase/0": str.upper,
    "toLowerCase/0": str.lower,
    "trim/0": lambda s: s.strip("".join(chr(c) for c in range(33))),
    "strip/0": lambda s: "".join(_strip_java(s)),
    "isBlank/0": lambda s: all(_is_java_space(ord(c)) for c in s),
    "concat/1": lambda s, o: s + o,
}

_COLLECTION: dict[str, Method] = {
    "size/0": len,
    "isEmpty/0": lambda c: len(c) == 0,
    "contains/1": lambda c, o: any(_equals(x, o) for x in c),
    "add/1": _collection_add,
    "remove/1": lambda c, o: _list_remove(c, o) if isinstance(c, list) else (c.discard(o) is None and False) or False,
    "clear/0": lambda c: c.clear(),
    "iterator/0": lambda c: JIterator(list(c) if isinstance(c, list) else _java_order(sorted(c, key=_stable))),
}

_LIST: dict[str, Method] = {
    "get/1": lambda xs, i: xs[_index(xs, i)],
    "set/2": _set_at,
    "indexOf/1": _index_of,
    "lastIndexOf/1": lambda xs, o: _index_of(xs, o, True),
    "peek/0": lambda xs: xs[0] if xs else None,
    "poll/0": lambda xs: xs.pop(0) if xs else None,
    "offer/1": lambda xs, e: xs.append(e) is None,
}

_SET: dict[str, Method] = {
    "remove/1": lambda c, o: (o in c, c.discard(o))[0],
}

_MAP: dict[str, Method] = {
    "get/1": lambda m, k: m.get(k),
    "put/2": _put,
    "containsKey/1": lambda m, k: k in m,
    "containsValue/1": lambda m, v: any(_equals(x, v) for x in m.values()),
    "remove/1": _remove_key,
    "getOrDefault/2": lambda m, k, d: m[k] if k in m else d,
    "size/0": len,
    "isEmpty/0": lambda m: len(m) == 0,
    "clear/0": lambda m: m.clear(),
    "keySet/0": lambda m: set(m.keys()),
    "values/0": lambda m: [m[k] for k in _java_order(list(m))],
}

_OPTIONAL: dict[str, Method] = {
    "isPresent/0": lambda o: o.value is not None,
    "isEmpty/0": lambda o: o.value is None,
    "get/0": _opt_get,
    "orElse/1": lambda o, d: d if o.value is None else o.value,
}

_DATE: dict[str, Method] = {
    "getTime/0": lambda d: d.time,
    "setTime/1": _set_time,
    "before/1": lambda d, w: d.time < w.time,
    "after/1": lambda d, w: d.time > w.time,
}

_ITERATOR: dict[str, Method] = {
    "hasNext/0": JIterator.has_next,
    "next/0": JIterator.next,
}


def _strip_java(s: str) -> str:
    start, end = 0, len(s)
    while start < end and _is_java_space(ord(s[start])):
        start += 1
    while end > start and _is_java_space(ord(s[end - 1])):
        end -= 1
    return s[start:end]


def _raise(message: str) -> object:
    raise JavaException(message)


def _java_int(v: object, bits: int) -> int:
    """Java's narrowing of a number to ``int``/``long`` (floating values saturate, NaN is 0)."""
    if isinstance(v, float):
        if math.isnan(v):
            return 0
        lo, hi = (_INT_MIN, _INT_MAX) if bits == 32 else (_LONG_MIN, _LONG_MAX)
        if math.isinf(v):
            return hi if v > 0 else lo
        return max(lo, min(hi, int(v)))
    return _wrap(int(v), bits)  # type: ignore[call-overload]


def _tables(recv: object) -> tuple[dict[str, Method], ...]:
    if isinstance(recv, str):
        return (_STRING, _OBJECT)
    if isinstance(recv, (bool, int, float)):
        return (_NUMBER, _OBJECT)
    if isinstance(recv, list):
        return (_LIST, _COLLECTION, _OBJECT)
    if isinstance(recv, set):
        return (_SET, _COLLECTION, _OBJECT)
    if isinstance(recv, dict):
        return (_MAP, _OBJECT)
    if isinstance(recv, JOptional):
        return (_OPTIONAL, _OBJECT)
    if isinstance(recv, JDate):
        return (_DATE, _OBJECT)
    if isinstance(recv, JIterator):
        return (_ITERATOR, _OBJECT)
    return ()


_HINTED = {"hashCode/0", "toString/0"}


def jcall(recv: object, name: str, args: tuple[object, ...] = (), hint: str | None = None) -> object:
    """Calls the Java library method ``name`` on ``recv`` (whose static type is ``hint`` when known).

    A receiver that is no library value (an object of a class-diagram type) gets the Python
    method of the same name; ``equals``, ``hashCode`` and ``toString`` fall back to Java's
    defaults for it.
    """
    if recv is None:
        raise JavaException(f"java.lang.NullPointerException: cannot invoke {name}() on null")
    key = f"{name}/{len(args)}"
    tables = _tables(recv)
    if tables and hint in _CHAR_HINTS and key == "compareTo/1":
        return _code(recv) - _code(args[0])
    for table in tables:
        method = table.get(key)
        if method is not None:
            return method(recv, *args, hint) if key in _HINTED else method(recv, *args)
    own = getattr(recv, name, None)
    if callable(own):
        return own(*args)
    if key in _OBJECT:
        return _OBJECT[key](recv, *args, hint) if key in _HINTED else _OBJECT[key](recv, *args)
    raise JavaException(f"no method {name} with {len(args)} argument(s) on {type(recv).__name__}")


def _box_statics(prim: str, bits: int | None) -> dict[str, Method]:
    def valueof(v: object) -> object:
        return v

    statics: dict[str, Method] = {"valueOf/1": valueof, "toString/1": lambda v: jformat(v, prim)}
    if prim in ("float", "double"):
        statics["compare/2"] = lambda a, b: _compare_double(float(a), float(b))
    elif prim == "char":
        statics["compare/2"] = lambda a, b: _code(a) - _code(b)
    elif prim in ("byte", "short"):
        statics["compare/2"] = lambda a, b: a - b
    else:
        statics["compare/2"] = _compare
    return statics


def _ctype(test: Callable[[str], bool]) -> Method:
    return lambda c: test(chr(_code(c)))


def _fn(f: Callable[[float], float]) -> Method:
    """A trigonometric function: NaN for infinite arguments (Python raises)."""
    return lambda a: f(a) if math.isfinite(a) else math.nan


def _overflow(f: Callable[[float], float], a: float) -> float:
    try:
        return f(a)
    except OverflowError:
        return math.inf


def _pow(a: float, b: float) -> float:
    """``Math.pow`` (IEEE results where Python raises)."""
    try:
        return math.pow(a, b)
    except OverflowError:
        return math.inf if a > 0 or (float(b).is_integer() and int(b) % 2 == 0) else -math.inf
    except ValueError:
        if a == 0:
            return math.inf
        return math.nan


def _min(a: object, b: object) -> object:
    if isinstance(a, float) or isinstance(b, float):
        x, y = float(a), float(b)  # type: ignore[arg-type]
        if math.isnan(x) or math.isnan(y):
            return math.nan
        return x if _compare_double(x, y) <= 0 else y
    # Math.min of ints and longs (floats and doubles were handled above)
    assert isinstance(a, int) and isinstance(b, int)
    return min(a, b)


def _max(a: object, b: object) -> object:
    if isinstance(a, float) or isinstance(b, float):
        x, y = float(a), float(b)  # type: ignore[arg-type]
        if math.isnan(x) or math.isnan(y):
            return math.nan
        return x if _compare_double(x, y) >= 0 else y
    # Math.max of ints and longs (floats and doubles were handled above)
    assert isinstance(a, int) and isinstance(b, int)
    return max(a, b)


def _round(a: float) -> int:
    """``Math.round(double)``: floor(a + 1/2), exactly; NaN is 0, out-of-range values saturate."""
    if math.isnan(a):
        return 0
    if math.isinf(a):
        return _java_int(a, 64)
    return _java_int(math.floor(Decimal(a) + Decimal("0.5")), 64)


_STATICS: dict[str, dict[str, Method]] = {
    "java.lang.Object": {"Object/0": object},
    "java.lang.Boolean": {
        **_box_statics("boolean", None),
        "Boolean/1": bool,
        "parseBoolean/1": lambda s: s is not None and s.lower() == "true",
        "logicalAnd/2": lambda a, b: a and b,
        "logicalOr/2": lambda a, b: a or b,
    },
    "java.lang.Character": {
        **_box_statics("char", None),
        "Character/1": lambda c: _char(_code(c)),
        "valueOf/1": lambda c: _char(_code(c)),
        "isDigit/1": _ctype(lambda s: s.isdecimal()),
        "isLetter/1": _ctype(str.isalpha),
        "isLetterOrDigit/1": _ctype(lambda s: s.isalpha() or s.isdecimal()),
        "isWhitespace/1": lambda c: _is_java_space(_code(c)),
        "isUpperCase/1": _ctype(lambda s: s.isupper()),
        "isLowerCase/1": _ctype(lambda s: s.islower()),
        "toUpperCase/1": lambda c: _char(ord(u)) if len(u := chr(_code(c)).upper()) == 1 else _char(_code(c)),
        "toLowerCase/1": lambda c: _char(ord(u)) if len(u := chr(_code(c)).lower()) == 1 else _char(_code(c)),
    },
    "java.lang.Byte": {**_box_statics("byte", 8), "Byte/1": int, "parseByte/1": lambda s: _parse_int(s, 8)},
    "java.lang.Short": {**_box_statics("short", 16), "Short/1": int, "parseShort/1": lambda s: _parse_int(s, 16)},
    "java.lang.Integer": {
        **_box_statics("int", 32),
        "Integer/1": int,
        "parseInt/1": lambda s: _parse_int(s, 32),
        "signum/1": lambda i: (i > 0) - (i < 0),
        "sum/2": lambda a, b: _wrap(a + b, 32),
        "max/2": max,
        "min/2": min,
    },
    "java.lang.Long": {
        **_box_statics("long", 64),
        "Long/1": int,
        "parseLong/1": lambda s: _parse_int(s, 64),
        "sum/2": lambda a, b: _wrap(a + b, 64),
    },
    "java.lang.Float": {
        **_box_statics("float", None),
        "Float/1": lambda v: f32(float(v)),
        "valueOf/1": lambda v: f32(float(v)),
        "parseFloat/1": lambda s: f32(_parse_float(s)),
        "isNaN/1": math.isnan,
    },
    "java.lang.Double": {
        **_box_statics("double", None),
        "Double/1": float,
        "valueOf/1": float,
        "parseDouble/1": _parse_float,
        "isNaN/1": math.isnan,
        "sum/2": lambda a, b: float(a) + float(b),
    },
    "java.lang.String": {"String/0": str, "valueOf/1": jformat},
    "java.lang.Math": {
        "abs/1": abs,
        "sqrt/1": lambda a: math.sqrt(a) if a >= 0 else math.nan,
        "pow/2": _pow,
        "sin/1": _fn(math.sin),
        "cos/1": _fn(math.cos),
        "tan/1": _fn(math.tan),
        "asin/1": lambda a: math.asin(a) if -1 <= a <= 1 else math.nan,
        "acos/1": lambda a: math.acos(a) if -1 <= a <= 1 else math.nan,
        "atan/1": math.atan,
        "atan2/2": math.atan2,
        "exp/1": lambda a: _overflow(math.exp, a),
        "log/1": lambda a: math.log(a) if a > 0 else (-math.inf if a == 0 else math.nan),
        "log10/1": lambda a: math.log10(a) if a > 0 else (-math.inf if a == 0 else math.nan),
        "hypot/2": math.hypot,
        "min/2": _min,
        "max/2": _max,
        "signum/1": lambda d: d if d == 0 or math.isnan(d) else math.copysign(1.0, d),
        "floor/1": lambda a: float(math.floor(a)) if math.isfinite(a) else a,
        "ceil/1": lambda a: float(math.ceil(a)) if math.isfinite(a) else a,
        "round/1": _round,
        "toRadians/1": math.radians,
        "toDegrees/1": math.degrees,
    },
    "java.util.ArrayList": {"ArrayList/0": list},
    "java.util.LinkedList": {"LinkedList/0": list},
    "java.util.HashSet": {"HashSet/0": set},
    "java.util.HashMap": {"HashMap/0": dict},
    "java.util.Optional": {
        "empty/0": JOptional,
        "of/1": lambda v: JOptional(v) if v is not None else _raise("java.lang.NullPointerException"),
        "ofNullable/1": JOptional,
    },
    "java.util.Date": {"Date/0": lambda: JDate(time.time_ns() // 1_000_000), "Date/1": JDate},
    "java.util.Collections": {
        "emptyList/0": list,
        "emptySet/0": set,
        "emptyMap/0": dict,
        "singletonList/1": lambda o: [o],
    },
}


_FIELDS: dict[str, dict[str, object]] = {
    "java.lang.Math": {"PI": math.pi, "E": math.e},
    "java.lang.Byte": {"MIN_VALUE": -(2**7), "MAX_VALUE": 2**7 - 1},
    "java.lang.Short": {"MIN_VALUE": -(2**15), "MAX_VALUE": 2**15 - 1},
    "java.lang.Integer": {"MIN_VALUE": _INT_MIN, "MAX_VALUE": _INT_MAX},
    "java.lang.Long": {"MIN_VALUE": _LONG_MIN, "MAX_VALUE": _LONG_MAX},
    "java.lang.Float": {
        "MIN_VALUE": struct.unpack(">f", struct.pack(">i", 1))[0],
        "MAX_VALUE": struct.unpack(">f", struct.pack(">i", 0x7F7FFFFF))[0],
    },
    "java.lang.Double": {"MIN_VALUE": 5e-324, "MAX_VALUE": 1.7976931348623157e308},
}


def jstatic(type_name: str, name: str, args: tuple[object, ...] = ()) -> object:
    """Calls the static method (or the constructor ``Type.Type``) ``name`` of the library type ``type_name``."""
    method = _STATICS.get(type_name, {}).get(f"{name}/{len(args)}")
    if method is None:
        raise JavaException(f"no static method {type_name}.{name} with {len(args)} argument(s)")
    return method(*args)


def jfield(type_name: str, name: str) -> object:
    """The value of the static attribute ``name`` of the library type ``type_name``."""
    fields = _FIELDS.get(type_name, {})
    if name not in fields:
        raise JavaException(f"no static attribute {type_name}.{name}")
    return fields[name]
