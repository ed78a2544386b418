"""The application Instances (hall.Hall) on the python-timesync platform (generated)."""

from __future__ import annotations

from collections.abc import Mapping
from enum import Enum

from hall.hall import Hall as _hall_hall
from hall.lamp import Lamp as _hall_lamp
from hall.lamp__no_dimmable import Lamp__no_dimmable as _hall_lamp__no_dimmable
from hall.wing import Wing as _hall_wing
from hall.wing__dimmed import Wing__dimmed as _hall_wing__dimmed
from maa_timesync import ComponentType
from maa_timesync.lockstep import LockstepApp

APPLICATION = "Instances"
ROOT = _hall_hall
COMPONENTS: dict[str, type[ComponentType]] = {
    "hall.Hall": _hall_hall,
    "hall.Lamp": _hall_lamp,
    "hall.Lamp__no_dimmable": _hall_lamp__no_dimmable,
    "hall.Wing": _hall_wing,
    "hall.Wing__dimmed": _hall_wing__dimmed,
}
ENUMS: dict[str, type[Enum]] = {
}
#: Port topics of the lock-step mode (ROS 2 names): "<instance path>.<out port>" of atomic instances
#: and "<in port>" of the root -> (topic, ROS 2 message type).
PORT_TOPICS: dict[str, tuple[str, str]] = {
    "level": ("/hall/level", "std_msgs/msg/Int32"),
    "a.brightness": ("/hall/a/brightness", "std_msgs/msg/Int32"),
    "b.brightness": ("/hall/b/brightness", "std_msgs/msg/Int32"),
    "c.brightness": ("/hall/c/brightness", "std_msgs/msg/Int32"),
    "w1.lamp.brightness": ("/hall/w1/lamp/brightness", "std_msgs/msg/Int32"),
    "w2.lamp.brightness": ("/hall/w2/lamp/brightness", "std_msgs/msg/Int32"),
}
#: ROS 2 node names of the atomic instances and mode components (keys of /maa/automaton_states).
NODE_NAMES: dict[str, str] = {
    "a": "/hall/a",
    "b": "/hall/b",
    "c": "/hall/c",
    "w1.lamp": "/hall/w1/lamp",
    "w2.lamp": "/hall/w2/lamp",
}

#: The automata table (@maa/protocol AutomatonEntry, for the IDE): instance path -> its entry as JSON.
AUTOMATA: dict[str, str] = {
}


def create_controller(parameters: Mapping[str, object]) -> LockstepApp:
    """The simulator's lock-step factory (lockstep.json)."""
    return LockstepApp(ROOT, parameters, PORT_TOPICS, NODE_NAMES, AUTOMATA)
