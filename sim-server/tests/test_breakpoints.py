"""Breakpoints of a lock-step run (maa_sim.breakpoints, `/sim/set_breakpoints`) with the generated example.

The ToastServiceRobot is generated for python-timesync at test time (as in
test_generated_lockstep.py); its Controller's automaton goes Idle -> Loading -> Toasting ->
Serving -> Idle. The build reports its transitions on `/maa/transitions` and its RobotArm
statements on `/maa/program_steps`; a breakpoint on `Toasting -> Serving` pauses the run after the
period of that transition, with Serving active.
"""

from __future__ import annotations

import json
from collections.abc import Iterator
from pathlib import Path
from typing import Any

import pytest
from conftest import TOAST_APP
from rosbridge_client import Client
from test_generated_lockstep import MODES_APP as MODES_MODEL
from test_generated_lockstep import TOAST_APP as TOAST_MODEL
from test_generated_lockstep import generate, lockstep_app

from maa_sim.app import SimApp
from maa_sim.breakpoints import check_request, reached, unresolved, within

CTRL = "/toast_service_robot/ctrl"
TRANSITIONS = "/maa/transitions"
PROGRAM_STEPS = "/maa/program_steps"


# ----------------------------------------------------------------------------- matching


def test_a_state_name_covers_the_state_and_its_substates() -> None:
    assert within("Serving", "Serving")
    assert within("Outer.Inner", "Outer") and within("Outer.Inner", "Inner") and within("A.B.C", "B.C")
    assert not within("Serving", "Serv") and not within("Outer.Inner", "Inner.Outer") and not within("", "Idle")


def test_a_transition_breakpoint_is_reached_by_its_transition_only() -> None:
    bp: Any = {"node": CTRL, "from": "Toasting", "to": "Serving"}
    assert reached(bp, {"node": CTRL, "from": "Toasting", "to": "Serving", "index": 2})
    assert not reached(bp, {"node": CTRL, "from": "Loading", "to": "Toasting", "index": 1})
    assert not reached(bp, {"node": "/other", "from": "Toasting", "to": "Serving", "index": 2})


def test_a_state_breakpoint_is_reached_when_the_state_is_entered_from_outside() -> None:
    bp: Any = {"node": CTRL, "state": "On"}
    assert reached(bp, {"node": CTRL, "from": "Off", "to": "On", "index": 1})
    assert not reached(bp, {"node": CTRL, "from": "On", "to": "On", "index": 0})  # stays in On
    assert not reached(bp, {"node": CTRL, "from": "On", "to": "Off", "index": 2})


def test_requests_are_checked_against_the_contract() -> None:
    good = {"breakpoints": [{"node": CTRL, "state": "Serving"}, {"node": CTRL, "from": "Toasting", "to": "Serving"}]}
    assert check_request(good) == good["breakpoints"]
    assert check_request({"breakpoints": []}) == []
    for bad in (
        {},
        {"breakpoints": "Serving"},
        {"breakpoints": [{"node": CTRL}]},
        {"breakpoints": [{"node": "ctrl", "state": "Serving"}]},  # not a node path
        {"breakpoints": [{"node": CTRL, "from": "Toasting"}]},
        {"breakpoints": [{"node": CTRL, "state": ""}]},
    ):
        with pytest.raises(ValueError, match="/sim/set_breakpoints"):
            check_request(bad)


#: the automata table entry of the modes fixture's root (gear.Gearbox, a mode automaton), as generated
GEARBOX_ENTRY: dict[str, Any] = {
    "instancePath": "",
    "node": "/gearbox",
    "component": "gear.Gearbox",
    "file": "gear/Gearbox.arc",
    "states": [{"path": "First", "line": 10}, {"path": "Second", "line": 15}],
    "transitions": [
        {"index": 0, "from": "First", "to": "Second", "label": "[speed < 0]", "line": 22, "column": 5},
        {"index": 1, "from": "Second", "to": "First", "label": "[speed == 0]", "line": 23, "column": 5},
    ],
    "kind": "modes",
}


def test_breakpoints_resolve_against_the_automata_table() -> None:
    table = [GEARBOX_ENTRY]
    good: list[Any] = [
        {"node": "/gearbox", "state": "Second"},
        {"node": "/gearbox", "from": "Second", "to": "First"},
        {"node": "/elsewhere", "state": "Anything"},  # no entry: the node check of the service decides
    ]
    assert unresolved(good, table) == []
    bad: list[Any] = [{"node": "/gearbox", "state": "Third"}, {"node": "/gearbox", "from": "First", "to": "Fifth"}]
    assert unresolved(bad, table) == [
        "no mode 'Third' in the automaton of /gearbox (First, Second)",
        "no mode 'Fifth' in the automaton of /gearbox (First, Second)",
    ]
    # an automaton's entry (no kind) names its states
    ctrl = {**GEARBOX_ENTRY, "node": CTRL, "states": [{"path": "Idle", "line": 5}], "kind": None}
    assert unresolved([{"node": CTRL, "state": "Serving"}], [ctrl]) == [
        f"no state 'Serving' in the automaton of {CTRL} (Idle)"
    ]


