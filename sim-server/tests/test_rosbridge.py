"""The rosbridge v2 endpoint: protocol operations, errors, a fuzz test, a real roslib client."""

from __future__ import annotations

import json
import random
import shutil
import subprocess
import time
from collections.abc import Iterator
from pathlib import Path

import pytest
from rosbridge_client import Client

from maa_sim.app import RunOptions, SimApp
from maa_sim.rosbridge import MAX_FRAME_BYTES, RosbridgeServer
from maa_sim.transport import LocalBus

JS_DIR = Path(__file__).resolve().parent / "js"


@pytest.fixture
def bus_server() -> Iterator[tuple[LocalBus, RosbridgeServer]]:
    bus = LocalBus()
    bus.declare("/sensors/distance", "std_msgs/msg/Int32")
    server = RosbridgeServer(bus, port=0)
    server.start()
    yield bus, server
    server.stop()


@pytest.fixture
def lockstep_app(toast_app_dir: Path) -> Iterator[SimApp]:
    app = SimApp(
        RunOptions(package=toast_app_dir, mode="lockstep", speed=1.0, rosbridge_port=0, viser_port=None, paused=True)
    )
    app.start()
    yield app
    app.stop()


def test_publish_subscribe_round_trip(bus_server: tuple[LocalBus, RosbridgeServer]) -> None:
    bus, server = bus_server
    a, b = Client.of(server), Client.of(server)
    try:
        b.send({"op": "subscribe", "id": "s1", "topic": "/chatter", "type": "std_msgs/String"})
        a.send({"op": "advertise", "id": "a1", "topic": "/chatter", "type": "std_msgs/msg/String"})
        time.sleep(0.1)
        a.send({"op": "publish", "topic": "/chatter", "msg": {"data": "hello"}})
        message = b.recv_until(lambda m: m.get("op") == "publish")
        assert message == {"op": "publish", "topic": "/chatter", "msg": {"data": "hello"}}
        # a message from the simulator side reaches the client too
        b.send({"op": "subscribe", "topic": "/sensors/distance"})
        time.sleep(0.1)
        bus.deliver("/sensors/distance", {"data": 17})
        assert b.recv_until(lambda m: m.get("topic") == "/sensors/distance")["msg"] == {"data": 17}
        b.send({"op": "unsubscribe", "id": "s1", "topic": "/chatter"})
        time.sleep(0.1)
        a.send({"op": "publish", "topic": "/chatter", "msg": {"data": "again"}})
        with pytest.raises(TimeoutError):
            b.recv(timeout=0.3)
    finally:
        a.close()
        b.close()


def test_throttle_rate_and_queue_length(bus_server: tuple[LocalBus, RosbridgeServer]) -> None:
    bus, server = bus_server
    client = Client.of(server)
    try:
        client.send({"op": "subscribe", "topic": "/sensors/distance", "throttle_rate": 200, "queue_length": 1})
        time.sleep(0.1)
        start = time.monotonic()
        while time.monotonic() - start < 1.0:
            bus.deliver("/sensors/distance", {"data": int((time.monotonic() - start) * 1000)})
            time.sleep(0.005)
        received = []
        with pytest.raises(TimeoutError):
            while True:
                received.append(client.recv(timeout=0.5))
        assert 3 <= len(received) <= 8, len(received)  # about 1 s / 200 ms, not ~200 messages
        assert received[-1]["msg"]["data"] > 800  # the latest value wins with queue_length 1
    finally:
        client.close()


def test_errors_get_status_replies(bus_server: tuple[LocalBus, RosbridgeServer]) -> None:
    _, server = bus_server
    client = Client.of(server)
    try:
        cases = [
            "not json",
            json.dumps([1, 2]),
            json.dumps({"no": "op"}),
            json.dumps({"op": "fly", "id": "x1"}),
            json.dumps({"op": "publish", "id": "x2", "topic": "/unknown", "msg": {}}),
            json.dumps({"op": "advertise", "id": "x3", "topic": "/t", "type": "no_such/Type"}),
            json.dumps({"op": "subscribe", "id": "x4", "topic": 5}),
            json.dumps(
                {"op": "subscribe", "id": "x5", "topic": "/a", "type": "std_msgs/Int32", "throttle_rate": "fast"}
            ),
            json.dumps({"op": "publish", "id": "x6", "topic": "/sensors/distance", "msg": {"data": "many"}}),
        ]
        for frame in cases:
            client.send(frame)
            reply = client.recv()
            assert reply["op"] == "status" and reply["level"] == "error", (frame, reply)
        client.send({"op": "publish", "id": "x9", "topic": "/sensors/distance", "msg": {"data": 1.5}})
        assert client.recv() == {
            "op": "status",
            "level": "error",
            "msg": "std_msgs/msg/Int32.data: expected an integer (int32)",
            "id": "x9",
        }
        reply = client.call("rosapi/no_such_service")
        assert reply["result"] is False
    finally:
        client.close()


