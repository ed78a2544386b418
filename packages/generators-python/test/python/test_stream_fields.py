"""Tests of the stream-test fields of the montiarc-io format (``run_streams``), the Java lambdas of
value transforms (``maa_timesync.javalambda``) and the ``.stream`` statements that express them."""

from __future__ import annotations

import math
import re
import sys
from collections.abc import Mapping
from pathlib import Path

import pytest

from maa_behavior import Behavior
from maa_timesync import AtomicComponent, run_streams
from maa_timesync.javalambda import JValue, LambdaError, compile_lambda, item_transform
from maa_timesync.streams import bind_type_args, decode_value, encode_item
from maa_timesync.streamtest import StreamTestError, parse, run_files

TICK_ITEM = {"tick": True}


class RelayBehavior(Behavior):
    """Event-driven: forwards every message."""

    TIMING = "timed"
    IN_PORTS = ("i",)
    OUT_PORTS = ("o",)

    def on_message(self, port: str, value: object) -> None:
        self._emit("o", value)


class Relay(AtomicComponent):
    NAME = "t.Relay"
    IN_PORTS = ("i",)
    OUT_PORTS = ("o",)
    PORT_TYPES = {"i": "T", "o": "T"}
    TYPE_PARAMETERS = ("T",)
    BEHAVIOR = RelayBehavior


class ToggleBehavior(Behavior):
    """Off/On, switching on every message; sends the message on o."""

    TIMING = "timed"
    IN_PORTS = ("i",)
    OUT_PORTS = ("o",)

    def start(self) -> None:
        self.state = "Off"
        super().start()

    def current_state(self) -> str | None:
        return self.state

    def on_message(self, port: str, value: object) -> None:
        self.state = "On" if self.state == "Off" else "Off"
        self._emit("o", value)


class Toggle(AtomicComponent):
    NAME = "t.Toggle"
    IN_PORTS = ("i",)
    OUT_PORTS = ("o",)
    PORT_TYPES = {"i": "int", "o": "int"}
    BEHAVIOR = ToggleBehavior


class Letters(AtomicComponent):
    NAME = "t.Letters"
    IN_PORTS = ("i",)
    OUT_PORTS = ("o",)
    PORT_TYPES = {"i": "Character", "o": "Character"}
    BEHAVIOR = RelayBehavior


# -- run_streams ----------------------------------------------------------------------------------


def test_type_args_bind_the_ports_java_types() -> None:
    out = run_streams(Relay, {"type_args": ["Long"], "inputs": {"i": [{"msg": 5, "type": "long"}, TICK_ITEM]}})
    assert out["outputs"]["o"] == [{"msg": 5, "type": "long"}, TICK_ITEM]
    out = run_streams(Relay, {"type_args": {"T": "Float"}, "inputs": {"i": [{"msg": 0.1, "type": "float"}, TICK_ITEM]}})
    assert out["outputs"]["o"] == [{"msg": 0.1, "type": "float"}, TICK_ITEM]
    assert bind_type_args(Relay, ["Integer"]) == {"i": "Integer", "o": "Integer"}
    with pytest.raises(ValueError, match="1 type parameter"):
        bind_type_args(Relay, ["Integer", "Long"])
    with pytest.raises(ValueError, match="no type parameter U"):
        bind_type_args(Relay, {"U": "Integer"})


def test_observe_state_records_the_state_between_steps() -> None:
    steps = [
        {"op": "init"},
        {"op": "observe_state"},
        {"op": "receive", "port": "i", "count": 2},
        {"op": "run"},
        {"op": "observe_state"},
        {"op": "receive", "port": "i", "count": 2},
        {"op": "run"},
        {"op": "observe_state"},
    ]
    out = run_streams(Toggle, {"inputs": {"i": [{"msg": 1}, TICK_ITEM, {"msg": 2}, TICK_ITEM]}, "steps": steps})
    assert out["state_trace"] == ["Off", "On", "Off"]
    with pytest.raises(ValueError, match="unknown step"):
        run_streams(Toggle, {"inputs": {}, "steps": [{"op": "init"}, {"op": "peek"}]})


