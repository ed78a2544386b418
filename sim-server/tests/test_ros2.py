"""ROS 2 mode with real rclpy processes: the toast ends on the plate; failures are reported; shutdown is clean."""

from __future__ import annotations

import json
import os
import signal
import subprocess
import sys
import time
from pathlib import Path

import pytest
from rosbridge_client import Client

from maa_sim.app import RunOptions, SimApp
from maa_sim.ros2 import DomainLease

SIM_SERVER = Path(__file__).resolve().parent.parent

#: Simulated seconds the toast run may take (it needs about 35), and wall seconds to wait for it.
GOAL_SIM_TIME = 120.0
WALL_TIMEOUT = 600.0


def test_domain_leases_are_distinct() -> None:
    a, b = DomainLease(), DomainLease()
    try:
        assert a.domain_id != b.domain_id
        assert 1 <= a.domain_id <= 100
    finally:
        a.release()
        b.release()


def test_toast_ends_on_the_plate_with_real_nodes(toast_app_dir: Path) -> None:
    app = SimApp(
        RunOptions(
            package=toast_app_dir,
            mode="ros2",
            # Real time and a simulated bound far above the ~35 s the toast takes: the simulated
            # clock does not wait for the rclpy nodes, which lag on a machine with every core
            # busy (at speed 3 and a 40 s bound the run once ended at the limit there). The run
            # ends at the goal, so the bound costs no time.
            speed=1.0,
            rosbridge_port=0,
            viser_port=None,
            until_goal=True,
            max_sim_time=GOAL_SIM_TIME,
            paused=True,
        )
    )
    app.start()
    try:
        assert app.supervisor is not None and app.rosbridge is not None
        assert [n["state"] for n in app.supervisor.statuses()] == ["running", "running"]
        client = Client.of(app.rosbridge)
        # a port topic between two generated nodes, seen through rosbridge
        client.send({"op": "subscribe", "topic": "/toast/arm/status", "type": "std_msgs/msg/String"})
        time.sleep(1.0)  # let the new subscription match the arm node's publisher
        assert client.call("/sim/resume")["result"] is True
        assert app.wait(timeout=WALL_TIMEOUT), "the run did not finish"
        assert app.runner is not None
        assert app.runner.finish_reason == "goal reached", app.status()
        assert app.session is not None and app.session.world.toast_on_plate()
        assert app.session.world.time < GOAL_SIM_TIME
        statuses = []
        while True:
            try:
                message = client.recv(timeout=0.5)
            except TimeoutError:
                break
            if message.get("topic") == "/toast/arm/status":
                statuses.append(message["msg"]["data"])
        assert [s for s in statuses if s != "IDLE"][:3] == ["BUSY", "DONE", "BUSY"], statuses  # FETCH, DELIVER
        topics = client.call("rosapi/topics")["values"]["topics"]
        assert {"/clock", "/joint_states", "/toast/ctrl/arm", "/toast/arm/status"} <= set(topics)
        nodes = client.call("rosapi/nodes")["values"]["nodes"]
        assert {"/toast/ctrl", "/toast/arm", "/maa_sim"} <= set(nodes)
        client.close()
        # a client that subscribes now (the run is over, nothing flows) gets the port's last value at once
        late = Client.of(app.rosbridge)
        late.send({"op": "subscribe", "topic": "/toast/ctrl/arm", "type": "std_msgs/msg/String"})
        last = late.recv_until(lambda m: m.get("topic") == "/toast/ctrl/arm", timeout=30)
        assert last["msg"] == app.runner.last_values.get("/toast/ctrl/arm") is not None
        late.close()
    finally:
        app.stop()
    assert app.supervisor is not None
    for process in app.supervisor.processes:
        assert process.process.poll() is not None


def test_crashed_and_hung_nodes_are_reported(faulty_app_dir: Path) -> None:
    app = SimApp(
        RunOptions(
            package=faulty_app_dir,
            mode="ros2",
            speed=1.0,
            rosbridge_port=0,
            viser_port=None,
            hang_timeout=5.0,
            startup_timeout=20.0,
        )
    )
    app.start()
    try:
        assert app.rosbridge is not None and app.supervisor is not None
        client = Client.of(app.rosbridge)
        deadline = time.monotonic() + 30
        states: dict[str, str] = {}
        while time.monotonic() < deadline:
            states = {n["name"]: n["state"] for n in app.supervisor.statuses()}
            settled = states.get("/faulty/forgetful") not in (None, "starting")
            if states.get("/faulty/crasher") == "crashed" and states.get("/faulty/hanger") == "hung" and settled:
                break
            time.sleep(0.2)
        assert states == {
            "/faulty/echo": "running",
            "/faulty/crasher": "crashed",
            "/faulty/hanger": "hung",
            # lost the answer to its first probe: the next probe finds it alive
            "/faulty/forgetful": "running",
        }
        events = [e for e in app.session.events if e.level == "error"] if app.session else []
        crash = next(e for e in events if e.source == "/faulty/crasher")
        assert "simulated failure in the crasher node" in crash.details["stderr_tail"]
        assert "exit code 1" in crash.message
        hang = next(e for e in events if e.source == "/faulty/hanger")
        assert "hangs" in hang.message or "did not come up" in hang.message
        assert "blocking in a timer callback" in hang.details["stderr_tail"]
        forgetful = next(p for p in app.supervisor.processes if p.spec.fqn == "/faulty/forgetful")
        assert "leaving probe 1 unanswered" in forgetful.tail()
        # the simulation keeps serving: time advances, the healthy node still echoes
        status = client.call("/sim/get_status")["values"]
        time.sleep(0.5)
        assert client.call("/sim/get_status")["values"]["time"] > status["time"]
        client.send({"op": "subscribe", "topic": "/faulty/echo", "type": "std_msgs/msg/Int32"})
        echo = client.recv_until(lambda m: m.get("topic") == "/faulty/echo", timeout=10)
        assert echo["msg"]["data"] < 25
        client.close()
    finally:
        app.stop()