def test_message_details_name_fields_and_constants(bus_server: tuple[LocalBus, RosbridgeServer]) -> None:
    """rosapi/message_details as roslib's getMessageDetails reads it: the IDE takes the literals of
    an enum message (a `value` field and one constant per literal) from the constants."""
    _, server = bus_server
    client = Client.of(server)
    try:
        reply = client.call("rosapi/message_details", {"type": "sensor_msgs/msg/BatteryState"})
        assert reply["result"] is True, reply
        typedefs = reply["values"]["typedefs"]
        battery = typedefs[0]
        assert battery["type"] == "sensor_msgs/BatteryState"
        fields = dict(zip(battery["fieldnames"], battery["fieldtypes"], strict=True))
        assert fields["header"] == "std_msgs/Header" and fields["voltage"] == "float32"
        assert fields["present"] == "bool" and fields["cell_voltage"] == "float32"
        lengths = dict(zip(battery["fieldnames"], battery["fieldarraylen"], strict=True))
        assert lengths["voltage"] == -1 and lengths["cell_voltage"] == 0
        constants = dict(zip(battery["constnames"], battery["constvalues"], strict=True))
        assert constants["POWER_SUPPLY_STATUS_UNKNOWN"] == "0" and constants["POWER_SUPPLY_STATUS_FULL"] == "4"
        # The nested types follow, each once.
        nested = ["sensor_msgs/BatteryState", "std_msgs/Header", "builtin_interfaces/Time"]
        assert [t["type"] for t in typedefs] == nested
        for bad in [{"type": "no_such/msg/Type"}, {"type": 5}, {}]:
            failed = client.call("rosapi/message_details", bad)
            assert failed["result"] is False, (bad, failed)
    finally:
        client.close()


def fuzz_frames(count: int, seed: int) -> list[str | bytes]:
    """Malformed and hostile frames, deterministic for a seed."""
    rng = random.Random(seed)
    ops = ["publish", "subscribe", "advertise", "unsubscribe", "unadvertise", "call_service", "set_level"]
    junk: list[object] = [None, True, -1, 2**70, 1.5, "", "x" * 300, [], {}, [1, [2]], {"a": {"b": None}}]

    def frame() -> str | bytes:
        kind = rng.randrange(14)
        if kind >= 10:
            return bad_message_frame(rng, kind)
        if kind == 0:
            text = json.dumps({"op": rng.choice(ops), "topic": "/t"})
            return text[: rng.randrange(1, len(text))]  # truncated JSON
        if kind == 1:
            return bytes(rng.randrange(256) for _ in range(rng.randrange(1, 64)))  # binary frame
        if kind == 2:
            return json.dumps({"op": "".join(rng.choice("abcxyz_") for _ in range(8)), "id": rng.randrange(1000)})
        if kind == 3:
            return json.dumps(rng.choice([*junk[:-1], [{"op": "publish"}]]))  # not an object
        if kind == 4:
            return '{"op": "publish", "topic": "/t", "msg": ' + "[" * 5000 + "]" * 5000 + "}"  # deep nesting
        if kind == 5 and rng.random() < 0.05:
            return json.dumps({"op": "publish", "topic": "/t", "msg": {"data": "x" * (MAX_FRAME_BYTES + 10)}})  # huge
        if kind == 6:
            return json.dumps({"op": rng.choice(ops), "id": "f", "topic": rng.choice(junk), "type": rng.choice(junk)})
        if kind == 7:
            return json.dumps({"op": "publish", "topic": "/sensors/distance", "msg": {"data": rng.choice(junk[3:])}})
        if kind == 8:
            return json.dumps({"op": "call_service", "service": rng.choice(junk), "args": rng.choice(junk)})
        return json.dumps(
            {
                "op": "subscribe",
                "topic": "/x",
                "type": "std_msgs/Int32",
                "queue_length": rng.choice([-5, 10**9, "q", 2.5]),
            }
        )

    return [frame() for _ in range(count)]


