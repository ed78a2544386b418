"""ROS 2 for real: the generated ToastServiceRobot nodes run as rclpy processes and do their job.

The interface package is built with the PyPI rosidl toolchain (cmake, g++), the ament_python package
is installed into this venv, every node of deployment.json is started as sim-server starts it (own
ROS domain id, localhost discovery, ``use_sim_time``), and a test node plays the simulator: it
publishes ``/clock``, the sensor topics and ``/joint_states`` (following the arm's commands), and
watches the actuator topics.
"""

from __future__ import annotations

import contextlib
import json
import os
import signal
import subprocess
import sys
import threading
import time
from collections.abc import Callable, Iterator
from pathlib import Path
from typing import Any

import pytest
from ros2_support import IFACE, Installed

rclpy = pytest.importorskip("rclpy")

TIMEOUT = 30.0


class FakeSimulator:
    """The simulator's side of the topics of docs/simulation.md, with a perfectly obedient arm."""

    def __init__(self) -> None:
        from rclpy.executors import SingleThreadedExecutor
        from rclpy.node import Node
        from rosgraph_msgs.msg import Clock
        from sensor_msgs.msg import JointState
        from std_msgs.msg import Float64, Int32, String

        self.context = rclpy.Context()
        rclpy.init(context=self.context, domain_id=int(os.environ["ROS_DOMAIN_ID"]))
        self.node = Node("fake_sim", context=self.context)
        self.executor = SingleThreadedExecutor(context=self.context)
        self.executor.add_node(self.node)
        self.msg = {"Clock": Clock, "JointState": JointState, "Int32": Int32, "String": String}
        self.clock = self.node.create_publisher(Clock, "/clock", 10)
        self.distance = self.node.create_publisher(Int32, "/sensors/distance", 10)
        self.color = self.node.create_publisher(String, "/sensors/color", 10)
        self.joint_states = self.node.create_publisher(JointState, "/joint_states", 10)
        self.lock = threading.Lock()
        self.events: list[tuple[str, Any]] = []
        self.joints = {"base_yaw": 0.0, "lift": 0.30, "finger_inner": 0.03, "finger_outer": 0.03}
        self.sensor_distance = 290
        self.sensor_color = "WHITE"
        self.node.create_subscription(String, "/toaster/command", lambda m: self._event("toaster", m.data), 10)
        self.node.create_subscription(JointState, "/arm/joint_command", self._on_joint_command, 10)
        self.node.create_subscription(Float64, "/arm/gripper_command", self._on_gripper, 10)
        self.sim_ns = 0
        self.running = True
        self.thread = threading.Thread(target=self._loop, daemon=True)
        self.thread.start()

    def subscribe(self, topic: str, msg_type: Any, name: str, convert: Callable[[Any], Any]) -> None:
        self.node.create_subscription(msg_type, topic, lambda m: self._event(name, convert(m)), 10)

    def _event(self, name: str, value: Any) -> None:
        with self.lock:
            self.events.append((name, value))

    def _on_joint_command(self, msg: Any) -> None:
        with self.lock:
            for name, position in zip(msg.name, msg.position, strict=False):
                self.joints[name] = float(position)
        self._event("joints", dict(zip(msg.name, msg.position, strict=False)))

    def _on_gripper(self, msg: Any) -> None:
        with self.lock:
            self.joints["finger_inner"] = self.joints["finger_outer"] = float(msg.data) / 2
        self._event("gripper", float(msg.data))

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
            clock = self.msg["Clock"]()
            clock.clock.sec, clock.clock.nanosec = divmod(self.sim_ns, 1_000_000_000)
            self.clock.publish(clock)
            with self.lock:
                names, positions = list(self.joints), list(self.joints.values())
            state = self.msg["JointState"](name=names, position=positions, velocity=[0.0] * len(names))
            state.header.stamp = clock.clock
            self.joint_states.publish(state)
            self.distance.publish(self.msg["Int32"](data=self.sensor_distance))
            self.color.publish(self.msg["String"](data=self.sensor_color))

    def mark(self) -> int:
        with self.lock:
            return len(self.events)

    def wait_for(self, name: str, value: Any, since: int = 0, timeout: float = TIMEOUT) -> float:
        """Waits for an event (after the first ``since`` events); returns the seconds waited."""
        deadline = time.monotonic() + timeout
        start = time.monotonic()
        while time.monotonic() < deadline:
            with self.lock:
                if any(n == name and v == value for n, v in self.events[since:]):
                    return time.monotonic() - start
            time.sleep(0.02)
        with self.lock:
            seen = [e for e in self.events if e[0] != "joints"][-30:]
        raise AssertionError(f"no {name} = {value!r} within {timeout} s; last events: {seen}")

    def wait_graph(self, deployment: dict[str, Any], timeout: float = TIMEOUT) -> float:
        """Waits until every node is up and every port topic has its publisher and subscribers.

        As maa-sim does before it starts the clock: a command sent before its subscriber was
        matched is lost (port topics are volatile).
        """
        subscribers: dict[str, int] = {}
        for n in deployment["nodes"]:
            for t in n["subscribes"]:
                subscribers[t["topic"]] = subscribers.get(t["topic"], 0) + 1
        ports = [t["topic"] for n in deployment["nodes"] for t in n["publishes"] if "port" in t]
        start = time.monotonic()
        while time.monotonic() < start + timeout:
            names = {f"{ns.rstrip('/')}/{name}" for name, ns in self.node.get_node_names_and_namespaces()}
            nodes_up = all(f"{n['namespace'].rstrip('/')}/{n['name']}" in names for n in deployment["nodes"])
            matched = all(
                self.node.count_publishers(t) >= 1 and self.node.count_subscribers(t) >= subscribers.get(t, 0)
                for t in ports
            )
            if nodes_up and matched:
                time.sleep(0.5)  # the subscriptions' own matching completes
                return time.monotonic() - start
            time.sleep(0.05)
        raise AssertionError(f"the nodes did not come up within {timeout} s")

    def close(self) -> None:
        self.running = False
        self.thread.join(timeout=2)
        self.executor.shutdown(timeout_sec=1.0)
        self.node.destroy_node()
        rclpy.shutdown(context=self.context)


