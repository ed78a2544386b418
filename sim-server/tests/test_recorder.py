"""`maa-sim run --record`: the MCAP file, read back with the `mcap` reader and decoded with
mcap-ros2-support, in both modes; the message definitions; a killed run's file."""

from __future__ import annotations

import contextlib
import json
import math
import signal
import subprocess
import sys
from collections import Counter
from pathlib import Path
from typing import Any

import pytest
from mcap.exceptions import EndOfFile
from mcap.reader import make_reader
from mcap.stream_reader import StreamReader
from mcap_ros2._dynamic import serialize_dynamic
from mcap_ros2.decoder import DecoderFactory

from maa_sim.app import RunOptions, SimApp
from maa_sim.cli import main
from maa_sim.messages import message_class
from maa_sim.msgdefs import _text_from_class, message_definition, message_text
from maa_sim.recorder import SCENE_TOPIC, SCENE_TYPE, part_path

#: the fixture application's port topics (tests/fixtures/toast_app/deployment.json; its lock-step
#: controller emits the same topics)
FIXTURE_PORT_TOPICS = {"/toast/ctrl/arm", "/toast/arm/status"}
SIM_TOPICS = {
    "/clock",
    "/joint_states",
    "/sensors/distance",
    "/sensors/color",
    "/arm/joint_command",
    "/arm/gripper_command",
    "/toaster/command",
}


def read_back(path: Path) -> tuple[dict[str, tuple[str, str, str]], Counter[str], list[tuple[str, int, Any]]]:
    """Channels (topic -> message encoding, schema name, schema encoding), counts per topic and every
    decoded message (topic, log time, message)."""
    decoded: list[tuple[str, int, Any]] = []
    with path.open("rb") as stream:
        reader = make_reader(stream, decoder_factories=[DecoderFactory()])
        assert reader.get_header().profile == "ros2"
        for _schema, channel, message, msg in reader.iter_decoded_messages(log_time_order=False):
            decoded.append((channel.topic, message.log_time, msg))
        summary = reader.get_summary()
    assert summary is not None, "the file is complete (summary and footer)"
    channels = {
        c.topic: (c.message_encoding, summary.schemas[c.schema_id].name, summary.schemas[c.schema_id].encoding)
        for c in summary.channels.values()
    }
    return channels, Counter(topic for topic, _, _ in decoded), decoded