#: Messages that fit no type, or fit the type but not what the simulator's own topics carry
#: (the fixture application reads /joint_states trusting every joint is there: `{}` ended the
#: simulation with a KeyError), on the simulator's topics and on the application's.
ALL_JOINTS = ["base_yaw", "lift", "finger_inner", "finger_outer"]
BAD_MESSAGES: list[tuple[str, object]] = [
    ("/joint_states", {}),
    ("/joint_states", {"name": ["base_yaw"], "position": [1.0], "velocity": [0.0]}),
    ("/joint_states", {"name": ALL_JOINTS, "position": [0.0] * 4, "velocity": [0.0]}),
    ("/joint_states", {"name": [*ALL_JOINTS, "base_yaw"], "position": [0.0] * 5, "velocity": [0.0] * 5}),
    ("/joint_states", {"name": ALL_JOINTS, "position": [0.0] * 4, "velocity": [0.0] * 4, "effort": [1.0]}),
    ("/joint_states", {"position": "x"}),
    ("/joint_states", {"name": [1, 2, 3, 4]}),
    ("/sensors/color", {"data": "PURPLE"}),
    ("/sensors/color", {}),
    ("/sensors/distance", {"data": None}),
    ("/clock", {"clock": {"sec": 1, "nanosec": 0}}),
    ("/clock", {}),
    ("/toast/ctrl/arm", {"data": 5}),
    ("/toast/arm/status", {"data": None}),
    ("/toast/arm/status", {"value": "DONE"}),
    ("/arm/joint_command", {"name": "base_yaw"}),
    ("/arm/joint_command", {"position": [[1.0]]}),
    ("/arm/gripper_command", {"data": "open"}),
    ("/toaster/command", {"data": ["START"]}),
]
#: Control services with arguments they refuse.
BAD_CALLS: list[tuple[str, object]] = [
    ("/sim/step", {"steps": 0}),
    ("/sim/step", {"steps": -3}),
    ("/sim/step", {"steps": 100_001}),
    ("/sim/step", {"steps": 2.5}),
    ("/sim/step", {"steps": "10"}),
    ("/sim/step", {"steps": None}),
    ("/sim/step", {"steps": True}),
    ("/sim/set_speed", {"speed": "fast"}),
    ("/sim/set_speed", {"speed": None}),
    ("/sim/set_speed", {"speed": -1}),
    ("/sim/set_speed", {"speed": 1e9}),
    ("/sim/reset", {"seed": "x"}),
    ("/sim/reset", {"seed": 1.5}),
    ("/sim/reset", {"seed": True}),
    ("rosapi/topic_type", {"topic": 5}),
    ("rosapi/message_details", {"type": "no/Such"}),
    ("/sim/pause", "now"),
    ("/sim/step", [1]),
]


def bad_message_frame(rng: random.Random, kind: int) -> str:
    if kind == 10 or kind == 11:
        topic, msg = rng.choice(BAD_MESSAGES)
        return json.dumps({"op": "publish", "id": f"p{kind}", "topic": topic, "msg": msg})
    service, args = rng.choice(BAD_CALLS)
    return json.dumps({"op": "call_service", "id": f"c{kind}", "service": service, "args": args})


def test_every_bad_message_is_refused_with_its_reason(lockstep_app: SimApp) -> None:
    assert lockstep_app.rosbridge is not None
    client = Client.of(lockstep_app.rosbridge)
    try:
        for topic, msg in BAD_MESSAGES:
            client.send({"op": "publish", "id": "bad", "topic": topic, "msg": msg})
            reply = client.recv(timeout=30)
            assert reply["op"] == "status" and reply["level"] == "error" and reply["id"] == "bad", (topic, msg, reply)
            assert reply["msg"] and "internal error" not in reply["msg"], (topic, msg, reply)
        # the frame of the report, and a complete joint state, which is taken
        client.send({"op": "publish", "id": "js", "topic": "/joint_states", "msg": {}})
        assert "name must list each of base_yaw" in client.recv(timeout=30)["msg"]
        full = {"name": ALL_JOINTS, "position": [0.0] * 4, "velocity": [0.0] * 4}
        client.send({"op": "publish", "id": "ok", "topic": "/joint_states", "msg": full})
        with pytest.raises(TimeoutError):
            client.recv(timeout=0.5)  # no error for a message that fits
        assert client.call("/sim/step", {"steps": 20}, timeout=60)["result"] is True
        assert lockstep_app.runner is not None and not lockstep_app.runner.finished.is_set()
    finally:
        client.close()


