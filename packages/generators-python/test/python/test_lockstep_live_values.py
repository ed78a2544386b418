"""Lock-step live values (docs/ide.md, "Live values"): port topics, automaton states, root input injection.

Runs the golden timesync build of the Features fixture (root in ports of primitive and enum types,
a hierarchical automaton, class-typed ports) through its generated lock-step factory.
"""

from __future__ import annotations

import importlib
import json
from collections.abc import Iterator
from types import ModuleType

import pytest
from conftest import import_golden_app

from maa_timesync.lockstep import STATES_TOPIC, TRANSITIONS_TOPIC, port_message, port_value


@pytest.fixture
def features_app() -> Iterator[ModuleType]:
    yield from import_golden_app("features", "feat")


def states_of(out: dict[str, list[dict[str, object]]]) -> dict[str, str] | None:
    if STATES_TOPIC not in out:
        return None
    [message] = out[STATES_TOPIC]
    result: dict[str, str] = json.loads(str(message["data"]))
    return result


def test_topics_follow_the_ros2_names_with_lockstep_types(features_app: ModuleType) -> None:
    topics = features_app.create_controller({}).topics()
    assert topics["/features/inc"] == "std_msgs/msg/Int32"  # a root in port
    assert topics["/features/mode"] == "std_msgs/msg/String"  # an enum: its constant's name
    assert topics["/features/press"] == "std_msgs/msg/Bool"
    assert topics["/features/lamp/brightness"] == "std_msgs/msg/Int32"  # out port of an atomic instance
    assert topics["/features/counter/reading"] == "std_msgs/msg/String"  # a class: JSON
    assert topics[STATES_TOPIC] == "std_msgs/msg/String"
    assert not any(t in topics for t in ("/features/total", "/features/log"))  # root out ports are forwarders


def test_every_slice_shows_its_port_values_and_changed_states(features_app: ModuleType) -> None:
    app = features_app.create_controller({})
    first = app.step(
        {
            "/features/press": {"data": True},
            "/features/inc": {"data": 2},
            "/features/mode": {"data": "FAST"},
            "/features/level": {"data": 7},
        }
    )
    # injected root inputs are shown in the slice that reads them
    assert first["/features/press"] == [{"data": True}]
    assert first["/features/mode"] == [{"data": "FAST"}]
    # a port written several times in a slice: every message, in order (initial outputs included)
    assert first["/features/lamp/log"] == [{"data": v} for v in ("init", "off", "on", "internal", "brighter")]
    assert first["/features/lamp/brightness"] == [{"data": 1}, {"data": 10}]
    assert first["/features/counter/text"][-1] == {"data": "sum=6"}
    # states: in the first slice, dotted paths for hierarchical states, keyed by ROS 2 node name
    assert states_of(first) == {"/features/lamp": "On.Bright"}
    second = app.step({})
    assert "/features/press" not in second and "/features/lamp/log" not in second
    assert states_of(second) is None  # unchanged
    third = app.step({"/features/press": {"data": True}})
    assert third["/features/lamp/log"] == [{"data": "leaving on"}, {"data": "off"}]
    assert states_of(third) == {"/features/lamp": "Off"}
    assert app.states() == {"/features/lamp": "Off"}
    app.reset()
    assert states_of(app.step({})) == {"/features/lamp": "Off"}  # a fresh first slice


def test_transitions_name_their_source_state_when_an_action_declares_a_local_state(features_app: ModuleType) -> None:
    """Lamp's `Dim -> Bright` declares `String state` in its action: the event still names the state
    the transition left (the generated code kept it in a local of the same name before)."""
    app = features_app.create_controller({})
    first = app.step({"/features/press": {"data": True}, "/features/level": {"data": 7}})
    events = [json.loads(str(m["data"])) for m in first[TRANSITIONS_TOPIC]]
    assert [(e["from"], e["to"]) for e in events] == [("Off", "On.Dim"), ("On.Dim", "On.Dim"), ("On.Dim", "On.Bright")]
    assert first["/features/lamp/log"][-1] == {"data": "brighter"}


def test_bad_injected_values_are_refused(features_app: ModuleType) -> None:
    app = features_app.create_controller({})
    with pytest.raises(ValueError, match="not a constant of Mode"):
        app.validate_input("/features/mode", {"data": "WARP"})
    app.validate_input("/features/mode", {"data": "SLOW"})
    app.validate_input("/unrelated/topic", {"data": "anything"})
    out = app.step({"/features/mode": {"data": "WARP"}})  # dropped, the slice still runs
    assert "/features/mode" not in out and STATES_TOPIC in out


def test_port_messages(features_app: ModuleType) -> None:
    data = importlib.import_module("feat.types.data")
    assert port_message(data.Mode.SLOW) == {"data": "SLOW"}
    assert port_message(5) == {"data": 5} and port_message(True) == {"data": True}
    assert port_message(float("inf")) == {"data": "inf"}
    pair = data.Pair(first=1, second=2, rest=[3])
    assert json.loads(str(port_message(pair)["data"])) == {"first": 1, "second": 2, "rest": [3]}
    assert port_value({"data": "FAST"}, data.Mode) is data.Mode.FAST
    assert port_value({"data": 4}, "int") == 4
