"""Lock-step mode with generated timesync builds: the toast is served, and the IDE's live values arrive.

The builds are generated at test time (``maa-gen generate ... --platform timesync``): the
ToastServiceRobot, the generator tests' Features fixture, whose root has in ports (input
injection over rosbridge) and a hierarchical automaton, and their Modes fixture, whose root has a
mode automaton. docs/ide.md ("Live values") is the contract: port topics under their ROS 2 names,
automaton states and the modes of mode components on ``/maa/automaton_states``.
"""

from __future__ import annotations

import itertools
import json
import shutil
import time
from collections.abc import Iterator
from pathlib import Path
from typing import Any

import pytest
import warm_maa_gen
from rosbridge_client import Client

from maa_sim.app import RunOptions, SimApp

REPO = Path(__file__).resolve().parents[2]
TOAST_APP = REPO / "examples" / "toast-service" / "TR.arcapp"
FEATURES_APP = REPO / "packages" / "generators-python" / "test" / "fixtures" / "features" / "Features.arcapp"
MODES_APP = REPO / "packages" / "generators-python" / "test" / "fixtures" / "modes" / "Modes.arcapp"
STATES = "/maa/automaton_states"
#: The toast must be on the plate within this much simulated time (about 15 s).
TIME_BOUND = 30.0


def generate(app: Path, out: Path) -> Path:
    if shutil.which("node") is None:
        pytest.skip("node is needed to generate the timesync build")
    result = warm_maa_gen.run(["generate", str(app), "--platform", "timesync", "--out", str(out)])
    assert result.returncode == 0, f"maa-gen generate failed:\n{result.stdout}\n{result.stderr}"
    return out / "timesync"


@pytest.fixture(scope="module")
def toast_build(tmp_path_factory: pytest.TempPathFactory) -> Path:
    return generate(TOAST_APP, tmp_path_factory.mktemp("toast-timesync"))


@pytest.fixture(scope="module")
def features_build(tmp_path_factory: pytest.TempPathFactory) -> Path:
    return generate(FEATURES_APP, tmp_path_factory.mktemp("features-timesync"))


@pytest.fixture(scope="module")
def modes_build(tmp_path_factory: pytest.TempPathFactory) -> Path:
    return generate(MODES_APP, tmp_path_factory.mktemp("modes-timesync"))


def lockstep_app(package: Path, **options: Any) -> SimApp:
    return SimApp(
        RunOptions(package=package, mode="lockstep", rosbridge_port=0, viser_port=None, paused=True, **options)
    )


def drain(client: Client, quiet: float = 0.5) -> list[dict[str, Any]]:
    messages: list[dict[str, Any]] = []
    while True:
        try:
            messages.append(client.recv(timeout=quiet))
        except TimeoutError:
            return messages


def step(client: Client, quiet: float = 0.3) -> list[dict[str, Any]]:
    """One slice through /sim/step; every message that arrived meanwhile and shortly after."""
    request_id = f"step:{time.monotonic_ns()}"
    client.send({"op": "call_service", "id": request_id, "service": "/sim/step", "args": {"steps": 1}})
    messages: list[dict[str, Any]] = []
    while True:
        m = client.recv(timeout=10)
        if m.get("op") == "service_response" and m.get("id") == request_id:
            assert m["result"] is True, m
            return messages + drain(client, quiet)
        messages.append(m)


@pytest.fixture
def toast_app(toast_build: Path) -> Iterator[SimApp]:
    app = lockstep_app(toast_build, until_goal=True, max_sim_time=TIME_BOUND, speed=0.0)
    app.start()
    yield app
    app.stop()


