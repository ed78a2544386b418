"""What the IDE's simulate view relies on (issue 19): a reset starts the clock at 0 again while the
elapsed time (pacing, recordings) keeps counting; a client that subscribes late gets a port's last
value at once; the viser panel's run controls can be turned off (the IDE has its own)."""

from __future__ import annotations

from collections.abc import Iterator
from pathlib import Path
from typing import Any

import pytest
from rosbridge_client import Client
from toast_app.lockstep import create_controller

from maa_sim.app import RunOptions, SimApp
from maa_sim.cli import build_parser
from maa_sim.runs import lockstep_session

PORT_TOPIC = "/toast/ctrl/arm"


@pytest.fixture
def lockstep_app(toast_app_dir: Path) -> Iterator[SimApp]:
    app = SimApp(
        RunOptions(package=toast_app_dir, mode="lockstep", speed=1.0, rosbridge_port=0, viser_port=None, paused=True)
    )
    app.start()
    yield app
    app.stop()


def subscribe_and_collect(client: Client, topic: str) -> list[dict[str, Any]]:
    """Subscribes, then makes two status round trips, collecting the topic's messages meanwhile.
    The endpoint hands a subscription's first message to its event loop; once the client has had
    the first reply and sent the second request, the loop has waited for that request and run
    everything scheduled before: every message sent at the subscription came before the second
    reply (no waiting on time)."""
    client.send({"op": "subscribe", "id": "late", "topic": topic, "type": "std_msgs/msg/String"})
    seen: list[dict[str, Any]] = []
    for barrier in ("first", "second"):
        client.send({"op": "call_service", "id": barrier, "service": "/sim/get_status", "args": {}})
        while True:
            message = client.recv(timeout=30)
            if message.get("op") == "service_response" and message.get("id") == barrier:
                break
            if message.get("op") == "publish" and message.get("topic") == topic:
                seen.append(message["msg"])
    return seen


# ------------------------------------------------------------------------------ the clock at a reset


def test_a_reset_starts_the_clock_at_zero_and_elapsed_keeps_counting() -> None:
    session, runner = lockstep_session(create_controller({}))
    for _ in range(50):
        runner.cycle()
    assert session.clock == pytest.approx(1.0)
    runner.reset()
    assert session.clock == 0.0
    assert session.observe()["/clock"]["clock"] == {"sec": 0, "nanosec": 0}
    assert session.elapsed == pytest.approx(1.0)
    runner.cycle()
    assert session.clock == pytest.approx(0.02)
    assert session.elapsed == pytest.approx(1.02)


def test_period_listeners_get_the_elapsed_time_which_never_goes_back() -> None:
    session, runner = lockstep_session(create_controller({}))
    times: list[float] = []
    session.period_listeners.append(lambda _world, t: times.append(t))
    for _ in range(10):
        runner.cycle()
    runner.reset()
    for _ in range(10):
        runner.cycle()
    assert times == sorted(times) and len(times) == 20
    assert times[-1] == pytest.approx(0.4)


def test_reset_over_rosbridge_answers_with_the_clock_at_zero(lockstep_app: SimApp) -> None:
    assert lockstep_app.rosbridge is not None
    client = Client.of(lockstep_app.rosbridge)
    try:
        assert client.call("/sim/step", {"steps": 25})["values"]["status"]["time"] == pytest.approx(0.5)
        status = client.call("/sim/reset")["values"]["status"]
        assert status["time"] == 0.0 and status["world_time"] == 0.0
        client.send({"op": "subscribe", "id": "c", "topic": "/clock", "type": "rosgraph_msgs/msg/Clock"})
        # sent, not called: the reply's wait would drop the /clock message that comes first
        client.send({"op": "call_service", "id": "one", "service": "/sim/step", "args": {"steps": 1}})
        clock = client.recv_until(lambda m: m.get("topic") == "/clock", timeout=30)
        assert clock["msg"]["clock"] == {"sec": 0, "nanosec": 20_000_000}
    finally:
        client.close()


def test_a_recording_across_a_reset_keeps_its_time_going_forward(toast_app_dir: Path, tmp_path: Path) -> None:
    """The recorder stamps with the elapsed time: a player sees one run after the other, while the
    recorded /clock shows the application's clock starting at 0 again."""
    from mcap.reader import make_reader
    from mcap_ros2.decoder import DecoderFactory

    target = tmp_path / "reset.mcap"
    app = SimApp(
        RunOptions(
            package=toast_app_dir, mode="lockstep", rosbridge_port=None, viser_port=None, paused=True, record=target
        )
    )
    app.start()
    try:
        assert app.runner is not None
        app.runner.step(10)
        app.runner.reset()
        app.runner.step(10)
    finally:
        app.stop()
    log_times: dict[str, list[int]] = {}
    clocks: list[int] = []
    with target.open("rb") as stream:
        reader = make_reader(stream, decoder_factories=[DecoderFactory()])
        for _schema, channel, message, msg in reader.iter_decoded_messages(log_time_order=False):
            log_times.setdefault(channel.topic, []).append(message.log_time)
            if channel.topic == "/clock":
                clocks.append(msg.clock.sec * 1_000_000_000 + msg.clock.nanosec)
    for topic, times in log_times.items():
        assert times == sorted(times), topic
    assert log_times["/sim/scene"][-1] == 400_000_000  # 20 periods of 20 ms
    assert clocks[9] == 200_000_000 and clocks[10] == 20_000_000  # the application's clock restarted


# ------------------------------------------------------------------------------ last values


def test_a_late_subscriber_gets_the_last_value_of_a_port_at_once(lockstep_app: SimApp) -> None:
    """The run is paused after a step: nothing flows, yet the port's value sent in the step shows."""
    assert lockstep_app.rosbridge is not None and lockstep_app.runner is not None
    client = Client.of(lockstep_app.rosbridge)
    try:
        client.call("/sim/step", {"steps": 1})  # the controller's first slice writes its arm command
        sent = lockstep_app.runner.last_values.get(PORT_TOPIC)
        assert sent is not None
        assert subscribe_and_collect(client, PORT_TOPIC) == [sent]
    finally:
        client.close()


def test_no_value_before_the_first_slice_nor_after_a_reset(lockstep_app: SimApp) -> None:
    """Nothing was sent yet (or the reset started a fresh run): the late subscriber gets nothing
    rather than a made-up or stale value; a topic the application never writes gets nothing."""
    assert lockstep_app.rosbridge is not None
    first, second, third = (Client.of(lockstep_app.rosbridge) for _ in range(3))
    try:
        assert subscribe_and_collect(first, PORT_TOPIC) == []
        second.call("/sim/step", {"steps": 1})
        second.call("/sim/reset")
        assert subscribe_and_collect(second, PORT_TOPIC) == []
        assert subscribe_and_collect(third, "/toast/no_such_port") == []
    finally:
        for c in (first, second, third):
            c.close()


# ------------------------------------------------------------------------------ viser's controls


def test_the_viser_controls_flag() -> None:
    parser = build_parser()
    assert parser.parse_args(["run", "--package", "x"]).viser_controls == "on"
    assert parser.parse_args(["run", "--package", "x", "--viser-controls", "off"]).viser_controls == "off"
    with pytest.raises(SystemExit):
        parser.parse_args(["run", "--package", "x", "--viser-controls", "maybe"])
