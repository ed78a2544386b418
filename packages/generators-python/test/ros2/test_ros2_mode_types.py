"""A mode component with an enum port and a class port on ROS 2 for real (the mode-types fixture, route.GearRouter).

The guards of its mode automaton read the enum port ``gear``; its modes route the class port ``s``: in gear LOW
the sample's value reaches ``o`` unchanged (``t1``), in gear HIGH scaled by 10 (``t10``) and the sample itself
reaches ``echo`` (``f``). The mode manager imports the generated message module (``import
gear_router_interfaces.msg``; the fault this test guards against rendered it as an empty ``from ... import``).

The interface package is built with the PyPI rosidl toolchain and installed into this venv (as the toast-service
test does); the ament_python package runs from its folder (deployment.json's ``python_path``).
"""

from __future__ import annotations

import os
import subprocess
import sys
import threading
import time
from collections.abc import Callable, Iterator
from pathlib import Path
from typing import Any

import pytest
from ros2_support import PACKAGE_DIR, RUFF_CONFIG, install_interfaces_command
from test_ros2_modes import generate_package
from test_ros2_toast_service import deployed_nodes

rclpy = pytest.importorskip("rclpy")

APP = PACKAGE_DIR / "test" / "fixtures" / "mode-types" / "GearRouter.arcapp"
PKG = "gear_router"
IFACE = f"{PKG}_interfaces"
ROOT = f"/{PKG}"
TIMEOUT = 30.0


