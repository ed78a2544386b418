"""ROS 2 message types by name, and the JSON form of messages (as rosbridge v2 writes them).

A message in JSON form is a dict with one key per field; nested messages are dicts, arrays are
lists, `builtin_interfaces/Time` is `{"sec": int, "nanosec": int}`. The conversion checks types
strictly (an `int32` field takes an int, not a float or a bool) so that a wrong frame gets an
error instead of a half-filled message. Needs only the generated Python message packages
(`std_msgs`, ...), not a running ROS graph.
"""

from __future__ import annotations

import importlib
import math
import re
from collections.abc import Mapping
from typing import Any

JsonMessage = dict[str, Any]

_TYPE_RE = re.compile(r"^([A-Za-z][A-Za-z0-9_]*)/(?:(msg|srv)/)?([A-Za-z][A-Za-z0-9_]*)$")

_INT_RANGES: dict[str, tuple[int, int]] = {
    "int8": (-(2**7), 2**7 - 1),
    "uint8": (0, 2**8 - 1),
    "byte": (0, 2**8 - 1),
    "char": (0, 2**8 - 1),
    "int16": (-(2**15), 2**15 - 1),
    "uint16": (0, 2**16 - 1),
    "int32": (-(2**31), 2**31 - 1),
    "uint32": (0, 2**32 - 1),
    "int64": (-(2**63), 2**63 - 1),
    "uint64": (0, 2**64 - 1),
}
_FLOATS = {"float", "double", "float32", "float64"}
_STRINGS = {"string", "wstring"}


class MessageError(ValueError):
    """A message or type name that does not fit."""


def normalize_type(name: str) -> str:
    """`std_msgs/String` and `std_msgs/msg/String` both become `std_msgs/msg/String`."""
    if not isinstance(name, str):
        raise MessageError("a type name must be a string")
    match = _TYPE_RE.match(name.strip())
    if not match:
        raise MessageError(f"invalid message type {name!r} (expected package/msg/Type)")
    package, kind, type_name = match.groups()
    return f"{package}/{kind or 'msg'}/{type_name}"


_class_cache: dict[str, type[Any]] = {}


def message_class(type_name: str) -> type[Any]:
    """The Python class of a ROS 2 message type (imported from its package)."""
    normalized = normalize_type(type_name)
    cached = _class_cache.get(normalized)
    if cached is not None:
        return cached
    package, kind, name = normalized.split("/")
    try:
        module = importlib.import_module(f"{package}.{kind}")
        cls = getattr(module, name)
    except (ImportError, AttributeError) as exc:
        raise MessageError(f"unknown message type {normalized}") from exc
    if not hasattr(cls, "get_fields_and_field_types"):
        raise MessageError(f"{normalized} is not a message type")
    _class_cache[normalized] = cls
    result: type[Any] = cls
    return result


def _field_types(cls_or_msg: Any) -> dict[str, str]:
    types: dict[str, str] = cls_or_msg.get_fields_and_field_types()
    return types


def _element_type(field_type: str) -> str | None:
    """`sequence<double, 3>` -> `double`; `double[3]` -> `double`; a scalar -> None."""
    if field_type.startswith("sequence<"):
        inner = field_type[len("sequence<") : -1]
        return inner.split(",")[0].strip()
    if field_type.endswith("]") and "[" in field_type:
        return field_type[: field_type.index("[")]
    return None


def _bound_of(field_type: str) -> int | None:
    if field_type.startswith("sequence<") and "," in field_type:
        return int(field_type[:-1].split(",")[1])
    return None


def _nested_class(type_str: str) -> type[Any]:
    """`builtin_interfaces/Time` (as in get_fields_and_field_types) -> the class."""
    return message_class(type_str)


def to_json(msg: Any) -> JsonMessage:
    """A ROS 2 message as a JSON-compatible dict."""
    result: JsonMessage = {}
    for name, field_type in _field_types(msg).items():
        result[name] = _value_to_json(getattr(msg, name), field_type)
    return result


def _value_to_json(value: Any, field_type: str) -> Any:
    element = _element_type(field_type)
    if element is not None:
        return [_value_to_json(v, element) for v in value]
    if hasattr(value, "get_fields_and_field_types"):
        return to_json(value)
    if isinstance(value, bytes):
        return list(value)
    if hasattr(value, "item"):  # numpy scalars
        return value.item()
    return value


def from_json(type_name: str, data: Any) -> Any:
    """A ROS 2 message of a type from its JSON form; raises MessageError when it does not fit."""
    cls = message_class(type_name)
    return _fill(cls, data, normalize_type(type_name))


