"""State traces of stream tests (``python -m maa_timesync.streamtest BUILD --states OUT.json FILE...``,
format ``maa-stream-states/1``): the state path of the component under test before the first tick and
after every tick, for automaton coverage; nothing for a component without an automaton."""

from __future__ import annotations

import json
import os
import subprocess
import sys
from collections.abc import Mapping
from pathlib import Path
from typing import Any

from maa_behavior import Behavior
from maa_timesync import AtomicComponent, System
from maa_timesync.streamtest import parse, run_test, state_path

TEST = Path(__file__).resolve().parents[1]
RTE = TEST.parent / "rte"
REPO = TEST.parents[2]
TOAST_BUILD = TEST / "golden" / "toast-service"
TOAST_MODELS = REPO / "examples" / "toast-service" / "toast"
MODES_BUILD = TEST / "golden" / "modes"
GEARBOX_STREAM = TEST / "fixtures" / "modes" / "gear" / "Gearbox.stream"


class LampBehavior(Behavior):
    """Event-driven hierarchical automaton: Off -> On.Dim -> On.Bright -> Off, one step per message."""

    TIMING = "timed"
    IN_PORTS = ("i",)
    OUT_PORTS = ("o",)
    _PARENT: Mapping[str, str | None] = {"Off": None, "On": None, "Dim": "On", "Bright": "On"}
    _NEXT = {"Off": "Dim", "Dim": "Bright", "Bright": "Off"}

    def start(self) -> None:
        self.state = "Off"
        super().start()

    def current_state(self) -> str | None:
        return self.state

    def on_message(self, port: str, value: object) -> None:
        self.state = self._NEXT[self.state]
        self._emit("o", value)


class Lamp(AtomicComponent):
    NAME = "t.Lamp"
    IN_PORTS = ("i",)
    OUT_PORTS = ("o",)
    PORT_TYPES = {"i": "int", "o": "int"}
    BEHAVIOR = LampBehavior


class PlainBehavior(Behavior):
    """No automaton: forwards every message."""

    TIMING = "timed"
    IN_PORTS = ("i",)
    OUT_PORTS = ("o",)

    def on_message(self, port: str, value: object) -> None:
        self._emit("o", value)


class Plain(AtomicComponent):
    NAME = "t.Plain"
    IN_PORTS = ("i",)
    OUT_PORTS = ("o",)
    PORT_TYPES = {"i": "int", "o": "int"}
    BEHAVIOR = PlainBehavior


def streamtest(build: Path, *args: str) -> subprocess.CompletedProcess[str]:
    env = {**os.environ, "PYTHONPATH": str(RTE)}
    return subprocess.run(
        [sys.executable, "-m", "maa_timesync.streamtest", str(build), *args],
        capture_output=True,
        text=True,
        check=False,
        timeout=120,
        env=env,
    )


def traces(path: Path) -> dict[str, Any]:
    data: dict[str, Any] = json.loads(path.read_text(encoding="utf-8"))
    assert data["format"] == "maa-stream-states/1"
    return data


def test_an_event_driven_automaton_traces_ticks_and_changes() -> None:
    test = parse('component t.Lamp;\ntest "x" { i = 1 2 Tk 3 Tk; }').tests[0]
    trace: list[str] = []
    assert run_test(Lamp, {}, test, {}, None, trace) == []
    # every message changes the state (an entry each), every tick is an entry
    assert trace == ["Off", "On.Dim", "On.Bright", "On.Bright", "Off", "Off"]


def test_a_component_without_an_automaton_has_no_trace() -> None:
    test = parse('component t.Plain;\ntest "x" { i = 1 Tk 2 Tk; o == 1 Tk 2 Tk; }').tests[0]
    trace: list[str] = []
    assert run_test(Plain, {}, test, {}, None, trace) == []
    assert trace == []
    system = System(Plain)
    system.init()
    assert state_path(system) is None


def test_the_toast_example_traces_its_automata(tmp_path: Path) -> None:
    out = tmp_path / "states.json"
    files = [str(TOAST_MODELS / f"{name}.stream") for name in ("Controller", "ArmController", "ToasterController")]
    result = streamtest(TOAST_BUILD, "--json", "--states", str(out), *files)
    assert result.returncode == 0, result.stdout + result.stderr
    assert all(r["passed"] for r in json.loads(result.stdout))
    tests = traces(out)["tests"]
    by_name = {t["test"]: t for t in tests}
    loading = by_name["a plate starts loading the bread"]
    assert loading["component"] == "toast.Controller" and loading["line"] == 15
    assert loading["file"] == files[0]
    assert loading["states"] == ["Idle", "Idle", "Loading"]  # before the first tick, after each of the two
    whole = by_name["the states of a whole service, slice by slice"]
    assert whole["states"] == ["Idle", "Loading", "Loading", "Toasting", "Toasting", "Serving", "Idle"]
    # the ArmController runs RobotArm programs, no automaton: no trace of its tests
    assert {t["component"] for t in tests} == {"toast.Controller", "toast.ToasterController"}
    assert len(tests) == 9


def test_a_mode_automaton_traces_its_modes(tmp_path: Path) -> None:
    out = tmp_path / "deep" / "states.json"
    out.parent.mkdir()
    result = streamtest(MODES_BUILD, "--states", str(out), str(GEARBOX_STREAM))
    assert result.returncode == 0, result.stdout + result.stderr
    states = [t["states"] for t in traces(out)["tests"]]
    assert states[1] == ["First", "First", "Second", "Second", "First", "First", "Second"]
    assert [p.name for p in out.parent.iterdir()] == ["states.json"]  # no temporary file left


def test_states_option_errors(tmp_path: Path) -> None:
    result = streamtest(TOAST_BUILD, "--states")
    assert result.returncode == 2 and "--states needs a file name" in result.stderr
    result = streamtest(TOAST_BUILD, "--states", str(tmp_path / "missing" / "states.json"), str(TOAST_MODELS / "Controller.stream"))
    assert result.returncode == 2 and "cannot write the state traces" in result.stderr