def test_generated_build_serves_the_toast_with_live_values(toast_app: SimApp) -> None:
    assert toast_app.rosbridge is not None and toast_app.session is not None and toast_app.runner is not None
    client = Client.of(toast_app.rosbridge)
    try:
        topics = client.call("rosapi/topics")["values"]
        types = dict(zip(topics["topics"], topics["types"], strict=True))
        assert types["/toast_service_robot/ctrl/arm"] == "std_msgs/msg/String"
        assert types["/toast_service_robot/dist/value"] == "std_msgs/msg/Int32"
        assert types["/toast_service_robot/toaster_ctrl/lever_down"] == "std_msgs/msg/Bool"
        assert types[STATES] == "std_msgs/msg/String"
        for topic in ("/toast_service_robot/ctrl/arm", "/toast_service_robot/arm/status", STATES):
            client.send({"op": "subscribe", "topic": topic})
        client.send({"op": "subscribe", "topic": "/toast_service_robot/dist/value", "throttle_rate": 500})
        time.sleep(0.2)
        assert client.call("/sim/resume")["result"] is True
        assert toast_app.wait(timeout=300), toast_app.status()
        assert toast_app.runner.finish_reason == "goal reached", toast_app.status()
        assert toast_app.session.world.toast_on_plate()
        assert toast_app.session.world.time < TIME_BOUND
        by_topic: dict[str, list[Any]] = {}
        for m in drain(client):
            if m.get("op") == "publish":
                by_topic.setdefault(m["topic"], []).append(m["msg"]["data"])
        assert by_topic["/toast_service_robot/ctrl/arm"] == ["NONE", "LOAD_BREAD", "PICKUP_AND_DEPLOY"]
        assert by_topic["/toast_service_robot/arm/status"][:4] == ["IDLE", "BUSY", "DONE", "BUSY"]
        assert 0 < by_topic["/toast_service_robot/dist/value"][0] < 25  # the bread in its holder, in mm
        states = [json.loads(s) for s in by_topic[STATES]]
        # the first slice's states (the bread is there at once: Idle -> Loading in slice 1), then every change
        assert states[0] == {"/toast_service_robot/ctrl": "Loading", "/toast_service_robot/toaster_ctrl": "Off"}
        assert all(a != b for a, b in itertools.pairwise(states))
        ctrl = [s["/toast_service_robot/ctrl"] for s in states]
        assert [c for i, c in enumerate(ctrl) if i == 0 or c != ctrl[i - 1]] == ["Loading", "Toasting", "Serving"]
        # a client that subscribes late gets the current states at once (latched), and so does get_status
        late = Client.of(toast_app.rosbridge)
        late.send({"op": "subscribe", "topic": STATES})
        current = json.loads(late.recv_until(lambda m: m.get("topic") == STATES)["msg"]["data"])
        late.close()
        assert current == states[-1]
        assert client.call("/sim/get_status")["values"]["automaton_states"] == states[-1]
    finally:
        client.close()


def test_injection_on_root_in_ports_over_rosbridge(features_build: Path) -> None:
    app = lockstep_app(features_build, speed=0.0)
    app.start()
    try:
        assert app.rosbridge is not None
        client = Client.of(app.rosbridge)
        client.send({"op": "set_level", "level": "warning"})
        for topic in ("/features/lamp/log", "/features/press", STATES):
            client.send({"op": "subscribe", "topic": topic})
        first = step(client)
        assert [m["msg"]["data"] for m in first if m.get("topic") == "/features/lamp/log"] == ["init", "off"]
        assert {json.loads(m["msg"]["data"])["/features/lamp"] for m in first if m.get("topic") == STATES} == {"Off"}
        # the IDE injects inputs on the root's unconnected in ports: they reach the next slice
        client.send({"op": "advertise", "topic": "/features/press", "type": "std_msgs/msg/Bool"})
        client.send({"op": "publish", "topic": "/features/press", "msg": {"data": True}})
        client.send({"op": "publish", "topic": "/features/level", "msg": {"data": 3}})
        client.send({"op": "publish", "id": "bad", "topic": "/features/mode", "msg": {"data": "WARP"}})
        time.sleep(0.2)
        second = step(client)
        errors = [m for m in second if m.get("op") == "status" and m.get("id") == "bad"]
        assert errors and "not a constant of Mode" in errors[0]["msg"]
        assert [m["msg"] for m in second if m.get("topic") == "/features/press"] == [{"data": True}]  # once
        assert [m["msg"]["data"] for m in second if m.get("topic") == "/features/lamp/log"][:1] == ["on"]
        assert [json.loads(m["msg"]["data"]) for m in second if m.get("topic") == STATES] == [
            {"/features/lamp": "On.Bright"}
        ]
        client.close()
    finally:
        app.stop()