def _fill(cls: type[Any], data: Any, path: str) -> Any:
    if data is None:
        data = {}
    if not isinstance(data, Mapping):
        raise MessageError(f"{path}: expected an object, got {type(data).__name__}")
    msg = cls()
    types = _field_types(cls)
    for key, value in data.items():
        if key not in types:
            raise MessageError(f"{path}: unknown field {key!r}")
        converted = _convert(value, types[key], f"{path}.{key}")
        try:
            setattr(msg, key, converted)
        except (AssertionError, TypeError, ValueError) as exc:
            raise MessageError(f"{path}.{key}: {exc or 'invalid value'}") from None
    return msg


def _convert(value: Any, field_type: str, path: str) -> Any:
    element = _element_type(field_type)
    if element is not None:
        if not isinstance(value, list):
            raise MessageError(f"{path}: expected an array")
        bound = _bound_of(field_type)
        if bound is not None and len(value) > bound:
            raise MessageError(f"{path}: at most {bound} elements")
        return [_convert(v, element, f"{path}[{i}]") for i, v in enumerate(value)]
    base = field_type.split("<", maxsplit=1)[0]
    if base in _INT_RANGES:
        if isinstance(value, bool) or not isinstance(value, int):
            raise MessageError(f"{path}: expected an integer ({field_type})")
        low, high = _INT_RANGES[base]
        if not low <= value <= high:
            raise MessageError(f"{path}: {value} is out of range for {field_type}")
        return value
    if base in _FLOATS:
        if isinstance(value, bool) or not isinstance(value, int | float):
            raise MessageError(f"{path}: expected a number ({field_type})")
        result = float(value)
        if base in ("float", "float32") and math.isfinite(result) and abs(result) > 3.4028235e38:
            raise MessageError(f"{path}: {value} is out of range for {field_type}")
        return result
    if base == "boolean":
        if not isinstance(value, bool):
            raise MessageError(f"{path}: expected true or false")
        return value
    if base in _STRINGS:
        if not isinstance(value, str):
            raise MessageError(f"{path}: expected a string")
        bound_match = re.match(r"^w?string<(\d+)>$", field_type)
        if bound_match and len(value) > int(bound_match.group(1)):
            raise MessageError(f"{path}: at most {bound_match.group(1)} characters")
        return value
    if base == "octet":
        if isinstance(value, bool) or not isinstance(value, int) or not 0 <= value <= 255:
            raise MessageError(f"{path}: expected a byte (0..255)")
        return bytes([value])
    if "/" in field_type:
        return _fill(_nested_class(field_type), value, path)
    raise MessageError(f"{path}: unsupported field type {field_type}")


def validate(type_name: str, data: Any) -> JsonMessage:
    """Checks a JSON message against its type and returns it with every field filled in."""
    return to_json(from_json(type_name, data))


# rosidl field types -> the names rosapi's message_details uses for them.
_ROSAPI_PRIMITIVES = {"double": "float64", "float": "float32", "octet": "byte", "boolean": "bool"}


def _rosapi_field(field_type: str) -> tuple[str, int]:
    """A field's type as rosapi names it, and its array length (-1: none, 0: unbounded)."""
    element = _element_type(field_type)
    if element is None:
        base, length = field_type, -1
    elif field_type.startswith("sequence<"):
        base, length = element, 0
    else:
        base, length = element, int(field_type[field_type.index("[") + 1 : -1] or 0)
    if base.startswith(("string<", "wstring<")):
        base = base[: base.index("<")]
    return _ROSAPI_PRIMITIVES.get(base, base), length


def _constants(cls: type[Any]) -> dict[str, Any]:
    # rosidl keeps a message's constants in its metaclass, name-mangled as `__constants`.
    meta = type(cls)
    constants = getattr(meta, f"_{meta.__name__.lstrip('_')}__constants", None)
    return dict(constants) if isinstance(constants, Mapping) else {}


def message_details(type_name: str) -> list[JsonMessage]:
    """rosapi's `message_details` of a type: its typedef first, then those of the message types it
    contains (each once). Constants come as names and values (strings, as rosapi sends them): the
    IDE reads enum literals from them."""
    typedefs: list[JsonMessage] = []
    seen: set[str] = set()
    pending = [normalize_type(type_name)]
    while pending:
        current = pending.pop(0)
        if current in seen:
            continue
        seen.add(current)
        cls = message_class(current)
        package, _, name = current.split("/")
        names, types, lengths, examples = [], [], [], []
        for field_name, field_type in _field_types(cls).items():
            rosapi_type, length = _rosapi_field(field_type)
            names.append(field_name)
            types.append(rosapi_type)
            lengths.append(length)
            if "/" in rosapi_type:
                pending.append(normalize_type(rosapi_type))
                examples.append("{}")
            else:
                examples.append("[]" if length >= 0 else "")
        constants = _constants(cls)
        typedefs.append(
            {
                "type": f"{package}/{name}",
                "fieldnames": names,
                "fieldtypes": types,
                "fieldarraylen": lengths,
                "examples": examples,
                "constnames": list(constants),
                "constvalues": [str(v) for v in constants.values()],
            }
        )
    return typedefs