def test_in_port_buffer_empty_after_run() -> None:
    spec = {
        "type_args": ["Integer"],
        "inputs": {"i": [{"msg": 1}, TICK_ITEM]},
        "extra_assertions": [{"assert": "in_port_buffer_empty_after_run", "port": "i"}],
    }
    assert run_streams(Relay, spec)["assertions"] == [
        {"assert": "in_port_buffer_empty_after_run", "port": "i", "holds": True, "detail": None}
    ]
    not_run = dict(spec, steps=[{"op": "init"}, {"op": "receive", "port": "i", "count": 2}])
    (check,) = run_streams(Relay, not_run)["assertions"]
    assert not check["holds"] and "2 item(s) left buffered on i" in check["detail"]
    with pytest.raises(ValueError, match="unknown extra assertion"):
        run_streams(Relay, dict(spec, extra_assertions=[{"assert": "no_such_check", "port": "i"}]))
    with pytest.raises(ValueError, match="no in port 'o'"):
        run_streams(Relay, dict(spec, extra_assertions=[{"assert": "in_port_buffer_empty_after_run", "port": "o"}]))


def test_observed_value_transform() -> None:
    spec = {
        "type_args": ["Integer"],
        "inputs": {"i": [{"msg": 97}, TICK_ITEM]},
        "observed_value_transform": {"o": "c -> (char) c.intValue()"},
    }
    assert run_streams(Relay, spec)["outputs"]["o"] == [{"char": "a"}, TICK_ITEM]
    with pytest.raises(ValueError, match="no observed port 'x'"):
        run_streams(Relay, dict(spec, observed_value_transform={"x": "c -> c"}))


def test_character_ports_carry_characters() -> None:
    out = run_streams(Letters, {"inputs": {"i": [{"char": "z"}, {"msg": 65}, TICK_ITEM]}})
    assert out["outputs"]["o"] == [{"char": "z"}, {"char": "A"}, TICK_ITEM]
    assert encode_item(ord("q"), "char") == {"char": "q"}


def test_map_and_object_values() -> None:
    assert decode_value({"map": [["a", 1], ["b", {"map": [[1, True]]}]]}) == {"a": 1, "b": {1: True}}
    assert encode_item({"k": 2}) == {"msg": {"map": [["k", 2]]}}
    with pytest.raises(ValueError, match="unknown data type NoSuchType"):
        decode_value({"object": "NoSuchType", "fields": {}})


# -- Java lambdas -----------------------------------------------------------------------------------


@pytest.mark.parametrize(
    ("lam", "item", "port_type", "want"),
    [
        ("c -> (char) c.intValue()", {"msg": 97}, "Integer", {"char": "a"}),
        ("c -> (int) c.charValue()", {"char": "a"}, "Character", {"msg": 97}),
        ("(Integer x) -> x.longValue() * 3", {"msg": 7}, None, {"msg": 21, "type": "long"}),
        ("x -> (byte) x", {"msg": 200}, None, {"msg": -56, "type": "byte"}),
        ("x -> (short) (x + 1)", {"msg": 32767}, None, {"msg": -32768, "type": "short"}),
        ("x -> x + 1", {"msg": 2147483647}, None, {"msg": -2147483648}),
        ("x -> x / 2", {"msg": -7}, None, {"msg": -3}),
        ("x -> x % 3", {"msg": -7}, None, {"msg": -1}),
        ("x -> (int) x", {"msg": -2.9, "type": "double"}, None, {"msg": -2}),
        ("x -> (int) x", {"msg": "NaN", "type": "double"}, None, {"msg": 0}),
        ("x -> (long) x", {"msg": 1e30, "type": "float"}, None, {"msg": 2**63 - 1, "type": "long"}),
        ("x -> x.floatValue() / 3", {"msg": 1}, None, {"msg": 0.3333333432674408, "type": "float"}),
        ("x -> x.doubleValue() / 0", {"msg": -1}, None, {"msg": "-Infinity", "type": "double"}),
        ('x -> "n=" + x', {"msg": 3, "type": "long"}, None, {"msg": "n=3"}),
        ('x -> x + "!"', {"char": "c"}, None, {"msg": "c!"}),
        ("x -> x > 2 ? 'y' : 'n'", {"msg": 3}, None, {"char": "y"}),
        ("x -> !(x == 1) && x != 2", {"msg": 3}, None, {"msg": True}),
        ("x -> x.name()", {"msg": {"enum": "OnOff", "literal": "ON"}}, None, {"msg": "ON"}),
        ("x -> x.length()", {"msg": "four"}, None, {"msg": 4}),
        ("x -> Character.valueOf((char) (x + 1))", {"msg": 64}, None, {"char": "A"}),
        ("x -> String.valueOf(x)", {"msg": 1.5, "type": "float"}, None, {"msg": "1.5"}),
        ("x -> Math.abs(x)", {"msg": -4, "type": "long"}, None, {"msg": 4, "type": "long"}),
        ("x -> -x", {"msg": 5, "type": "short"}, None, {"msg": -5}),
        ("x -> x", {"msg": 97}, "char", {"char": "a"}),
    ],
)
def test_java_lambdas(lam: str, item: Mapping[str, object], port_type: str | None, want: Mapping[str, object]) -> None:
    assert item_transform(lam, port_type)(item) == want
    assert item_transform(lam, port_type)(TICK_ITEM) == TICK_ITEM


