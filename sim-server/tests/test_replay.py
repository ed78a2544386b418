"""`maa-sim replay`: a lock-step run of the generated ToastServiceRobot recorded, read back with the
`mcap` reader libraries (as Foxglove/Lichtblick read it), and played back: seeking moves the viser
scene to the recorded poses, the services answer the recorded values, bad input is refused."""

from __future__ import annotations

import json
import math
import signal
import subprocess
import sys
from collections.abc import Iterator
from pathlib import Path
from typing import Any

import pytest
from conftest import TOAST_APP as TOAST_APP_DIR
from mcap.reader import make_reader
from mcap_ros2.decoder import DecoderFactory
from rosbridge_client import Client
from test_generated_lockstep import TOAST_APP, generate

from maa_sim.app import RunOptions, SimApp
from maa_sim.recorder import SCENE_TOPIC, SCENE_TYPE
from maa_sim.replay import RecordingError, ReplayServer, load_recording, to_json

STATES = "/maa/automaton_states"


def record_run(package: Path, target: Path) -> list[tuple[str, str]]:
    """A lock-step run of `package` until the toast is on the plate, recorded; returns the run's topics."""
    app = SimApp(
        RunOptions(
            package=package,
            mode="lockstep",
            rosbridge_port=None,
            viser_port=None,
            until_goal=True,
            max_sim_time=40.0,
            record=target,
        )
    )
    app.start()
    try:
        assert app.wait(180)
        assert app.session is not None
        return app.session.transport.topics()
    finally:
        app.stop()


@pytest.fixture(scope="module")
def recorded(tmp_path_factory: pytest.TempPathFactory) -> tuple[Path, list[tuple[str, str]]]:
    """The fixture application (tests/fixtures/toast_app) recorded until the toast is on the plate."""
    target = tmp_path_factory.mktemp("rec") / "toast.mcap"
    return target, record_run(TOAST_APP_DIR, target)


@pytest.fixture(scope="module")
def server(recorded: tuple[Path, list[tuple[str, str]]]) -> Iterator[ReplayServer]:
    replay = ReplayServer(load_recording(recorded[0]), token="replay-test-token-0123456789abcdef")
    replay.start()
    yield replay
    replay.stop()


def _first_on_plate(scenes: list[tuple[float, Any]]) -> float:
    return next(t for t, s in scenes if s["toast_on_plate"])


def read_back(path: Path) -> tuple[dict[str, Any], dict[str, list[Any]]]:
    """The schemas by topic and the decoded messages by topic, read as Foxglove/Lichtblick read a file."""
    decoded: dict[str, list[Any]] = {}
    with path.open("rb") as stream:
        reader = make_reader(stream, decoder_factories=[DecoderFactory()])
        assert reader.get_header().profile == "ros2"
        for _schema, channel, _message, msg in reader.iter_decoded_messages():
            decoded.setdefault(channel.topic, []).append(msg)
        summary = reader.get_summary()
    assert summary is not None
    return {c.topic: summary.schemas[c.schema_id] for c in summary.channels.values()}, decoded


def test_the_recording_reads_in_the_mcap_libraries_with_every_topic_and_its_schema(
    recorded: tuple[Path, list[tuple[str, str]]],
) -> None:
    path, run_topics = recorded
    schemas, decoded = read_back(path)
    # every topic of the run (simulator, port topics, and automaton states, transitions and
    # program steps when the application publishes them) and the scene
    assert set(schemas) == {topic for topic, _ in run_topics} | {SCENE_TOPIC}
    for topic, type_name in run_topics:
        assert schemas[topic].name == type_name and schemas[topic].encoding == "ros2msg", topic
    assert schemas[SCENE_TOPIC].name == SCENE_TYPE
    assert decoded[SCENE_TOPIC][-1].toast_on_plate