# ----------------------------------------------------------------------------- a run


@pytest.fixture(scope="module")
def toast_build(tmp_path_factory: pytest.TempPathFactory) -> Path:
    return Path(generate(TOAST_MODEL, tmp_path_factory.mktemp("toast-breakpoints")))


@pytest.fixture
def toast_app(toast_build: Path) -> Iterator[SimApp]:
    app = lockstep_app(toast_build, max_sim_time=60.0, speed=0.0)
    app.start()
    yield app
    app.stop()


def events(client: Client, topic: str, until: Any) -> list[dict[str, Any]]:
    """The `data` of every message of `topic` up to the first for which `until` holds."""
    found: list[dict[str, Any]] = []
    while True:
        m = client.recv_until(lambda m: m.get("op") == "publish" and m.get("topic") == topic, timeout=120)
        found.append(json.loads(m["msg"]["data"]))
        if until(found[-1]):
            return found


def test_a_transition_breakpoint_pauses_the_run_with_its_target_active(toast_app: SimApp) -> None:
    assert toast_app.rosbridge is not None
    control, watch = Client.of(toast_app.rosbridge), Client.of(toast_app.rosbridge)
    try:
        watch.send({"op": "subscribe", "topic": TRANSITIONS, "type": "std_msgs/msg/String"})
        bad = control.call("/sim/set_breakpoints", {"breakpoints": [{"node": CTRL, "from": "Toasting"}]})
        assert bad["result"] is False and "/sim/set_breakpoints" in str(bad["values"]), bad
        stranger = control.call(
            "/sim/set_breakpoints", {"breakpoints": [{"node": "/toast_service_robot/x", "state": "A"}]}
        )
        assert stranger["result"] is False and "no automaton runs on /toast_service_robot/x" in str(stranger["values"])
        answer = control.call(
            "/sim/set_breakpoints", {"breakpoints": [{"node": CTRL, "from": "Toasting", "to": "Serving"}]}
        )
        assert answer["result"] is True, answer
        watch.call("/sim/get_status")  # its subscription is in place once the endpoint answers its next call
        assert control.call("/sim/resume")["result"] is True
        taken = events(watch, TRANSITIONS, lambda e: e["node"] == CTRL and e["to"] == "Serving")
        ctrl = [(e["from"], e["to"], e["index"]) for e in taken if e["node"] == CTRL]
        assert ctrl == [("Idle", "Loading", 0), ("Loading", "Toasting", 1), ("Toasting", "Serving", 2)]
        status = control.call("/sim/get_status")["values"]
        assert status["paused"] is True
        assert status["breakpoint"] == {"node": CTRL, "from": "Toasting", "to": "Serving"}
        assert status["automaton_states"][CTRL] == "Serving"
        # paused for good: no period runs until the client says so
        assert control.call("/sim/get_status")["values"]["periods"] == status["periods"]
        # a step goes on (one period) and the status no longer names the breakpoint
        assert control.call("/sim/step", {"steps": 1})["result"] is True
        after = control.call("/sim/get_status")["values"]
        assert after["breakpoint"] is None and after["periods"] == status["periods"] + 1
    finally:
        control.close()
        watch.close()