@pytest.mark.parametrize(
    ("lam", "error"),
    [
        ("x -> y + 1", "unknown name y"),
        ("x -> x.hashCode()", "unsupported method hashCode"),
        ("x -> Objects.hash(x)", "unsupported method"),
        ("(Widget w) -> w", "unsupported parameter type Widget"),
        ("x -> (x", "expected )"),
        ("x -> x +", "unexpected"),
        ("x => x", "unexpected"),
        ("x -> 99999999999", "out of range"),
        ("x -> x # 1", "unexpected"),
    ],
)
def test_lambdas_outside_the_subset_are_refused_when_compiled(lam: str, error: str) -> None:
    with pytest.raises(LambdaError, match=re.escape(error)):
        compile_lambda(lam)  # the message names the problem


def test_lambda_errors_on_values() -> None:
    with pytest.raises(LambdaError, match="/ by zero"):
        compile_lambda("x -> x / 0")(JValue("int", 1))
    with pytest.raises(LambdaError, match="boolean has no method intValue"):
        compile_lambda("x -> x.intValue()")(JValue("boolean", True))
    assert math.isnan(compile_lambda("x -> x % 0.0")(JValue("double", 1.0)).value)


# -- .stream files ----------------------------------------------------------------------------------


def _app(tmp_path: Path) -> None:
    (tmp_path / "maa_app.py").write_text(
        "from test_stream_fields import Letters, Relay, Toggle\n"
        "COMPONENTS = {'t.Relay': Relay, 't.Toggle': Toggle, 't.Letters': Letters}\nENUMS = {}\n",
        encoding="utf-8",
    )
    if str(Path(__file__).parent) not in sys.path:
        sys.path.insert(0, str(Path(__file__).parent))
    sys.modules.pop("maa_app", None)


def _run(tmp_path: Path, text: str) -> list[dict[str, object]]:
    _app(tmp_path)
    stream = tmp_path / "t.stream"
    stream.write_text(text, encoding="utf-8")
    try:
        return run_files(tmp_path, [stream])
    finally:
        # Other tests import their own maa_app.
        sys.modules.pop("maa_app", None)
        sys.path.remove(str(tmp_path))


def test_stream_steps_states_transforms_and_empty_ports(tmp_path: Path) -> None:
    results = _run(
        tmp_path,
        (
            "component t.Toggle;\n"
            'test "steps in order" {\n'
            "  state == Off;\n"
            "  i = 97 Tk;\n"
            "  run;\n"
            "  state == On;\n"
            "  i = 98 Tk;\n"
            "  run 1;\n"
            "  state == Off;\n"
            "  transform o = c -> (char) c.intValue();\n"
            "  o == 'a' Tk 'b' Tk;\n"
            "  empty i;\n"
            "}\n"
            'test "a state between the steps differs" { i = 1 Tk; run; state == Off; o == 1 Tk; }\n'
            'test "a transformed value keeps its type" { i = 97 Tk; transform o = c -> (char) c.intValue(); o == 97 Tk; }\n'
            'test "left buffered" { i = 1 Tk; empty i; run 0; }\n'
        ),
    )
    assert [(r["test"], r["passed"]) for r in results] == [
        ("steps in order", True),
        ("a state between the steps differs", False),
        ("a transformed value keeps its type", False),
        ("left buffered", False),
    ]
    assert [r["line"] for r in results] == [2, 14, 15, 16]  # the line of `test`, not of the blanks before it
    assert results[1]["problems"] == ["state (line 14): expected Off; got On"]
    assert results[2]["problems"] == ["o: expected 97 Tk; got 'a' Tk"]
    assert results[3]["problems"] == ["empty i: 1 item(s) left buffered: Tk"]