def test_a_recording_of_the_generated_example_holds_its_automaton_states_and_port_topics(
    tmp_path_factory: pytest.TempPathFactory,
) -> None:
    build = generate(TOAST_APP, tmp_path_factory.mktemp("toast-timesync"))
    target = tmp_path_factory.mktemp("rec-example") / "TR.mcap"
    run_topics = record_run(build, target)
    schemas, decoded = read_back(target)
    assert set(schemas) == {topic for topic, _ in run_topics} | {SCENE_TOPIC}
    assert schemas[STATES].name == "std_msgs/msg/String"
    assert "/toast_service_robot/ctrl" in json.loads(decoded[STATES][-1].data)
    port_topics = [t for t in schemas if t.startswith("/toast_service_robot/") and t != STATES]
    assert port_topics and all(decoded.get(t) for t in port_topics)
    for optional in ("/maa/transitions", "/maa/program_steps"):  # recorded whenever the run has them
        assert (optional in schemas) == (optional in dict(run_topics))
    assert decoded[SCENE_TOPIC][-1].toast_on_plate


def test_load_gives_scene_states_and_messages_in_time_order(recorded: tuple[Path, list[tuple[str, str]]]) -> None:
    recording = load_recording(recorded[0])
    assert recording.scene_times == sorted(recording.scene_times) and len(recording.scenes) > 100
    times = [t for t, _, _ in recording.messages]
    assert times == sorted(times)
    assert SCENE_TOPIC not in {topic for _, topic, _ in recording.messages}
    assert recording.start == 0.0 or recording.start <= recording.scene_times[0]
    assert recording.end >= recording.scene_times[-1]
    arm = [m for _, topic, m in recording.messages if topic == "/toast/ctrl/arm"]
    assert arm and isinstance(arm[0]["data"], str)
    # messages in rosbridge's JSON form (nested objects, lists)
    joint = next(m for _, topic, m in recording.messages if topic == "/joint_states")
    assert isinstance(joint["name"], list) and isinstance(joint["header"]["stamp"]["sec"], int)


def test_seek_places_the_scene_at_the_recorded_poses(server: ReplayServer) -> None:
    recording = server.recording
    scene = server.scene
    assert scene is not None
    on_plate = _first_on_plate(list(zip(recording.scene_times, recording.scenes, strict=True)))
    i = recording.scene_times.index(on_plate)
    # just before the moment: the state before; at it and a little after: the recorded state
    assert server.seek({"time": on_plate - 1e-6})["scene"]["toast_on_plate"] is False
    answer = server.seek({"time": on_plate + 1e-4})
    assert answer["success"] and answer["scene"] is recording.scenes[i]
    assert answer["status"]["time"] == pytest.approx(on_plate + 1e-4)
    assert answer["status"]["toast_on_plate"] is True and "scene" not in answer["status"]
    assert server.status(with_scene=True)["scene"] is recording.scenes[i]
    recorded_bread = recording.scenes[i]["body_poses"][recording.scenes[i]["body_names"].index("bread")]
    frame = scene._frames["bread"]
    assert frame.position == pytest.approx(tuple(recorded_bread["position"][k] for k in "xyz"))
    assert frame.wxyz == pytest.approx(tuple(recorded_bread["orientation"][k] for k in "wxyz"))
    assert math.hypot(frame.position[0] + 0.15, frame.position[1] + 0.26) < 0.08  # on the plate
    # back to the start: the bread is where it began, off the plate
    server.seek({"time": recording.start})
    assert math.hypot(frame.position[0] + 0.15, frame.position[1] + 0.26) > 0.1
    # before the first state and after the last: the first and the last
    assert server.seek({"time": -5})["scene"] is recording.scenes[0]
    assert server.seek({"time": 1e9})["scene"] is recording.scenes[-1]


def test_seek_refuses_what_is_no_time(server: ReplayServer) -> None:
    for bad in ({}, {"time": "3"}, {"time": True}, {"time": None}, {"time": math.nan}):
        answer = server.seek(bad)
        assert answer["success"] is False and "time must be a number" in answer["message"]