def test_fuzz_1000_malformed_frames(lockstep_app: SimApp) -> None:
    """Against a running lock-step session: every frame gets its error, the simulation goes on."""
    assert lockstep_app.rosbridge is not None and lockstep_app.runner is not None
    client = Client.of(lockstep_app.rosbridge)
    try:
        assert client.call("/sim/resume", timeout=30)["result"] is True
        frames = fuzz_frames(1000, seed=1234)
        errors = 0
        for frame in frames:
            client.send(frame)
            reply = client.recv(timeout=5)
            assert reply["op"] in ("status", "service_response"), reply
            if reply["op"] == "service_response":
                assert reply["result"] is False
                reply = client.recv(timeout=5)
            assert reply["op"] == "status" and reply["level"] == "error", (frame[:200], reply)
            errors += 1
        assert errors == 1000
        # still answering, on this connection and on a new one
        assert client.call("rosapi/topics")["result"] is True
        fresh = Client.of(lockstep_app.rosbridge)
        assert "/clock" in fresh.call("rosapi/topics")["values"]["topics"]
        fresh.close()
        # and still simulating: it ran meanwhile, and it steps
        assert not lockstep_app.runner.finished.is_set(), lockstep_app.runner.finish_reason
        paused = client.call("/sim/pause", timeout=30)["values"]["status"]
        assert paused["periods"] > 0 and paused["finished"] == ""
        stepped = client.call("/sim/step", {"steps": 10}, timeout=60)["values"]["status"]
        assert stepped["periods"] == paused["periods"] + 10
    finally:
        client.close()


def test_control_services(lockstep_app: SimApp) -> None:
    assert lockstep_app.rosbridge is not None
    client = Client.of(lockstep_app.rosbridge)
    try:
        status = client.call("/sim/get_status")["values"]
        assert status["paused"] is True and status["mode"] == "lockstep"
        reply = client.call("/sim/step", {"steps": 10})
        assert reply["result"] is True
        assert reply["values"]["status"]["time"] == pytest.approx(0.2)
        assert client.call("/sim/step", {"steps": "ten"})["result"] is False
        assert client.call("/sim/set_speed", {"speed": 5})["values"]["status"]["speed"] == 5
        assert client.call("/sim/set_speed", {"speed": -1})["result"] is False
        client.call("/sim/resume")
        time.sleep(0.3)
        client.call("/sim/pause")
        t = client.call("/sim/get_status")["values"]["time"]
        assert t > 0.2
        time.sleep(0.2)
        assert client.call("/sim/get_status")["values"]["time"] == t  # paused
        client.call("/sim/reset")
        assert client.call("/sim/get_status")["values"]["world_time"] == 0.0
        types = client.call("rosapi/topics")["values"]
        assert dict(zip(types["topics"], types["types"], strict=True))["/toast/ctrl/arm"] == "std_msgs/msg/String"
        assert (
            client.call("rosapi/topic_type", {"topic": "/joint_states"})["values"]["type"]
            == "sensor_msgs/msg/JointState"
        )
        assert "/sim/step" in client.call("rosapi/services")["values"]["services"]
    finally:
        client.close()


def test_input_injection_in_lockstep(lockstep_app: SimApp) -> None:
    assert lockstep_app.rosbridge is not None
    client = Client.of(lockstep_app.rosbridge)
    try:
        client.call("/sim/step", {"steps": 1})  # the controller's initial slice writes STOP
        client.send({"op": "advertise", "topic": "/toaster/command", "type": "std_msgs/msg/String"})
        client.send({"op": "publish", "topic": "/toaster/command", "msg": {"data": "START"}})
        time.sleep(0.1)
        client.call("/sim/step", {"steps": 50})
        world = lockstep_app.session.world if lockstep_app.session else None
        assert world is not None and world.lever_position() < -0.05
    finally:
        client.close()


@pytest.fixture(scope="module")
def roslib_installed() -> Path:
    npm = shutil.which("npm")
    if npm is None or shutil.which("node") is None:
        pytest.skip("node and npm are needed for the roslib test")
    if not (JS_DIR / "node_modules" / "roslib").is_dir():
        subprocess.run(
            [npm, "install", "--prefix", str(JS_DIR), "--no-audit", "--no-fund", "--loglevel=error"],
            check=True,
            timeout=300,
        )
    return JS_DIR


def test_roslib_client(roslib_installed: Path, lockstep_app: SimApp) -> None:
    assert lockstep_app.rosbridge is not None and lockstep_app.runner is not None
    assert lockstep_app.runner.paused  # the client resumes it once it has subscribed
    result = subprocess.run(
        ["node", str(roslib_installed / "roslib_client.mjs"), lockstep_app.rosbridge.url_with_token],
        capture_output=True,
        text=True,
        check=False,
        timeout=60,
    )
    assert result.returncode == 0, result.stdout + result.stderr
    report = json.loads(result.stdout.strip().splitlines()[-1])
    assert "/toast/ctrl/arm" in report["topics"]
    assert report["topicType"] == "sensor_msgs/msg/JointState"
    assert report["distance"] < 25  # a port value read through roslib
    assert report["armCommand"] == "FETCH"  # the controller's port, live
    assert report["echo"] == "hello from roslib"  # an input published by roslib came back
    assert report["serviceError"]  # a failing service reached the failed callback