def test_stream_generic_components_and_typed_literals(tmp_path: Path) -> None:
    results = _run(
        tmp_path,
        (
            "component t.Relay<Long>;\n"
            'test "long" { i = 5 Tk; o == 5 Tk; transform o = x -> x * 2; }\n'
            'test "typed literals" { i = 5 Tk; transform o = x -> x * 2; o == 10L Tk; }\n'
            'test "an int is not a long" { i = 5 Tk; transform o = x -> x; o == 5 Tk; }\n'
        ),
    )
    assert [r["passed"] for r in results] == [False, True, False]
    assert results[0]["problems"] == ["o: expected 5 Tk; got 10L Tk"]
    assert results[2]["problems"] == ["o: expected 5 Tk; got 5L Tk"]
    generic = _run(tmp_path, 'component t.Relay;\ntest "x" { i = 1 Tk; o == 1 Tk; }\n')
    assert not generic[0]["passed"] and "is generic: give its type arguments" in generic[0]["problems"][0]
    too_many = _run(tmp_path, 'component t.Relay<Long, Integer>;\ntest "x" { i = 1 Tk; o == 1 Tk; }\n')
    assert "1 type parameter(s)" in too_many[0]["problems"][0]


def test_stream_characters(tmp_path: Path) -> None:
    results = _run(tmp_path, "component t.Letters;\ntest \"chars\" { i = 'x' '\\n' Tk; o == 'x' '\\n' Tk; }\n")
    assert results[0]["passed"], results[0]["problems"]


def test_stream_feature_configurations(tmp_path: Path) -> None:
    results = _run(tmp_path, 'component t.Toggle features (fast = true);\ntest "x" { i = 1 Tk; o == 1 Tk; }\n')
    assert results[0]["problems"] == [f"{tmp_path / 't.stream'}: the build of t.Toggle does not record a feature configuration"]
    Toggle.FEATURES = {"fast": False}  # type: ignore[attr-defined]
    try:
        results = _run(tmp_path, 'component t.Toggle features (fast = true);\ntest "x" { i = 1 Tk; o == 1 Tk; }\n')
        assert "has another feature configuration than {'fast': True}" in results[0]["problems"][0]
        results = _run(tmp_path, 'component t.Toggle features (fast = false);\ntest "x" { i = 1 Tk; o == 1 Tk; }\n')
        assert results[0]["passed"], results[0]["problems"]
    finally:
        del Toggle.FEATURES  # type: ignore[attr-defined]


def test_stream_checks(tmp_path: Path) -> None:
    results = _run(tmp_path, ('component t.Toggle;\ntest "unknown ports" { i = 1 Tk; transform x = c -> c; empty o; }\n'))
    assert results[0]["problems"] == ["transform: t.Toggle has no out port 'x'", "empty: t.Toggle has no in port 'o'"]


def test_stream_syntax() -> None:
    parsed = parse(
        "component a.B<Integer, String>(p = 1) features (f = true, g = false);\n"
        "test \"t\" { run = 1 Tk; empty = 2; transform = 3; i = 4L 1.5f 'c'; run 2; empty i, run; }"
    )
    assert parsed.type_args == ["Integer", "String"] and parsed.features == {"f": True, "g": False}
    test = parsed.tests[0]
    # `run`, `empty` and `transform` stay usable as port names.
    assert set(test.inputs) == {"run", "empty", "transform", "i"}
    assert test.sequenced and test.empty == ["i", "run"]
    with pytest.raises(StreamTestError, match="'ticks' and 'run' do not mix"):
        parse('component a.B;\ntest "t" { i = 1 Tk; ticks 2; run; }')
    with pytest.raises(StreamTestError, match="transform o: unsupported method foo"):
        parse('component a.B;\ntest "t" { transform o = x -> x.foo(); }')
    with pytest.raises(StreamTestError, match="must be true or false"):
        parse('component a.B features (f = 1);\ntest "t" { }')
    with pytest.raises(StreamTestError, match="'run' takes a number"):
        parse('component a.B;\ntest "t" { run 1.5; }')


def test_the_state_of_a_mode_automaton_is_its_mode() -> None:
    from maa_timesync import ComposedComponent, System
    from maa_timesync.streams import current_state

    class Wrapper(ComposedComponent):
        NAME = "t.Wrapper"
        IN_PORTS = ("i",)
        OUT_PORTS = ("o",)
        PORT_TYPES = {"i": "int", "o": "int"}
        CONNECTORS = (("", "i", (("", "o"),)),)

    system = System(Wrapper, {})
    assert current_state(system) is None
    system.top.mode = "Doubled"  # type: ignore[attr-defined]  # what maa_timesync.modes.ModeInstance keeps
    assert current_state(system) == "Doubled"
    toggle = System(Toggle, {})
    toggle.init()
    assert current_state(toggle) == "Off"