def test_lockstep_run_records_every_topic_and_the_scene(toast_app_dir: Path, tmp_path: Path) -> None:
    target = tmp_path / "out" / "run.mcap"
    app = SimApp(
        RunOptions(
            package=toast_app_dir,
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
        # written beside the final name while the run lasts
        assert part_path(target).exists() and not target.exists()
        assert app.wait(120)
    finally:
        app.stop()
    assert target.exists() and not part_path(target).exists()
    assert app.session is not None and app.session.world.toast_on_plate()

    channels, counts, decoded = read_back(target)
    assert set(channels) == SIM_TOPICS | FIXTURE_PORT_TOPICS | {SCENE_TOPIC}
    for topic, (message_encoding, _, schema_encoding) in channels.items():
        assert (message_encoding, schema_encoding) == ("cdr", "ros2msg"), topic
        assert counts[topic] > 0, topic
    assert channels["/joint_states"][1] == "sensor_msgs/msg/JointState"
    assert channels[SCENE_TOPIC][1] == SCENE_TYPE
    periods = app.session.periods
    assert counts["/clock"] == counts[SCENE_TOPIC] == periods
    assert app.recorder is not None and app.recorder.summary()["messages"] == sum(counts.values())

    # stamped with the simulation clock: the scene's log times are its stamps, one period apart
    scenes = [(t, m) for topic, t, m in decoded if topic == SCENE_TOPIC]
    for log_time, scene in scenes[:5]:
        stamp = scene.stamp
        assert log_time == stamp.sec * 1_000_000_000 + stamp.nanosec
    assert scenes[1][0] - scenes[0][0] == 20_000_000
    last = scenes[-1][1]
    assert last.toast_on_plate and last.toast_level >= 0.8  # golden
    names = list(last.body_names)
    assert "bread" in names and len(names) == len(last.body_poses)
    bread = last.body_poses[names.index("bread")]
    assert math.hypot(bread.position.x + 0.15, bread.position.y + 0.26) < 0.08  # on the plate
    arm = [m for topic, _, m in decoded if topic == "/toast/ctrl/arm"]
    assert all(isinstance(m.data, str) and m.data for m in arm)


@pytest.mark.slow
def test_ros2_run_records_the_port_topics_of_the_nodes(toast_app_dir: Path, tmp_path: Path) -> None:
    target = tmp_path / "ros2.mcap"
    app = SimApp(
        RunOptions(
            package=toast_app_dir,
            mode="ros2",
            speed=1.0,
            rosbridge_port=None,
            viser_port=None,
            max_sim_time=6.0,
            record=target,
            startup_timeout=60.0,
            hang_timeout=20.0,
        )
    )
    app.start()
    try:
        assert app.wait(120)
    finally:
        app.stop()
    channels, counts, _ = read_back(target)
    # the nodes' port topics came over DDS (the arm program is sent when the bread is seen)
    assert "/toast/ctrl/arm" in channels and counts["/toast/ctrl/arm"] > 0
    for topic in ("/clock", "/joint_states", "/sensors/distance", "/arm/joint_command", SCENE_TOPIC):
        assert counts[topic] > 0, topic
    assert all(c[0] == "cdr" and c[2] == "ros2msg" for c in channels.values())
    assert channels["/toast/ctrl/arm"][1] == "std_msgs/msg/String"


def test_definitions_carry_their_dependencies() -> None:
    text = message_definition("sensor_msgs/msg/JointState")
    assert "MSG: std_msgs/Header" in text and "MSG: builtin_interfaces/Time" in text
    assert "string[] name" in text
    scene = message_definition(SCENE_TYPE)
    for dep in ("builtin_interfaces/Time", "geometry_msgs/Pose", "geometry_msgs/Point", "geometry_msgs/Quaternion"):
        assert f"MSG: {dep}\n" in scene
    # mcap-ros2-support parses them into encoders
    for type_name in ("sensor_msgs/msg/JointState", SCENE_TYPE, "rosgraph_msgs/msg/Clock"):
        assert type_name in serialize_dynamic(type_name, message_definition(type_name))


def field_lines(text: str) -> list[str]:
    lines = []
    for line in text.splitlines():
        code = line.split("#", 1)[0].strip()
        if code and "=" not in code:
            field_type, name = code.split()[:2]
            lines.append(f"{field_type.split('/')[-1]} {name}")  # geometry_msgs/Point and Point alike
    return lines


@pytest.mark.parametrize(
    "type_name", ["sensor_msgs/msg/JointState", "std_msgs/msg/Header", "geometry_msgs/msg/Pose", "std_msgs/msg/Int32"]
)
def test_definition_from_the_python_class_matches_the_msg_file(type_name: str) -> None:
    """A package installed without its share folder gets the same fields from its Python class."""
    assert field_lines(_text_from_class(message_class(type_name))) == field_lines(message_text(type_name))


def test_unknown_type_is_reported_and_left_out(tmp_path: Path) -> None:
    from maa_sim.recorder import McapRecorder, record_topics

    recorder = McapRecorder(tmp_path / "x.mcap")
    warnings: list[str] = []
    recorded = record_topics(
        recorder,
        [("/a", "std_msgs/msg/Int32"), ("/b", "no_such_msgs/msg/Thing")],
        lambda *_: None,
        lambda: 0.0,
        warnings.append,
    )
    recorder.close()
    assert recorded == ["/a"]
    assert len(warnings) == 1 and "/b" in warnings[0] and "not recorded" in warnings[0]


def test_killed_run_leaves_the_part_file_readable(toast_app_dir: Path, tmp_path: Path) -> None:
    target = tmp_path / "killed.mcap"
    process = subprocess.Popen(
        [
            sys.executable,
            "-m",
            "maa_sim.cli",
            "run",
            "--package",
            str(toast_app_dir),
            "--mode",
            "lockstep",
            "--speed",
            "1",
            "--rosbridge-port",
            "off",
            "--viser-port",
            "off",
            "--record",
            str(target),
            "--progress-json",
        ],
        stdout=subprocess.PIPE,
        text=True,
    )
    try:
        assert process.stdout is not None
        progress = []
        for line in process.stdout:
            if line.startswith('{"event": "progress"'):
                progress.append(json.loads(line))
                if len(progress) == 2:  # more than a second after the first chunk was written
                    break
        assert len(progress) == 2
        process.send_signal(signal.SIGKILL)
    finally:
        process.kill()
        process.wait()
    assert not target.exists()
    part = part_path(target)
    kinds: Counter[str] = Counter()
    with part.open("rb") as stream, contextlib.suppress(EndOfFile):  # the cut-off end
        for record in StreamReader(stream).records:
            kinds[type(record).__name__] += 1
    assert kinds["Header"] == 1 and kinds["Schema"] > 0 and kinds["Channel"] > 0
    assert kinds["Message"] >= 50  # at least a second of the run at speed 1 (50 periods of /clock alone)


def test_inspect_command(toast_app_dir: Path, tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    target = tmp_path / "short.mcap"
    code = main(
        [
            "run",
            "--package",
            str(toast_app_dir),
            "--mode",
            "lockstep",
            "--max-time",
            "0.5",
            "--rosbridge-port",
            "off",
            "--viser-port",
            "off",
            "--record",
            str(target),
            "--status-json",
        ]
    )
    assert code == 0
    finished = json.loads(capsys.readouterr().out.strip().splitlines()[-1])
    assert finished["event"] == "finished" and finished["record"]["path"] == str(target)
    assert finished["record"]["topics"]["/clock"] == 25
    assert main(["inspect", str(target)]) == 0
    info = json.loads(capsys.readouterr().out)
    assert info["profile"] == "ros2" and info["complete"] and info["messages"] == finished["record"]["messages"]
    clock = next(c for c in info["channels"] if c["topic"] == "/clock")
    assert clock == {
        "topic": "/clock",
        "message_encoding": "cdr",
        "schema": "rosgraph_msgs/msg/Clock",
        "schema_encoding": "ros2msg",
        "messages": 25,
    }
    assert main(["inspect", str(tmp_path / "missing.mcap")]) == 2
