"""The application Modes (gear.Gearbox) on the python-timesync platform (generated)."""

from __future__ import annotations

from collections.abc import Mapping
from enum import Enum

from gear.gearbox import Gearbox as _gear_gearbox
from gear.scale import Scale as _gear_scale
from gear.total import Total as _gear_total
from maa_timesync import ComponentType
from maa_timesync.lockstep import LockstepApp

APPLICATION = "Modes"
ROOT = _gear_gearbox
COMPONENTS: dict[str, type[ComponentType]] = {
    "gear.Gearbox": _gear_gearbox,
    "gear.Scale": _gear_scale,
    "gear.Total": _gear_total,
}
ENUMS: dict[str, type[Enum]] = {
}
#: Port topics of the lock-step mode (ROS 2 names): "<instance path>.<out port>" of atomic instances
#: and "<in port>" of the root -> (topic, ROS 2 message type).
PORT_TOPICS: dict[str, tuple[str, str]] = {
    "speed": ("/gearbox/speed", "std_msgs/msg/Int32"),
    "s1.o": ("/gearbox/s1/o", "std_msgs/msg/Int32"),
    "s10.o": ("/gearbox/s10/o", "std_msgs/msg/Int32"),
    "t.o": ("/gearbox/t/o", "std_msgs/msg/Int32"),
}
#: ROS 2 node names of the atomic instances and mode components (keys of /maa/automaton_states).
NODE_NAMES: dict[str, str] = {
    "": "/gearbox",
    "s1": "/gearbox/s1",
    "s10": "/gearbox/s10",
    "t": "/gearbox/t",
}

#: The automata table (@maa/protocol AutomatonEntry, for the IDE): instance path -> its entry as JSON.
AUTOMATA: dict[str, str] = {
    "": "{\"instancePath\":\"\",\"node\":\"/gearbox\",\"component\":\"gear.Gearbox\",\"file\":\"gear/Gearbox.arc\",\"states\":[{\"path\":\"First\",\"line\":10},{\"path\":\"Second\",\"line\":15}],\"transitions\":[{\"index\":0,\"from\":\"First\",\"to\":\"Second\",\"label\":\"[speed < 0]\",\"line\":22,\"column\":5},{\"index\":1,\"from\":\"Second\",\"to\":\"First\",\"label\":\"[speed == 0]\",\"line\":23,\"column\":5}],\"kind\":\"modes\"}",
}


def create_controller(parameters: Mapping[str, object]) -> LockstepApp:
    """The simulator's lock-step factory (lockstep.json)."""
    return LockstepApp(ROOT, parameters, PORT_TOPICS, NODE_NAMES, AUTOMATA)
