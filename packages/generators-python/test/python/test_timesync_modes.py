"""maa_timesync.modes: decomposed components whose mode automaton switches subcomponents and connectors."""

from __future__ import annotations

import json
from collections.abc import Iterator, Mapping
from types import ModuleType

import pytest
from conftest import import_golden_app

from maa_behavior import Behavior
from maa_timesync import TICK, AtomicComponent, ComponentType, ModeComponent, System
from maa_timesync.lockstep import STATES_TOPIC, TRANSITIONS_TOPIC, LockstepApp
from maa_timesync.modes import ModeInstance, port_value
from maa_timesync.runtime import Connector


class CountBehavior(Behavior):
    """Sync: sends how many slices with a message it has seen (its state survives resting)."""

    TIMING = "sync"
    IN_PORTS = ("i",)
    OUT_PORTS = ("o",)

    def init(self) -> None:
        self.count = 0

    def step(self, inputs: Mapping[str, object]) -> None:
        if inputs.get("i") is not None:
            self.count += 1
            self._emit("o", self.count)


class Count(AtomicComponent):
    NAME = "t.Count"
    IN_PORTS = ("i",)
    OUT_PORTS = ("o",)
    PORT_TYPES = {"i": "int", "o": "int"}
    BEHAVIOR = CountBehavior


class NegBehavior(Behavior):
    """Event-driven: negates every message at once."""

    TIMING = "timed"
    IN_PORTS = ("i",)
    OUT_PORTS = ("o",)

    def on_message(self, port: str, value: object) -> None:
        assert isinstance(value, int)
        self._emit("o", -value)


class Neg(AtomicComponent):
    NAME = "t.Neg"
    IN_PORTS = ("i",)
    OUT_PORTS = ("o",)
    PORT_TYPES = {"i": "int", "o": "int"}
    BEHAVIOR = NegBehavior


class Switch(ModeComponent):
    """<<sync>> mode automaton { initial mode A { Count a; i -> a.i; a.o -> o; } mode B { Count b; ... } A -> B [i < 0]; B -> A [i > 0]; }."""

    NAME = "t.Switch"
    IN_PORTS = ("i",)
    OUT_PORTS = ("o", "unused")
    PORT_TYPES = {"i": "int", "o": "int", "unused": "int"}
    MODES = ("A", "B")
    INITIAL_MODE = "A"
    MODE_TIMING = "sync"
    MODE_SUBCOMPONENTS: Mapping[str, tuple[str, ...]] = {"A": ("a",), "B": ("b",)}
    MODE_CONNECTORS: Mapping[str, tuple[Connector, ...]] = {
        "A": (("", "i", (("a", "i"),)), ("a", "o", (("", "o"),))),
        "B": (("", "i", (("b", "i"),)), ("b", "o", (("", "o"),))),
    }

    @classmethod
    def mode_transition(
        cls, mode: str, trigger: str | None, inputs: Mapping[str, object], params: Mapping[str, object]
    ) -> tuple[int, str] | None:
        del trigger, params
        i = inputs.get("i")
        if mode == "A" and isinstance(i, int) and i < 0:
            return 0, "B"
        if mode == "B" and isinstance(i, int) and i > 0:
            return 1, "A"
        return None

    @classmethod
    def subcomponents(cls, params: Mapping[str, object]) -> list[tuple[str, type[ComponentType], dict[str, object]]]:
        return [("a", Count, {}), ("b", Count, {})]


class EventSwitch(ModeComponent):
    """mode automaton (event-based) { initial mode Pass { i -> o; } mode Negate { Neg n; i -> n.i; n.o -> o; } Pass -> Negate flip; Negate -> Pass Tick; }."""

    NAME = "t.EventSwitch"
    IN_PORTS = ("i", "flip")
    OUT_PORTS = ("o",)
    PORT_TYPES = {"i": "int", "flip": "boolean", "o": "int"}
    MODES = ("Pass", "Negate")
    INITIAL_MODE = "Pass"
    MODE_TIMING = "timed"
    MODE_SUBCOMPONENTS: Mapping[str, tuple[str, ...]] = {"Pass": (), "Negate": ("n",)}
    MODE_CONNECTORS: Mapping[str, tuple[Connector, ...]] = {
        "Pass": (("", "i", (("", "o"),)),),
        "Negate": (("", "i", (("n", "i"),)), ("n", "o", (("", "o"),))),
    }

    @classmethod
    def mode_transition(
        cls, mode: str, trigger: str | None, inputs: Mapping[str, object], params: Mapping[str, object]
    ) -> tuple[int, str] | None:
        del inputs, params
        if mode == "Pass" and trigger == "flip":
            return 0, "Negate"
        if mode == "Negate" and trigger == "":
            return 1, "Pass"
        return None

    @classmethod
    def subcomponents(cls, params: Mapping[str, object]) -> list[tuple[str, type[ComponentType], dict[str, object]]]:
        return [("n", Neg, {})]


def feed(system: System, port: str, items: list[object]) -> None:
    for item in items:
        system.receive(port, item)


