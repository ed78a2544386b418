"""The application Variability (lamp.Room) on the python-timesync platform (generated)."""

from __future__ import annotations

from collections.abc import Mapping
from enum import Enum

from lamp.doubler import Doubler as _lamp_doubler
from lamp.lamp import Lamp as _lamp_lamp
from lamp.room import Room as _lamp_room
from maa_timesync import ComponentType
from maa_timesync.lockstep import LockstepApp

APPLICATION = "Variability"
ROOT = _lamp_room
COMPONENTS: dict[str, type[ComponentType]] = {
    "lamp.Doubler": _lamp_doubler,
    "lamp.Lamp": _lamp_lamp,
    "lamp.Room": _lamp_room,
}
ENUMS: dict[str, type[Enum]] = {
}
#: Port topics of the lock-step mode (ROS 2 names): "<instance path>.<out port>" of atomic instances
#: and "<in port>" of the root -> (topic, ROS 2 message type).
PORT_TOPICS: dict[str, tuple[str, str]] = {
    "level": ("/room/level", "std_msgs/msg/Int32"),
    "lamp.brightness": ("/room/lamp/brightness", "std_msgs/msg/Int32"),
    "doubler.o": ("/room/doubler/o", "std_msgs/msg/Int32"),
}
#: ROS 2 node names of the atomic instances and mode components (keys of /maa/automaton_states).
NODE_NAMES: dict[str, str] = {
    "lamp": "/room/lamp",
    "doubler": "/room/doubler",
}

#: The automata table (@maa/protocol AutomatonEntry, for the IDE): instance path -> its entry as JSON.
AUTOMATA: dict[str, str] = {
}


def create_controller(parameters: Mapping[str, object]) -> LockstepApp:
    """The simulator's lock-step factory (lockstep.json)."""
    return LockstepApp(ROOT, parameters, PORT_TOPICS, NODE_NAMES, AUTOMATA)