def start_nodes(package: Path, log_dir: Path) -> list[tuple[str, subprocess.Popen[bytes]]]:
    """Starts every node of deployment.json the way sim-server does; each with its log
    ``<namespace>.<name>.log`` (dots for slashes) in ``log_dir``, listed under that stem."""
    deployment = json.loads((package / "deployment.json").read_text(encoding="utf-8"))
    env = dict(os.environ)
    env["PYTHONUNBUFFERED"] = "1"
    env["PYTHONPATH"] = os.pathsep.join(str((package / p).resolve()) for p in deployment["python_path"])
    processes = []
    for n in deployment["nodes"]:
        fqn = f"{n['namespace'].rstrip('/')}/{n['name']}"
        # files named by the whole node name: two nodes may share a name in different namespaces
        stem = fqn.strip("/").replace("/", ".")
        params = log_dir / f"{stem}.params.yaml"
        params.write_text(json.dumps({fqn: {"ros__parameters": n["parameters"]}}), encoding="utf-8")
        log = (log_dir / f"{stem}.log").open("wb")
        cmd = [
            sys.executable,
            "-m",
            n["module"],
            *n["args"],
            "--ros-args",
            "-r",
            f"__node:={n['name']}",
            "-r",
            f"__ns:={n['namespace']}",
            "-p",
            "use_sim_time:=true",
            "--params-file",
            str(params),
        ]
        processes.append(
            (
                stem,
                subprocess.Popen(
                    cmd, cwd=package, env=env, stdout=log, stderr=subprocess.STDOUT, start_new_session=True
                ),
            )
        )
    return processes