def test_sync_mode_switches_before_the_slice_and_resting_subcomponents_keep_their_state() -> None:
    system = System(Switch)
    system.init()
    feed(system, "i", [5, TICK, 7, TICK, -1, TICK, -2, TICK, 3, TICK, TICK])
    system.run()
    # a counts slices 1, 2; slice 3 (-1) already runs in B (b: 1), slice 4 in B (b: 2);
    # slice 5 (3) back in A, whose count went on from 2; slice 6 has no message.
    assert system.outputs["o"] == [1, TICK, 2, TICK, 1, TICK, 2, TICK, 3, TICK, TICK]
    # No connector drives 'unused' in any mode: it gets the slice ends.
    assert system.outputs["unused"] == [TICK] * 6
    top = system.top
    assert isinstance(top, ModeInstance)
    assert top.mode_log == ["A", "B", "A"]


def test_the_transition_hook_hears_every_mode_transition_with_its_index() -> None:
    system = System(Switch)
    top = system.top
    assert isinstance(top, ModeInstance)
    taken: list[tuple[int, str, str]] = []
    top.transition_hook = lambda index, source, target: taken.append((index, source, target))
    system.init()
    # slices whose guard does not hold (5, 7 in A; -2 in B; no message) take no transition
    feed(system, "i", [5, TICK, 7, TICK, -1, TICK, -2, TICK, 3, TICK, TICK])
    system.run()
    assert taken == [(0, "A", "B"), (1, "B", "A")]


def test_event_mode_switches_on_its_trigger_ports_and_on_ticks() -> None:
    system = System(EventSwitch)
    system.init()
    system.receive("i", 1)
    system.receive("flip", True)
    system.receive("i", 2)
    system.receive("i", TICK)
    system.receive("flip", TICK)
    system.receive("i", 3)
    system.receive("i", TICK)
    system.receive("flip", TICK)
    system.run()
    # 1 passes; the message on flip switches to Negate, so 2 is negated; the tick switches back.
    assert system.outputs["o"] == [1, -2, TICK, 3, TICK]


def test_port_value_gives_the_default_without_message() -> None:
    assert port_value({"i": None}, "i", 0) == 0
    assert port_value({}, "i", False) is False
    assert port_value({"i": -3}, "i", 0) == -3


def test_lockstep_publishes_the_mode_as_the_live_state_of_the_mode_component() -> None:
    # the same live-state entry as an automaton's: the instance's node path -> its mode
    app = LockstepApp(Switch, {}, {"i": ("/switch/i", "std_msgs/msg/Int32")}, {"": "/switch"})
    first = app.step({})
    assert first[STATES_TOPIC] == [{"data": json.dumps({"/switch": "A"})}]
    assert STATES_TOPIC not in app.step({"/switch/i": {"data": 4}})  # no switch: nothing new
    switched = app.step({"/switch/i": {"data": -1}})
    assert switched[STATES_TOPIC] == [{"data": json.dumps({"/switch": "B"})}]
    assert app.states() == {"/switch": "B"}


def test_lockstep_reports_mode_transitions_as_the_instance_transitions() -> None:
    # /maa/transitions as an automaton's: the instance's node path, the modes, the transition's index
    app = LockstepApp(Switch, {}, {"i": ("/switch/i", "std_msgs/msg/Int32")}, {"": "/switch"})
    assert TRANSITIONS_TOPIC not in app.step({})
    assert TRANSITIONS_TOPIC not in app.step({"/switch/i": {"data": 4}})  # the guard does not hold
    switched = app.step({"/switch/i": {"data": -1}})
    assert [json.loads(str(m["data"])) for m in switched[TRANSITIONS_TOPIC]] == [{"node": "/switch", "from": "A", "to": "B", "index": 0}]
    back = app.step({"/switch/i": {"data": 2}})
    assert [json.loads(str(m["data"])) for m in back[TRANSITIONS_TOPIC]] == [{"node": "/switch", "from": "B", "to": "A", "index": 1}]
    app.reset()  # a reset run reports its own transitions only
    assert TRANSITIONS_TOPIC not in app.step({})


@pytest.fixture
def gearbox_app() -> Iterator[ModuleType]:
    """The golden timesync build of the modes fixture (gear.Gearbox) through its generated app module."""
    yield from import_golden_app("modes", "gear")


def test_the_generated_build_reports_its_mode_transitions_by_their_table_index(gearbox_app: ModuleType) -> None:
    app = gearbox_app.create_controller({})
    (entry,) = app.automata()
    assert entry["node"] == "/gearbox" and entry["kind"] == "modes"
    table = {(t["from"], t["to"]): t["index"] for t in entry["transitions"]}
    assert table == {("First", "Second"): 0, ("Second", "First"): 1}
    app.step({})
    switched = app.step({"/gearbox/speed": {"data": -3}})
    [event] = [json.loads(str(m["data"])) for m in switched[TRANSITIONS_TOPIC]]
    assert event == {"node": "/gearbox", "from": "First", "to": "Second", "index": table[("First", "Second")]}
    back = app.step({})  # no speed: Java's 0, the guard of Second -> First
    [event] = [json.loads(str(m["data"])) for m in back[TRANSITIONS_TOPIC]]
    assert event == {"node": "/gearbox", "from": "Second", "to": "First", "index": table[("Second", "First")]}