def test_a_state_breakpoint_pauses_when_the_state_is_entered(toast_app: SimApp) -> None:
    assert toast_app.rosbridge is not None
    control, watch = Client.of(toast_app.rosbridge), Client.of(toast_app.rosbridge)
    try:
        for topic in (PROGRAM_STEPS, TRANSITIONS):
            watch.send({"op": "subscribe", "topic": topic, "type": "std_msgs/msg/String"})
        assert control.call("/sim/set_breakpoints", {"breakpoints": [{"node": CTRL, "state": "Toasting"}]})["result"]
        watch.call("/sim/get_status")
        assert control.call("/sim/resume")["result"] is True
        steps: list[dict[str, Any]] = []
        while True:  # LoadBread runs in Loading; its DONE takes the Controller to Toasting
            m = watch.recv_until(lambda m: m.get("op") == "publish", timeout=120)
            data = json.loads(m["msg"]["data"])
            if m["topic"] == PROGRAM_STEPS:
                steps.append(data)
            elif data["node"] == CTRL and data["to"] == "Toasting":
                break
        assert steps[0] == {
            "node": "/toast_service_robot/arm",
            "program": "LoadBread",
            "step": 0,
            "line": 22,
            "text": "move top;",
            "file": "toast/ArmController.arc",
        }
        assert [s["step"] for s in steps] == list(range(10))
        assert steps[6]["line"] == 23 and steps[6]["text"] == "move aboveToaster;"
        status = control.call("/sim/get_status")["values"]
        assert status["paused"] is True and status["breakpoint"] == {"node": CTRL, "state": "Toasting"}
        assert status["automaton_states"][CTRL] == "Toasting"
        # cleared: the run goes on to its end without stopping again
        assert control.call("/sim/set_breakpoints", {"breakpoints": []})["result"] is True
        assert control.call("/sim/resume")["result"] is True
        assert toast_app.wait(timeout=300)
        assert toast_app.status()["breakpoint"] is None
    finally:
        control.close()
        watch.close()


def test_a_controller_without_transitions_has_no_breakpoints() -> None:
    app = lockstep_app(TOAST_APP)
    app.start()
    try:
        assert app.rosbridge is not None
        client = Client.of(app.rosbridge)
        answer = client.call("/sim/set_breakpoints", {"breakpoints": [{"node": CTRL, "state": "Serving"}]})
        assert answer["result"] is False and "lock-step" in str(answer["values"])
        assert client.call("/sim/get_status")["values"]["breakpoint"] is None
        client.close()
    finally:
        app.stop()


# ----------------------------------------------------------------------------- modes


@pytest.fixture(scope="module")
def modes_build(tmp_path_factory: pytest.TempPathFactory) -> Path:
    return Path(generate(MODES_MODEL, tmp_path_factory.mktemp("modes-breakpoints")))


def test_mode_transitions_are_reported_and_a_mode_breakpoint_pauses_the_run(modes_build: Path) -> None:
    """gear.Gearbox (the root, node /gearbox) switches First -> Second on a negative speed and back
    on the next slice without one: its mode transitions arrive on /maa/transitions with their index
    in the automata table, and breakpoints on a mode and on a mode transition pause the run."""
    app = lockstep_app(modes_build, max_sim_time=60.0, speed=0.0)
    app.start()
    try:
        assert app.rosbridge is not None
        assert app.runner is not None
        table = app.runner.controller.automata()
        assert table == [GEARBOX_ENTRY]
        control, watch = Client.of(app.rosbridge), Client.of(app.rosbridge)
        try:
            watch.send({"op": "subscribe", "topic": TRANSITIONS, "type": "std_msgs/msg/String"})
            # a mode the automaton does not have: refused with the modes it has
            third = control.call("/sim/set_breakpoints", {"breakpoints": [{"node": "/gearbox", "state": "Third"}]})
            assert third["result"] is False
            assert "no mode 'Third' in the automaton of /gearbox (First, Second)" in str(third["values"]), third
            answer = control.call("/sim/set_breakpoints", {"breakpoints": [{"node": "/gearbox", "state": "Second"}]})
            assert answer["result"] is True, answer
            watch.call("/sim/get_status")  # its subscription is in place once the endpoint answers its next call
            control.send({"op": "advertise", "topic": "/gearbox/speed", "type": "std_msgs/msg/Int32"})
            control.send({"op": "publish", "topic": "/gearbox/speed", "msg": {"data": -1}})
            assert control.call("/sim/resume")["result"] is True
            taken = events(watch, TRANSITIONS, lambda e: e["to"] == "Second")
            assert taken == [{"node": "/gearbox", "from": "First", "to": "Second", "index": 0}]
            status = control.call("/sim/get_status")["values"]
            assert status["paused"] is True and status["breakpoint"] == {"node": "/gearbox", "state": "Second"}
            assert status["automaton_states"] == {"/gearbox": "Second"}
            # the next slice has no speed (Java's 0 in the guard): the transition back is taken and pauses
            back = {"node": "/gearbox", "from": "Second", "to": "First"}
            assert control.call("/sim/set_breakpoints", {"breakpoints": [back]})["result"] is True
            assert control.call("/sim/resume")["result"] is True
            taken = events(watch, TRANSITIONS, lambda e: e["to"] == "First")
            assert taken == [{**back, "index": 1}]
            status = control.call("/sim/get_status")["values"]
            assert status["paused"] is True and status["breakpoint"] == back
            assert status["automaton_states"] == {"/gearbox": "First"}
        finally:
            control.close()
            watch.close()
    finally:
        app.stop()
