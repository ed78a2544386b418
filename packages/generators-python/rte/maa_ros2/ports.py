"""How port values travel as ROS 2 messages.

The behavior classes see plain Python values (``maa_behavior``): numbers, booleans, strings,
``enum.Enum`` members and dataclasses of the Python data types. A port's codec turns them into
messages and back: primitives travel in ``std_msgs`` messages (field ``data``), enums as the
generated enum message (constants + ``value`` = the literal's ordinal), classes as their
generated message (fields in snake_case, converted recursively).
"""

from __future__ import annotations

import dataclasses
import enum
import re
import typing
from collections.abc import Callable
from dataclasses import dataclass
from typing import Any


@dataclass(frozen=True)
class PortCodec:
    """The message class of a port and its conversions."""

    msg_type: Any
    to_msg: Callable[[object], Any]
    from_msg: Callable[[Any], object]


def std_port(msg_type: Any, cast: Callable[[Any], object]) -> PortCodec:
    """A primitive port carried in a ``std_msgs`` message with a ``data`` field."""

    def to_msg(value: object) -> Any:
        return msg_type(data=cast(value))

    def from_msg(msg: Any) -> object:
        return msg.data

    return PortCodec(msg_type, to_msg, from_msg)


def char_port(msg_type: Any) -> PortCodec:
    """A ``char``/``Character`` port: the behavior sees the character's code (as Java's ``char`` is
    an integral type), the topic carries the character as a one-character ``std_msgs/String``."""

    def to_msg(value: object) -> Any:
        return msg_type(data=chr(value) if isinstance(value, int) and not isinstance(value, bool) else str(value))

    def from_msg(msg: Any) -> object:
        data = str(msg.data)
        return ord(data[0]) if data else 0

    return PortCodec(msg_type, to_msg, from_msg)


def enum_port(msg_type: Any, py_type: type[enum.Enum]) -> PortCodec:
    """An enum port: the message's ``value`` is the literal's ordinal."""
    members = list(py_type)

    def to_msg(value: object) -> Any:
        if isinstance(value, enum.Enum):
            return msg_type(value=members.index(value))
        return msg_type(value=int(value))  # type: ignore[call-overload]

    def from_msg(msg: Any) -> object:
        return members[int(msg.value)]

    return PortCodec(msg_type, to_msg, from_msg)


def class_port(msg_type: Any, py_type: type) -> PortCodec:
    """A class port: the dataclass and its generated message, field by field."""

    def to_msg(value: object) -> Any:
        return _to_msg(value, msg_type)

    def from_msg(msg: Any) -> object:
        return _from_msg(msg, py_type)

    return PortCodec(msg_type, to_msg, from_msg)


def field_name(name: str) -> str:
    """The message field of an attribute (as ros2.DataTypes names it)."""
    s = re.sub(r"([a-z0-9])([A-Z])", r"\1_\2", name)
    s = re.sub(r"([A-Z]+)([A-Z][a-z])", r"\1_\2", s).lower()
    s = re.sub(r"[^a-z0-9_]+", "_", s)
    return re.sub(r"_+", "_", s).strip("_")


def _to_msg(value: object, msg_type: Any) -> Any:
    msg = msg_type()
    if not dataclasses.is_dataclass(value):
        raise TypeError(f"cannot convert {value!r} to {msg_type.__name__}")
    for f in dataclasses.fields(value):
        name = field_name(f.name)
        current = getattr(msg, name)
        v = getattr(value, f.name)
        if isinstance(v, enum.Enum):
            v = type(current)(value=list(type(v)).index(v))
        elif dataclasses.is_dataclass(v):
            v = _to_msg(v, type(current))
        setattr(msg, name, v)
    return msg


def _from_msg(msg: Any, py_type: type) -> object:
    hints = typing.get_type_hints(py_type)
    values: dict[str, object] = {}
    for f in dataclasses.fields(py_type):
        v = getattr(msg, field_name(f.name))
        hint = hints.get(f.name)
        for candidate in typing.get_args(hint) or (hint,):
            if isinstance(candidate, type) and issubclass(candidate, enum.Enum):
                v = list(candidate)[int(v.value)]
                break
            if isinstance(candidate, type) and dataclasses.is_dataclass(candidate):
                v = _from_msg(v, candidate)
                break
        values[f.name] = v
    return py_type(**values)