def test_services_over_rosbridge_need_the_token_and_answer_the_recording(server: ReplayServer) -> None:
    assert server.rosbridge is not None
    with pytest.raises(Exception, match=r"401|403"):
        Client(server.rosbridge.url, token="wrong-token-0123456789abcdef0123")
    client = Client.of(server.rosbridge)
    try:
        client.send(
            {"op": "call_service", "id": "m", "service": "/sim/replay_messages", "args": {"exclude": ["/clock"]}}
        )
        answer = client.recv_until(lambda m: m.get("id") == "m", timeout=30)
        values = answer["values"]
        assert answer["result"] and values["success"], answer
        topics = {m["topic"] for m in values["messages"]}
        assert "/toast/ctrl/arm" in topics and "/clock" not in topics and SCENE_TOPIC not in topics
        assert len(values["messages"]) == len([m for m in server.recording.messages if m[1] != "/clock"])
        client.send({"op": "call_service", "id": "s", "service": "/sim/seek", "args": {"time": 2.0}})
        seek = client.recv_until(lambda m: m.get("id") == "s", timeout=30)["values"]
        assert seek["success"] and seek["status"]["time"] == 2.0
        client.send({"op": "call_service", "id": "b", "service": "/sim/replay_messages", "args": {"exclude": "x"}})
        bad = client.recv_until(lambda m: m.get("id") == "b", timeout=30)["values"]
        assert bad["success"] is False and "exclude" in bad["message"]
    finally:
        client.ws.close()


def test_a_file_that_is_no_recording_is_an_error(tmp_path: Path) -> None:
    junk = tmp_path / "junk.mcap"
    junk.write_bytes(b"not an mcap file at all")
    with pytest.raises(RecordingError, match=r"cannot read the recording junk\.mcap"):
        load_recording(junk)
    with pytest.raises(RecordingError, match="cannot read"):
        load_recording(tmp_path / "missing.mcap")


def test_to_json_turns_decoded_messages_into_rosbridge_json() -> None:
    class Inner:
        __slots__ = ("sec",)

        def __init__(self) -> None:
            self.sec = 3

    class Outer:
        __slots__ = ("data", "items", "stamp")

        def __init__(self) -> None:
            self.stamp = Inner()
            self.items = [Inner()]
            self.data = b"\x01\x02"

    assert to_json(Outer()) == {"stamp": {"sec": 3}, "items": [{"sec": 3}], "data": [1, 2]}


def test_cli_replay_serves_until_terminated_and_refuses_a_bad_file(
    recorded: tuple[Path, list[tuple[str, str]]], tmp_path: Path
) -> None:
    cmd = [sys.executable, "-m", "maa_sim", "replay", "--rosbridge-port", "0", "--viser-port", "off", "--status-json"]
    junk = tmp_path / "junk.mcap"
    junk.write_text("junk")
    bad = subprocess.run([*cmd, str(junk)], capture_output=True, text=True, timeout=120, check=False)
    assert bad.returncode == 2 and "cannot read the recording junk.mcap" in bad.stderr
    proc = subprocess.Popen([*cmd, str(recorded[0])], stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    try:
        assert proc.stdout is not None
        ready = json.loads(proc.stdout.readline())
        assert ready["event"] == "ready" and ready["rosbridge"].startswith("ws://127.0.0.1:")
        assert ready["viser"] is None and ready["end"] > ready["start"]
    finally:
        proc.send_signal(signal.SIGTERM)
        assert proc.wait(60) == 0


def test_a_ros2_run_records_the_event_topics_too(toast_app_dir: Path) -> None:
    """ROS 2 mode: no controller declares the event topics, so the recorder subscribes to them itself."""
    from types import SimpleNamespace

    from maa_sim.recorder import EVENT_TOPICS

    app = SimApp(RunOptions(package=toast_app_dir, mode="ros2", rosbridge_port=None, viser_port=None))
    app.session = SimpleNamespace(transport=object())  # type: ignore[assignment]  # only its transport is read
    topics = dict(app._recorded_topics())
    assert set(EVENT_TOPICS) == {"/maa/automaton_states", "/maa/transitions", "/maa/program_steps"}
    for topic in EVENT_TOPICS:
        assert topics[topic] == "std_msgs/msg/String"
    assert topics["/clock"] == "rosgraph_msgs/msg/Clock"