@contextlib.contextmanager
def deployed_nodes(package: Path, log_dir: Path) -> Iterator[list[tuple[str, subprocess.Popen[bytes]]]]:
    """The nodes of deployment.json while the block runs: each must still run at its end (its log
    otherwise), and all are stopped afterwards (SIGINT to their sessions, SIGKILL after 5 s)."""
    processes = start_nodes(package, log_dir)
    try:
        yield processes
        for name, p in processes:
            assert p.poll() is None, f"node {name} ended with {p.returncode}:\n{(log_dir / f'{name}.log').read_text()}"
    finally:
        for _, p in processes:
            if p.poll() is None:
                os.killpg(p.pid, signal.SIGINT)
        for _, p in processes:
            try:
                p.wait(timeout=5)
            except subprocess.TimeoutExpired:
                os.killpg(p.pid, signal.SIGKILL)
                p.wait()


@pytest.fixture()
def running(installed: Installed, ros_domain: int, tmp_path: Path) -> Iterator[tuple[FakeSimulator, Path]]:
    del ros_domain
    sim = FakeSimulator()
    package = installed.generated.package
    from toast_service_robot_interfaces.msg import ArmProgram, ArmStatus, ToasterCmd  # built by `installed`

    sim.subscribe("/toast_service_robot/ctrl/arm", ArmProgram, "arm_cmd", lambda m: int(m.value))
    sim.subscribe("/toast_service_robot/arm/status", ArmStatus, "arm_status", lambda m: int(m.value))
    sim.subscribe("/toast_service_robot/ctrl/toaster", ToasterCmd, "toaster_cmd", lambda m: int(m.value))
    try:
        with deployed_nodes(package, tmp_path):
            up = sim.wait_graph(json.loads((package / "deployment.json").read_text(encoding="utf-8")))
            print(f"7 nodes up and matched after {up:.1f} s")
            yield sim, tmp_path
    finally:
        sim.close()


def test_installed_packages_import(installed: Installed) -> None:
    code = (
        f"from {IFACE}.msg import ArmProgram, ToastColor; "
        "from toast_service_robot.nodes.ctrl import create_node; "
        "assert ToastColor.GOLDEN == 1 and ArmProgram.PICKUP_AND_DEPLOY == 2"
    )
    result = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=False, cwd="/")
    assert result.returncode == 0, result.stderr
    print(f"interface package build {installed.build_seconds:.1f} s, pip install {installed.install_seconds:.1f} s")


def test_toast_service_nodes_serve_a_toast(running: tuple[FakeSimulator, Path]) -> None:
    sim, logs = running
    from toast_service_robot_interfaces.msg import ArmProgram, ArmStatus, ToasterCmd

    start = time.monotonic()
    try:
        # bread in the holder: the controller starts LoadBread, the arm runs it on the simulator's joints
        # until DONE; the controller starts the toaster: ToasterController holds the lever, the
        # ToasterActuator sends START
        sim.sensor_distance = 20
        breadbox = {"base_yaw": pytest.approx(0.0), "lift": pytest.approx(0.07)}
        stages = [
            ("arm_cmd", ArmProgram.LOAD_BREAD),
            ("gripper", pytest.approx(0.06)),
            ("joints", breadbox),
            ("arm_status", ArmStatus.DONE),
            ("toaster", "START"),
        ]
        times = [(f"{n}={v}", sim.wait_for(n, v)) for n, v in stages]
        # golden toast: the controller stops the toaster (the lever is released) and starts PickupAndDeploy
        sim.sensor_distance = 290
        golden = sim.mark()
        sim.sensor_color = "GOLDEN"
        stages = [
            ("toaster_cmd", ToasterCmd.STOP),
            ("toaster", "STOP"),
            ("arm_cmd", ArmProgram.PICKUP_AND_DEPLOY),
            ("arm_status", ArmStatus.BUSY),
        ]
        times += [(f"{n}={v}", sim.wait_for(n, v, golden)) for n, v in stages]
        print("stages (s after the previous one):", ", ".join(f"{n} {t:.1f}" for n, t in times))
    except AssertionError as exc:
        tails = "\n".join(f"--- {p.name}\n{p.read_text()[-1500:]}" for p in sorted(logs.glob("*.log")))
        raise AssertionError(f"{exc}\n{tails}") from None
    print(f"toast served in {time.monotonic() - start:.1f} s wall time")
