"""Tests of maa_timesync: the scheduler's stream semantics, stream encoding, stream tests, lock-step."""

from __future__ import annotations

from collections.abc import Mapping
from enum import Enum
from pathlib import Path

import pytest

from maa_behavior import Behavior
from maa_timesync import TICK, AtomicComponent, ComponentType, ComposedComponent, System, decode_item, encode_item, run_streams
from maa_timesync.lockstep import LockstepApp, platform
from maa_timesync.streamtest import StreamTestError, parse, run_files


class OnOff(Enum):
    ON = 0
    OFF = 1


class DelayBehavior(Behavior):
    """Sync Delay: initial { o = OFF; }, delayed o, S -> S / { o = i; }."""

    TIMING = "sync"
    IN_PORTS = ("i",)
    OUT_PORTS = ("o",)
    DELAYED = frozenset({"o"})

    def init(self) -> None:
        self._emit("o", OnOff.OFF)

    def step(self, inputs: Mapping[str, object]) -> None:
        self._emit("o", inputs.get("i"))


class Delay(AtomicComponent):
    NAME = "t.Delay"
    IN_PORTS = ("i",)
    OUT_PORTS = ("o",)
    PORT_TYPES = {"i": OnOff, "o": OnOff}
    BEHAVIOR = DelayBehavior


class EchoBehavior(Behavior):
    """Event-driven: every message is echoed at once, twice."""

    TIMING = "timed"
    IN_PORTS = ("i",)
    OUT_PORTS = ("o",)

    def on_message(self, port: str, value: object) -> None:
        self._emit("o", value)
        self._emit("o", value)


class Echo(AtomicComponent):
    NAME = "t.Echo"
    IN_PORTS = ("i",)
    OUT_PORTS = ("o",)
    PORT_TYPES = {"i": "long", "o": "long"}
    BEHAVIOR = EchoBehavior


class Chain(ComposedComponent):
    NAME = "t.Chain"
    IN_PORTS = ("i",)
    OUT_PORTS = ("o", "unused")
    PORT_TYPES = {"i": OnOff, "o": OnOff, "unused": "int"}
    CONNECTORS = (("", "i", (("a", "i"),)), ("a", "o", (("b", "i"),)), ("b", "o", (("", "o"),)))

    @classmethod
    def subcomponents(cls, params: Mapping[str, object]) -> list[tuple[str, type[ComponentType], dict[str, object]]]:
        return [("a", Delay, {}), ("b", Delay, {})]


def test_delayed_sync_component() -> None:
    system = System(Delay)
    system.init()
    system.receive("i", OnOff.ON)
    system.receive("i", TICK)
    system.run()
    assert system.outputs["o"] == [OnOff.OFF, TICK, OnOff.ON, TICK]


def test_event_component_writes_twice_per_message() -> None:
    out = run_streams(Echo, {"inputs": {"i": [{"msg": 5, "type": "long"}, {"tick": True}]}})
    assert out["outputs"]["o"] == [{"msg": 5, "type": "long"}, {"msg": 5, "type": "long"}, {"tick": True}]


def test_composition_delays_twice_and_ticks_undriven_ports() -> None:
    system = System(Chain)
    system.init()
    for item in (OnOff.ON, TICK, TICK):
        system.receive("i", item)
    system.run()
    assert system.outputs["o"] == [OnOff.OFF, TICK, OnOff.OFF, TICK, OnOff.ON, TICK]
    assert system.outputs["unused"] == [TICK, TICK]


def test_stream_items_keep_java_types() -> None:
    assert encode_item(1.5, "float") == {"msg": 1.5, "type": "float"}
    assert encode_item(decode_item({"msg": 0.1, "type": "float"}), "float") == {"msg": 0.1, "type": "float"}
    assert encode_item(float("inf"), "double") == {"msg": "Infinity", "type": "double"}
    assert encode_item(OnOff.ON) == {"msg": {"enum": "OnOff", "literal": "ON"}}
    assert decode_item({"msg": {"enum": "OnOff", "literal": "OFF"}}, OnOff) is OnOff.OFF
    assert decode_item({"tick": True}) is TICK


def test_stream_test_files(tmp_path: Path) -> None:
    app = tmp_path / "maa_app.py"
    app.write_text(
        "from test_timesync_rte import Delay, OnOff\nCOMPONENTS = {'t.Delay': Delay}\nENUMS = {'OnOff': OnOff}\n",
        encoding="utf-8",
    )
    stream = tmp_path / "Delay.stream"
    stream.write_text(
        "component t.Delay;\n"
        'test "delays" { i = ON Tk OFF Tk; o == OFF Tk ON Tk OFF Tk; }\n'
        'test "values only" { i = ON Tk; o ~= OFF ON; }\n'
        'test "wrong" { i = ON Tk; o == OnOff.ON Tk; }\n',
        encoding="utf-8",
    )
    import sys

    sys.path.insert(0, str(Path(__file__).parent))
    results = run_files(tmp_path, [stream])
    assert [r["passed"] for r in results] == [True, True, False]
    assert results[2]["problems"] == ["o: expected ON Tk; got OFF Tk ON Tk"]


def test_stream_test_syntax_errors() -> None:
    with pytest.raises(StreamTestError):
        parse('component a.B;\ntest "x" { i = 1 Tk }', "x.stream")
    parsed = parse('component a.B(p = 3, q = X.Y);\ntest "t" { i = 1 2.5 "s" true Tk; ticks 3; state == S; }')
    assert parsed.params == {"p": 3, "q": parsed.params["q"]}
    assert parsed.tests[0].inputs["i"] == [1, 2.5, "s", True, TICK]
    assert parsed.tests[0].ticks == 3 and parsed.tests[0].state == "S"


class SensorBehavior(Behavior):
    """A handwritten platform component: reads a simulator topic, publishes a command."""

    OUT_PORTS = ("value",)

    def step(self, inputs: Mapping[str, object]) -> None:
        msg = platform().latest("/sensors/distance")
        if msg is not None:
            self._emit("value", msg["data"])
            platform().publish("/toaster/command", {"data": "START" if msg["data"] < 100 else "STOP"})


class Sensor(AtomicComponent):
    NAME = "t.Sensor"
    OUT_PORTS = ("value",)
    BEHAVIOR = SensorBehavior


def test_lockstep_controller_runs_one_slice_per_step() -> None:
    app = LockstepApp(Sensor, {})
    assert app.step({"/sensors/distance": {"data": 50}}) == {"/toaster/command": [{"data": "START"}]}
    assert app.step({"/sensors/distance": {"data": 500}}) == {"/toaster/command": [{"data": "STOP"}]}
    assert app.system.outputs["value"] == [50, TICK, 500, TICK]
    app.reset()
    assert app.step({}) == {}  # a reset forgets the simulator messages
