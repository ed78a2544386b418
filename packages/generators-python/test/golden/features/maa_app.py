"""The application Features (feat.Features) on the python-timesync platform (generated)."""

from __future__ import annotations

from collections.abc import Mapping
from enum import Enum

from feat.counter import Counter as _feat_counter
from feat.features import Features as _feat_features
from feat.lamp import Lamp as _feat_lamp
from feat.types.data import Mode
from maa_timesync import ComponentType
from maa_timesync.lockstep import LockstepApp

APPLICATION = "Features"
ROOT = _feat_features
COMPONENTS: dict[str, type[ComponentType]] = {
    "feat.Counter": _feat_counter,
    "feat.Features": _feat_features,
    "feat.Lamp": _feat_lamp,
}
ENUMS: dict[str, type[Enum]] = {
    "Mode": Mode,
}
#: Port topics of the lock-step mode (ROS 2 names): "<instance path>.<out port>" of atomic instances
#: and "<in port>" of the root -> (topic, ROS 2 message type).
PORT_TOPICS: dict[str, tuple[str, str]] = {
    "inc": ("/features/inc", "std_msgs/msg/Int32"),
    "mode": ("/features/mode", "std_msgs/msg/String"),
    "press": ("/features/press", "std_msgs/msg/Bool"),
    "level": ("/features/level", "std_msgs/msg/Int32"),
    "counter.total": ("/features/counter/total", "std_msgs/msg/Int32"),
    "counter.text": ("/features/counter/text", "std_msgs/msg/String"),
    "counter.reading": ("/features/counter/reading", "std_msgs/msg/String"),
    "counter.pair": ("/features/counter/pair", "std_msgs/msg/String"),
    "lamp.log": ("/features/lamp/log", "std_msgs/msg/String"),
    "lamp.brightness": ("/features/lamp/brightness", "std_msgs/msg/Int32"),
    "other.total": ("/features/other/total", "std_msgs/msg/Int32"),
    "other.text": ("/features/other/text", "std_msgs/msg/String"),
    "other.reading": ("/features/other/reading", "std_msgs/msg/String"),
    "other.pair": ("/features/other/pair", "std_msgs/msg/String"),
}
#: ROS 2 node names of the atomic instances and mode components (keys of /maa/automaton_states).
NODE_NAMES: dict[str, str] = {
    "counter": "/features/counter",
    "lamp": "/features/lamp",
    "other": "/features/other",
}

#: The automata table (@maa/protocol AutomatonEntry, for the IDE): instance path -> its entry as JSON.
AUTOMATA: dict[str, str] = {
    "lamp": "{\"instancePath\":\"lamp\",\"node\":\"/features/lamp\",\"component\":\"feat.Lamp\",\"file\":\"feat/Lamp.arc\",\"states\":[{\"path\":\"Off\",\"line\":13},{\"path\":\"On\",\"line\":16},{\"path\":\"On.Dim\",\"line\":20},{\"path\":\"On.Bright\",\"line\":21}],\"transitions\":[{\"index\":0,\"from\":\"On\",\"to\":\"On\",\"label\":\"level [level > 5] / { presses++; log = \\\"internal\\\"; }\",\"line\":24,\"column\":7},{\"index\":1,\"from\":\"On.Dim\",\"to\":\"On.Bright\",\"label\":\"Tick / { String state = \\\"brighter\\\"; log = state; }\",\"line\":26,\"column\":7},{\"index\":2,\"from\":\"Off\",\"to\":\"On\",\"label\":\"press [press] / { presses++; }\",\"line\":28,\"column\":5},{\"index\":3,\"from\":\"On\",\"to\":\"Off\",\"label\":\"press [press]\",\"line\":29,\"column\":5}]}",
}


def create_controller(parameters: Mapping[str, object]) -> LockstepApp:
    """The simulator's lock-step factory (lockstep.json)."""
    return LockstepApp(ROOT, parameters, PORT_TOPICS, NODE_NAMES, AUTOMATA)
