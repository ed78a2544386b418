"""Mode automata on ROS 2 for real: the generated nodes of the modes fixture (gear.Gearbox) run as
rclpy processes; a mode switch changes which subcomponent's output reaches the out port ``o``.

The fixture needs no message package of its own (its ports are ``int``), so the generated package
runs from its folder (deployment.json's ``python_path``) without being built or installed.
"""

from __future__ import annotations

import json
import os
import subprocess
import threading
import time
from collections.abc import Iterator
from pathlib import Path
from typing import Any

import pytest
from ros2_support import MAA_GEN, PACKAGE_DIR
from test_ros2_toast_service import deployed_nodes

rclpy = pytest.importorskip("rclpy")

MODES_APP = PACKAGE_DIR / "test" / "fixtures" / "modes" / "Modes.arcapp"
TIMEOUT = 30.0


class Probe:
    """Publishes ``/clock`` (the nodes run on simulation time), feeds ``/gearbox/speed`` and records
    what arrives on the out ports and the mode topic."""

    def __init__(self) -> None:
        from rclpy.executors import SingleThreadedExecutor
        from rclpy.node import Node
        from rclpy.qos import DurabilityPolicy, HistoryPolicy, QoSProfile, ReliabilityPolicy
        from rosgraph_msgs.msg import Clock
        from std_msgs.msg import Int32, String

        self.context = rclpy.Context()
        rclpy.init(context=self.context, domain_id=int(os.environ["ROS_DOMAIN_ID"]))
        self.node = Node("probe", context=self.context)
        self.executor = SingleThreadedExecutor(context=self.context)
        self.executor.add_node(self.node)
        self.int32 = Int32
        self.clock_type = Clock
        self.clock = self.node.create_publisher(Clock, "/clock", 10)
        self.sim_ns = 0
        self.speed = self.node.create_publisher(Int32, "/gearbox/speed", 10)
        self.lock = threading.Lock()
        self.events: list[tuple[str, Any]] = []
        self.node.create_subscription(Int32, "/gearbox/o", lambda m: self._event("o", m.data), 10)
        self.node.create_subscription(Int32, "/gearbox/total", lambda m: self._event("total", m.data), 10)
        latched = QoSProfile(history=HistoryPolicy.KEEP_LAST, depth=1, reliability=ReliabilityPolicy.RELIABLE,
                             durability=DurabilityPolicy.TRANSIENT_LOCAL)
        self.node.create_subscription(String, "/gearbox/maa_modes/mode", lambda m: self._event("mode", m.data), latched)
        self.running = True
        self.thread = threading.Thread(target=self._loop, daemon=True)
        self.thread.start()

    def _event(self, name: str, value: Any) -> None:
        with self.lock:
            self.events.append((name, value))

    def _loop(self) -> None:
        period = 0.02
        next_tick = time.monotonic()
        while self.running and self.context.ok():
            self.executor.spin_once(timeout_sec=0.002)
            now = time.monotonic()
            if now < next_tick:
                continue
            next_tick = now + period
            self.sim_ns += int(period * 1e9)
            clock = self.clock_type()
            clock.clock.sec, clock.clock.nanosec = divmod(self.sim_ns, 1_000_000_000)
            self.clock.publish(clock)

    def mark(self) -> int:
        with self.lock:
            return len(self.events)

    def send(self, value: int) -> None:
        self.speed.publish(self.int32(data=value))

    def wait_for(self, name: str, value: Any, since: int = 0, resend: int | None = None) -> None:
        """Waits for an event after the first ``since`` events (publishing ``resend`` again while waiting:
        port topics are volatile, a message sent before every subscription matched is lost)."""
        deadline = time.monotonic() + TIMEOUT
        while time.monotonic() < deadline:
            with self.lock:
                if any(n == name and v == value for n, v in self.events[since:]):
                    return
            if resend is not None:
                self.send(resend)
            time.sleep(0.05)
        with self.lock:
            seen = self.events[-30:]
        raise AssertionError(f"no {name} = {value!r} within {TIMEOUT} s; last events: {seen}")

    def close(self) -> None:
        self.running = False
        self.thread.join(timeout=2)
        self.executor.shutdown(timeout_sec=1.0)
        self.node.destroy_node()
        rclpy.shutdown(context=self.context)


@pytest.fixture(scope="module")
def package(tmp_path_factory: pytest.TempPathFactory) -> Path:
    out = tmp_path_factory.mktemp("modes")
    result = subprocess.run(
        ["node", str(MAA_GEN), "generate", str(MODES_APP), "--platform", "rospython", "--out", str(out)],
        capture_output=True,
        text=True,
        check=False,
    )
    assert result.returncode == 0, f"maa-gen generate failed:\n{result.stdout}\n{result.stderr}"
    return out / "rospython" / "gearbox"


def test_deployment_has_a_mode_manager_and_gated_nodes(package: Path) -> None:
    data = json.loads((package / "deployment.json").read_text(encoding="utf-8"))
    names = {n["name"]: n for n in data["nodes"]}
    assert sorted(names) == ["maa_modes", "s1", "s10", "t"]
    manager = names["maa_modes"]
    assert manager["namespace"] == "/gearbox"
    assert {"topic": "/gearbox/maa_modes/mode", "type": "std_msgs/msg/String"} in manager["publishes"]
    assert {"port": "o", "topic": "/gearbox/o", "type": "std_msgs/msg/Int32"} in manager["publishes"]
    mode = {"topic": "/gearbox/maa_modes/mode", "type": "std_msgs/msg/String"}
    for n in ("s1", "s10", "t"):
        assert mode in names[n]["subscribes"]
    publishers: dict[str, str] = {}
    for n in data["nodes"]:
        for t in n["publishes"]:
            assert t["topic"] not in publishers, f"{t['topic']} has two publishers"
            publishers[t["topic"]] = n["name"]


@pytest.fixture()
def probe(package: Path, ros_domain: int, tmp_path: Path) -> Iterator[Probe]:
    del ros_domain
    p = Probe()
    try:
        with deployed_nodes(package, tmp_path):
            yield p
    finally:
        p.close()


def test_a_mode_switch_changes_which_subcomponent_reaches_the_out_port(probe: Probe) -> None:
    # the initial mode First: s1 scales by 1 and its output reaches o
    probe.wait_for("mode", "First")
    probe.wait_for("o", 3, resend=3)
    # a negative speed switches to Second before it is relayed: s10 scales by 10, t sums up
    since = probe.mark()
    probe.send(-1)
    probe.wait_for("mode", "Second", since)
    probe.wait_for("o", -10, since)
    probe.wait_for("total", -10, since)
    since = probe.mark()
    probe.send(2)
    probe.wait_for("o", 20, since)
    # zero switches back: s1's output reaches o again, s10's no longer does
    since = probe.mark()
    probe.send(0)
    probe.wait_for("mode", "First", since)
    probe.wait_for("o", 0, since)
    since = probe.mark()
    probe.send(4)
    probe.wait_for("o", 4, since)
    with probe.lock:
        after = [v for n, v in probe.events[since:] if n == "o"]
    assert set(after) <= {0, 4}, f"only s1's outputs reach o in mode First: {after}"