@pytest.fixture(scope="module")
def package(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """The generated ament package, its interface package built and installed into this venv."""
    pytest.importorskip("rosidl_adapter", reason="needs the venv of scripts/setup_ros2_venv.sh")
    pkg = generate_package(APP, tmp_path_factory.mktemp("mode-types"), PKG)
    result = subprocess.run(
        install_interfaces_command(pkg.parent / IFACE),
        capture_output=True,
        text=True,
        check=False,
    )
    assert result.returncode == 0, (
        f"install_ros2_interfaces.sh failed:\n{result.stdout[-4000:]}\n{result.stderr[-4000:]}"
    )
    return pkg


def test_the_mode_manager_imports_the_message_module(package: Path) -> None:
    text = (package / PKG / "nodes" / "maa_modes.py").read_text(encoding="utf-8")
    assert f"import {IFACE}.msg\n" in text
    assert f"from {IFACE}.msg import" not in text
    known = f"lint.isort.known-third-party=['{PKG}','{IFACE}','maa_behavior','maa_ros2']"
    cmd = [sys.executable, "-m", "ruff", "check", "--no-cache", "--config", str(RUFF_CONFIG), "--config", known, "."]
    # from the platform folder, as test_generated_code.py runs it (in the package its launch/ folder is first-party)
    result = subprocess.run(cmd, cwd=package.parent, capture_output=True, text=True, check=False)
    assert result.returncode == 0, result.stdout + result.stderr


class Probe:
    """Publishes ``/clock`` (the nodes run on simulation time) and the in ports ``gear`` and ``s``; records
    ``o``, ``echo`` (as ``(value, gear ordinal)``) and the latched mode topic."""

    def __init__(self) -> None:
        from gear_router_interfaces.msg import Gear, Sample
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
        self.gear_type, self.sample_type, self.clock_type = Gear, Sample, Clock
        self.clock = self.node.create_publisher(Clock, "/clock", 10)
        self.sim_ns = 0
        self.gear = self.node.create_publisher(Gear, f"{ROOT}/gear", 10)
        self.sample = self.node.create_publisher(Sample, f"{ROOT}/s", 10)
        self.lock = threading.Lock()
        self.events: list[tuple[str, Any]] = []
        self.node.create_subscription(Int32, f"{ROOT}/o", self._recorder("o", lambda m: m.data), 10)
        echo = self._recorder("echo", lambda m: (m.value, m.gear.value))
        self.node.create_subscription(Sample, f"{ROOT}/echo", echo, 10)
        latched = QoSProfile(
            history=HistoryPolicy.KEEP_LAST,
            depth=1,
            reliability=ReliabilityPolicy.RELIABLE,
            durability=DurabilityPolicy.TRANSIENT_LOCAL,
        )
        mode = self._recorder("mode", lambda m: m.data)
        self.node.create_subscription(String, f"{ROOT}/maa_modes/mode", mode, latched)
        self.running = True
        self.thread = threading.Thread(target=self._loop, daemon=True)
        self.thread.start()

    def _recorder(self, name: str, value: Callable[[Any], Any]) -> Callable[[Any], None]:
        def record(msg: Any) -> None:
            with self.lock:
                self.events.append((name, value(msg)))

        return record

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

    def send(self, gear: int | None, value: int) -> None:
        """A message on ``gear`` (the ordinal; none if None) and a sample of ``value`` (in gear HIGH) on ``s``."""
        if gear is not None:
            self.gear.publish(self.gear_type(value=gear))
        self.sample.publish(self.sample_type(value=value, gear=self.gear_type(value=self.gear_type.HIGH)))

    def wait_for(self, name: str, value: Any, since: int = 0, resend: tuple[int | None, int] | None = None) -> None:
        """Waits for an event ``value`` on ``name`` after the first ``since`` events, sending ``resend`` again while
        waiting (port topics are volatile: a message sent before every subscription matched is lost)."""
        deadline = time.monotonic() + TIMEOUT
        while time.monotonic() < deadline:
            with self.lock:
                if (name, value) in self.events[since:]:
                    return
            if resend is not None:
                self.send(*resend)
            time.sleep(0.05)
        with self.lock:
            seen = self.events[-30:]
        raise AssertionError(f"no {name} = {value!r} within {TIMEOUT} s; last events: {seen}")

    def values(self, name: str, since: int = 0) -> list[Any]:
        with self.lock:
            return [v for n, v in self.events[since:] if n == name]

    def close(self) -> None:
        self.running = False
        self.thread.join(timeout=2)
        self.executor.shutdown(timeout_sec=1.0)
        self.node.destroy_node()
        rclpy.shutdown(context=self.context)


@pytest.fixture()
def probe(package: Path, ros_domain: int, tmp_path: Path) -> Iterator[Probe]:
    del ros_domain
    p = Probe()
    try:
        with deployed_nodes(package, tmp_path):
            yield p
    except AssertionError as exc:
        tails = "\n".join(f"--- {f.name}\n{f.read_text()[-1500:]}" for f in sorted(tmp_path.glob("*.log")))
        raise AssertionError(f"{exc}\n{tails}") from None
    finally:
        p.close()


def test_the_enum_port_switches_modes_and_the_class_port_is_routed(probe: Probe) -> None:
    low, high = probe.gear_type.LOW, probe.gear_type.HIGH
    # the initial mode Low: t1 scales the sample's value by 1, nothing reaches echo
    probe.wait_for("mode", "Low")
    probe.wait_for("o", 3, resend=(low, 3))
    # gear HIGH switches to High before the slice is relayed: t10 scales by 10, f forwards the sample to echo
    since = probe.mark()
    probe.wait_for("mode", "High", since, resend=(high, 4))
    probe.wait_for("o", 40, since, resend=(high, 4))
    probe.wait_for("echo", (4, high), since, resend=(high, 4))
    # a slice without a gear message keeps the mode
    since = probe.mark()
    probe.wait_for("o", 50, since, resend=(None, 5))
    # gear LOW switches back: t1's outputs reach o again, f's no longer reach echo
    since = probe.mark()
    probe.wait_for("mode", "Low", since, resend=(low, 6))
    probe.wait_for("o", 6, since, resend=(low, 6))
    since = probe.mark()
    probe.wait_for("o", 7, since, resend=(low, 7))
    assert set(probe.values("o", since)) <= {7}, f"only t1's outputs reach o in mode Low: {probe.values('o', since)}"
    assert probe.values("echo", since) == [], "f rests in mode Low"