def _alive(pid: int) -> bool:
    try:
        with open(f"/proc/{pid}/stat") as f:
            return f.read().split()[2] != "Z"
    except FileNotFoundError:
        return False


@pytest.mark.parametrize("sig", [signal.SIGTERM, signal.SIGINT])
def test_signal_stops_every_child(toast_app_dir: Path, sig: signal.Signals) -> None:
    command = [
        sys.executable,
        "-m",
        "maa_sim.cli",
        "run",
        "--package",
        str(toast_app_dir),
        "--mode",
        "ros2",
        "--rosbridge-port",
        "0",
        "--viser-port",
        "0",
        "--status-json",
    ]
    process = subprocess.Popen(command, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, cwd=SIM_SERVER)
    try:
        assert process.stdout is not None
        line = process.stdout.readline()
        ready = json.loads(line)
        assert ready["event"] == "ready", line
        pids = [n["pid"] for n in ready["nodes"]]
        assert len(pids) == 2 and all(_alive(p) for p in pids)
        time.sleep(1.0)
        process.send_signal(sig)
        process.wait(timeout=20)
        assert process.returncode == 0, process.stderr.read() if process.stderr else ""
        deadline = time.monotonic() + 5
        while any(_alive(p) for p in pids) and time.monotonic() < deadline:
            time.sleep(0.1)
        assert not any(_alive(p) for p in pids)
    finally:
        if process.poll() is None:
            process.kill()
            process.wait()


def test_nodes_die_with_a_killed_simulator(toast_app_dir: Path) -> None:
    command = [
        sys.executable, "-m", "maa_sim.cli", "run", "--package", str(toast_app_dir), "--mode", "ros2",
        "--rosbridge-port", "off", "--viser-port", "off", "--status-json",
    ]  # fmt: skip
    process = subprocess.Popen(command, stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, text=True, cwd=SIM_SERVER)
    pids: list[int] = []
    try:
        assert process.stdout is not None
        ready = json.loads(process.stdout.readline())
        pids = [n["pid"] for n in ready["nodes"]]
        assert all(_alive(p) for p in pids)
        process.kill()  # no chance to clean up
        process.wait(timeout=10)
        deadline = time.monotonic() + 5
        while any(_alive(p) for p in pids) and time.monotonic() < deadline:
            time.sleep(0.1)
        assert not any(_alive(p) for p in pids)
    finally:
        for pid in pids:
            if _alive(pid):
                os.kill(pid, signal.SIGKILL)


def test_reset_restarts_the_nodes_for_a_fresh_run(toast_app_dir: Path) -> None:
    app = SimApp(
        RunOptions(
            package=toast_app_dir,
            mode="ros2",
            speed=1.0,  # real time: the nodes lag the simulated clock when every core is busy
            rosbridge_port=0,
            viser_port=None,
            until_goal=True,
            max_sim_time=2 * GOAL_SIM_TIME,
            startup_timeout=60.0,
            hang_timeout=20.0,
        )
    )
    app.start()
    try:
        assert app.supervisor is not None and app.rosbridge is not None and app.session is not None
        old_pids = {n["name"]: n["pid"] for n in app.supervisor.statuses()}
        client = Client.of(app.rosbridge)
        # mid-run: the bread is in the toaster and browning, the controller waits for GOLDEN
        deadline = time.monotonic() + WALL_TIMEOUT
        while app.session.world.toast_level < 0.3 and time.monotonic() < deadline:
            time.sleep(0.05)
        assert app.session.world.toast_level >= 0.3, app.status()
        before = client.call("/sim/get_status")["values"]["time"]
        reply = client.call("/sim/reset", timeout=90)
        assert reply["result"] is True, reply
        assert "2 node(s) restarted" in reply["values"]["message"]
        nodes = {n["name"]: n for n in app.supervisor.statuses()}
        assert set(nodes) == set(old_pids)
        assert all(n["state"] == "running" for n in nodes.values()), nodes
        assert all(nodes[name]["pid"] != pid for name, pid in old_pids.items())
        for process in app.supervisor.processes:
            assert process.process.poll() is None
        status = reply["values"]["status"]
        assert status["time"] < before  # a fresh run: the clock starts at 0 again (the new nodes see it from 0)
        # a fresh run: the restarted controller starts from Idle and serves the toast again (with the old
        # state it would still wait in Toasting for a GOLDEN that never comes, the bread being back in its holder)
        assert app.wait(timeout=WALL_TIMEOUT), app.status()
        assert app.runner is not None and app.runner.finish_reason == "goal reached", app.status()
        assert app.session.world.toast_on_plate()
        assert app.session.world.time < GOAL_SIM_TIME  # counted from the reset
        client.close()
    finally:
        app.stop()
    for process in app.supervisor.processes:
        assert process.process.poll() is not None