def test_the_mode_of_a_mode_component_is_its_live_state(modes_build: Path) -> None:
    app = lockstep_app(modes_build, speed=0.0)
    app.start()
    try:
        assert app.rosbridge is not None
        client = Client.of(app.rosbridge)
        for topic in ("/gearbox/s1/o", "/gearbox/s10/o", STATES):
            client.send({"op": "subscribe", "topic": topic})
        first = step(client)
        # the root gear.Gearbox has no automaton state of its own: its live state is its mode
        assert [json.loads(m["msg"]["data"]) for m in first if m.get("topic") == STATES] == [{"/gearbox": "First"}]
        client.send({"op": "advertise", "topic": "/gearbox/speed", "type": "std_msgs/msg/Int32"})
        client.send({"op": "publish", "topic": "/gearbox/speed", "msg": {"data": -1}})
        # the slices until the message is fed (no state changes before: a slice without speed stays in First)
        for _ in range(50):
            second = step(client)
            changes = [json.loads(m["msg"]["data"]) for m in second if m.get("topic") == STATES]
            if changes:
                break
        # a negative speed switches to Second in its own slice: s10 handles it
        assert changes == [{"/gearbox": "Second"}]
        assert [m["msg"]["data"] for m in second if m.get("topic") == "/gearbox/s10/o"] == [-10]
        assert client.call("/sim/get_status")["values"]["automaton_states"] == {"/gearbox": "Second"}
        # the next slice has no speed (Java's 0 in the guard): back to First
        third = step(client)
        assert [json.loads(m["msg"]["data"]) for m in third if m.get("topic") == STATES] == [{"/gearbox": "First"}]
        client.close()
    finally:
        app.stop()


def test_recording_has_a_channel_for_every_port_topic(toast_build: Path, tmp_path: Path) -> None:
    """`--record` with a generated build: every port topic its topics() declares is a channel with
    messages, each decodes with its ROS 2 schema (docs/simulation.md, "Recording")."""
    from mcap.reader import make_reader
    from mcap_ros2.decoder import DecoderFactory

    target = tmp_path / "toast.mcap"
    app = SimApp(
        RunOptions(
            package=toast_build,
            mode="lockstep",
            rosbridge_port=None,
            viser_port=None,
            until_goal=True,
            max_sim_time=TIME_BOUND,
            record=target,
        )
    )
    app.start()
    try:
        assert app.wait(300)
        assert app.runner is not None
        declared = dict(app.runner.controller.topics())  # type: ignore[union-attr]
    finally:
        app.stop()
    assert app.runner.finish_reason == "goal reached"
    counts: dict[str, int] = {}
    with target.open("rb") as stream:
        reader = make_reader(stream, decoder_factories=[DecoderFactory()])
        for _schema, channel, _message, _decoded in reader.iter_decoded_messages():
            counts[channel.topic] = counts.get(channel.topic, 0) + 1
        summary = reader.get_summary()
    assert summary is not None
    types = {c.topic: summary.schemas[c.schema_id].name for c in summary.channels.values()}
    port_topics = {t for t in declared if t.startswith("/toast_service_robot/")}
    assert port_topics, declared
    for topic in port_topics:
        assert counts.get(topic, 0) > 0, f"{topic} has no messages"
        assert types[topic] == declared[topic], topic
    assert counts[STATES] > 0 and counts["/sim/scene"] == counts["/clock"]
