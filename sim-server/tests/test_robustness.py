"""A simulation outlives bad input: an injected message the application fails on, and a long step
that must not hold the endpoint for everyone."""

from __future__ import annotations

import textwrap
from collections.abc import Iterator, Mapping
from pathlib import Path
from typing import Any

import pytest
from rosbridge_client import Client

from maa_sim.app import RunOptions, SimApp
from maa_sim.lockstep import OutputValue
from maa_sim.messages import JsonMessage
from maa_sim.runs import lockstep_session

PICKY_TOPIC = "/picky/in"


class Picky:
    """A controller that fails (after changing its state) on a message it cannot parse."""

    def __init__(self) -> None:
        self.seen: list[int] = []
        self.slices = 0
        self.broken = False  # True: fails in every slice, with or without injected messages

    def topics(self) -> dict[str, str]:
        return {PICKY_TOPIC: "std_msgs/msg/String"}

    def step(self, inputs: Mapping[str, JsonMessage]) -> Mapping[str, OutputValue]:
        self.slices += 1
        if self.broken:
            raise KeyError("missing")
        message = inputs.get(PICKY_TOPIC)
        if message is not None:
            self.seen.append(-1)  # a change the failure below must not leave behind
            self.seen[-1] = int(message["data"])  # ValueError on "oops"
        return {}


def test_a_slice_that_fails_on_an_injected_message_is_rolled_back_and_run_without_it() -> None:
    controller = Picky()
    session, runner = lockstep_session(controller)
    events: list[str] = []
    session.event_listeners.append(lambda event: events.append(f"{event.level}: {event.message}"))
    runner.inject(PICKY_TOPIC, {"data": "oops"})
    runner.cycle()
    assert controller.seen == [] and controller.slices == 1  # rolled back, then the slice without it
    assert session.periods == 1 and not runner.finished.is_set()
    assert len(events) == 1 and events[0].startswith("error: the application failed on the message injected")
    assert PICKY_TOPIC in events[0] and "ValueError" in events[0]
    runner.inject(PICKY_TOPIC, {"data": "7"})
    runner.cycle()
    assert controller.seen == [7] and len(events) == 1
    # the application's own failure (no injected message) still ends the run, as before
    controller.broken = True
    with pytest.raises(KeyError):
        runner.cycle()


@pytest.fixture
def picky_app(tmp_path: Path) -> Iterator[SimApp]:
    (tmp_path / "picky_ctrl.py").write_text(
        textwrap.dedent(
            f"""
            from typing import Any


            class Picky:
                def __init__(self) -> None:
                    self.seen: list[int] = []

                def topics(self) -> dict[str, str]:
                    return {{"{PICKY_TOPIC}": "std_msgs/msg/String"}}

                def step(self, inputs: dict[str, Any]) -> dict[str, Any]:
                    message = inputs.get("{PICKY_TOPIC}")
                    if message is not None:
                        self.seen.append(int(message["data"]))
                    return {{}}


            def create(_parameters: Any) -> Picky:
                return Picky()
            """
        )
    )
    (tmp_path / "lockstep.json").write_text(
        '{"format": "maa-lockstep/1", "factory": "picky_ctrl:create", "python_path": ["."]}'
    )
    app = SimApp(RunOptions(package=tmp_path, mode="lockstep", speed=1.0, rosbridge_port=0, viser_port=None))
    app.start()
    yield app
    app.stop()


def test_an_injected_message_the_application_fails_on_gets_an_error_and_the_run_goes_on(picky_app: SimApp) -> None:
    assert picky_app.rosbridge is not None and picky_app.runner is not None
    client = Client.of(picky_app.rosbridge)
    try:
        client.send({"op": "publish", "id": "p1", "topic": PICKY_TOPIC, "msg": {"data": "oops"}})
        report = client.recv_until(lambda m: m.get("op") == "status", timeout=60)
        assert report["level"] == "error" and "injection" in report["msg"] and "ValueError" in report["msg"]
        client.send({"op": "publish", "id": "p2", "topic": PICKY_TOPIC, "msg": {"data": "42"}})
        controller: Any = picky_app.runner.controller
        client.call("/sim/pause", timeout=30)  # the injected 42 is in a slice or waits for the next
        assert client.call("/sim/step", {"steps": 2}, timeout=60)["result"] is True
        assert controller.seen == [42]
        assert not picky_app.runner.finished.is_set(), picky_app.runner.finish_reason
    finally:
        client.close()


@pytest.fixture
def lockstep_app(toast_app_dir: Path) -> Iterator[SimApp]:
    app = SimApp(
        RunOptions(package=toast_app_dir, mode="lockstep", speed=1.0, rosbridge_port=0, viser_port=None, paused=True)
    )
    app.start()
    yield app
    app.stop()


def test_a_long_step_leaves_the_endpoint_to_everyone_and_a_pause_stops_it(lockstep_app: SimApp) -> None:
    """/sim/step with the maximum (100000 periods, minutes on a slow machine) runs in the
    background: another client is answered while it is in flight, and its pause ends it."""
    assert lockstep_app.rosbridge is not None
    stepper, other = Client.of(lockstep_app.rosbridge), Client.of(lockstep_app.rosbridge)
    try:
        stepper.send({"op": "call_service", "id": "big", "service": "/sim/step", "args": {"steps": 100_000}})
        # wait (by asking) until the step is under way; each answer arrives while it is
        while (status := other.call("/sim/get_status", timeout=60)["values"])["stepping"] is None:
            assert status["periods"] == 0, "the step ended before another client was answered"
        assert status["stepping"][1] == 100_000
        assert "/clock" in other.call("rosapi/topics", timeout=60)["values"]["topics"]
        second = other.call("/sim/step", {"steps": 5}, timeout=60)  # one step at a time
        assert second["result"] is False and "in progress" in second["values"]
        paused = other.call("/sim/pause", timeout=60)
        assert paused["result"] is True
        reply = stepper.recv_until(lambda m: m.get("id") == "big", timeout=120)
        assert reply["result"] is True, reply
        done = reply["values"]["status"]["periods"]
        assert 0 < done < 100_000
        assert reply["values"]["message"] == f"stepped {done} of 100000 period(s); stopped by a pause"
        assert reply["values"]["status"]["stepping"] is None and reply["values"]["status"]["paused"] is True
        # no period after the pause answered, and stepping works again
        assert other.call("/sim/get_status", timeout=60)["values"]["periods"] == done
        assert other.call("/sim/step", {"steps": 3}, timeout=60)["values"]["status"]["periods"] == done + 3
    finally:
        stepper.close()
        other.close()


def test_a_reset_or_resume_also_stops_a_step(lockstep_app: SimApp) -> None:
    assert lockstep_app.rosbridge is not None and lockstep_app.runner is not None
    stepper, other = Client.of(lockstep_app.rosbridge), Client.of(lockstep_app.rosbridge)
    try:
        for service, why in (("/sim/reset", "a reset"), ("/sim/resume", "a resume")):
            other.call("/sim/pause", timeout=60)
            stepper.send({"op": "call_service", "id": why, "service": "/sim/step", "args": {"steps": 100_000}})
            while other.call("/sim/get_status", timeout=60)["values"]["stepping"] is None:
                pass
            assert other.call(service, timeout=120)["result"] is True
            reply = stepper.recv_until(lambda m, why=why: m.get("id") == why, timeout=120)
            assert reply["values"]["message"].endswith(f"stopped by {why}"), reply
        assert not lockstep_app.runner.paused  # resumed: the loop runs on
    finally:
        stepper.close()
        other.close()
