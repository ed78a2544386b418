"""ROS 2 message definitions as text, the way ROS 2 bags carry them (MCAP schema encoding `ros2msg`).

A definition is the type's `.msg` text followed by the text of every message type it uses, each
after a line of 80 `=` and a line `MSG: pkg/Type`. The text comes from the type's `.msg` file
(maa-sim's own types in `maa_sim/msg`, installed interface packages in their share folder, found
through the ament index), or, for a package installed without its share folder, is written from
the Python class's fields (without comments and constants).
"""

from __future__ import annotations

import importlib.util
import os
import re
import sys
from functools import cache
from pathlib import Path
from typing import Any

from .messages import message_class, normalize_type

SEPARATOR = "=" * 80
#: maa-sim's own message types (the scene state), with their `.msg` files in this package
OWN_PACKAGE = "maa_sim"
_OWN_MSG_DIR = Path(__file__).resolve().parent / "msg"

_PRIMITIVES = {
    "bool",
    "byte",
    "char",
    "float32",
    "float64",
    "int8",
    "uint8",
    "int16",
    "uint16",
    "int32",
    "uint32",
    "int64",
    "uint64",
    "string",
    "wstring",
}
#: rosidl's Python field type names that differ from the `.msg` names
_PY_TO_MSG = {"double": "float64", "float": "float32", "boolean": "bool", "octet": "byte"}


def message_definition(type_name: str) -> str:
    """The full definition of a type: its text, then each message type it uses once (depth first)."""
    root = normalize_type(type_name)
    parts = [message_text(root)]
    seen = {root}
    pending = dependencies(root)
    while pending:
        dep = pending.pop(0)
        if dep in seen:
            continue
        seen.add(dep)
        package, _, name = dep.split("/")
        parts.append(f"{SEPARATOR}\nMSG: {package}/{name}\n{message_text(dep)}")
        pending = dependencies(dep) + pending
    return "\n".join(part.rstrip("\n") for part in parts) + "\n"


@cache
def message_text(type_name: str) -> str:
    """One type's own text (no dependencies); MessageError when the type is unknown."""
    package, _, name = normalize_type(type_name).split("/")
    msg_file = _msg_file(package, name)
    if msg_file is not None:
        return msg_file.read_text(encoding="utf-8")
    return _text_from_class(message_class(type_name))


def dependencies(type_name: str) -> list[str]:
    """The message types a type's fields use, in field order (`pkg/msg/Type`)."""
    package = normalize_type(type_name).split("/")[0]
    result: list[str] = []
    for line in message_text(type_name).splitlines():
        field_type = _field_type(line)
        if field_type is None or field_type in _PRIMITIVES:
            continue
        if field_type == "Header":
            qualified = "std_msgs/msg/Header"
        elif "/" in field_type:
            qualified = normalize_type(field_type)
        else:
            qualified = f"{package}/msg/{field_type}"
        if qualified not in result:
            result.append(qualified)
    return result


def _field_type(line: str) -> str | None:
    """The base type of a field line (`geometry_msgs/Pose[] poses` -> `geometry_msgs/Pose`);
    None for comments, blank lines and constants."""
    text = line.split("#", 1)[0].strip()
    if not text:
        return None
    tokens = text.split(None, 1)
    if len(tokens) < 2 or re.match(r"^\w+\s*=", tokens[1]):
        return None  # a constant (NAME=value) or not a field at all
    base = tokens[0].split("[", 1)[0]
    return base.split("<", 1)[0]


def _msg_file(package: str, name: str) -> Path | None:
    if package == OWN_PACKAGE:
        own = _OWN_MSG_DIR / f"{name}.msg"
        return own if own.is_file() else None
    for prefix in _prefixes(package):
        candidate = prefix / "share" / package / "msg" / f"{name}.msg"
        if candidate.is_file():
            return candidate
    return None


def _prefixes(package: str) -> list[Path]:
    """Where an interface package's share folder may be: the ament prefixes, this Python's prefix,
    and the prefix the package's Python module was installed into (`PREFIX/lib/pythonX.Y/site-packages`)."""
    prefixes = [Path(p) for p in os.environ.get("AMENT_PREFIX_PATH", "").split(os.pathsep) if p]
    prefixes.append(Path(sys.prefix))
    spec = importlib.util.find_spec(package)
    origin = spec.origin if spec is not None else None
    if origin:
        for parent in Path(origin).resolve().parents:
            if parent.name == "lib":
                prefixes.append(parent.parent)
                break
    return prefixes


def _text_from_class(cls: type[Any]) -> str:
    """A `.msg` text from rosidl's Python field types (`sequence<double, 3>` -> `float64[<=3]`)."""
    fields: dict[str, str] = cls.get_fields_and_field_types()
    return "".join(f"{_msg_type(field_type)} {name}\n" for name, field_type in fields.items())


def _msg_type(field_type: str) -> str:
    if field_type.startswith("sequence<"):
        inner = field_type[len("sequence<") : -1]
        element, _, bound = inner.partition(",")
        return f"{_msg_type(element.strip())}[{'<=' + bound.strip() if bound else ''}]"
    if field_type.endswith("]") and "[" in field_type:
        element = field_type[: field_type.index("[")]
        return f"{_msg_type(element)}{field_type[field_type.index('[') :]}"
    bounded = re.match(r"^(w?string)<(\d+)>$", field_type)
    if bounded:
        return f"{bounded.group(1)}<={bounded.group(2)}"
    return _PY_TO_MSG.get(field_type, field_type)
