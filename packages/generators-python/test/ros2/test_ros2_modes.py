"""Mode automata on ROS 2 for real: the generated nodes of the modes fixture (gear.Gearbox) run as
rclpy processes; a mode switch changes which subcomponent's output reaches the out port ``o``.
The mode-params fixture (pick.SelectorPair) has two mode components whose guard reads an enum
parameter (``kind == Kind.FAST``): only the FAST instance switches.

The fixtures need no message package of their own (their ports are ``int``), so the generated
packages run from their folder (deployment.json's ``python_path``) without being built or installed.
"""

from __future__ import annotations

import contextlib
import json
import os
import threading
import time
from collections.abc import Iterator, Mapping
from pathlib import Path
from typing import Any

import pytest
from ros2_support import PACKAGE_DIR, maa_gen
from test_ros2_toast_service import deployed_nodes

rclpy = pytest.importorskip("rclpy")

MODES_APP = PACKAGE_DIR / "test" / "fixtures" / "modes" / "Modes.arcapp"
MODE_PARAMS_APP = PACKAGE_DIR / "test" / "fixtures" / "mode-params" / "SelectorPair.arcapp"
TIMEOUT = 30.0


class Probe:
    """Publishes ``/clock`` (the nodes run on simulation time), feeds the ``Int32`` topic ``speed`` and
    records what arrives on the ``Int32`` topics ``outputs`` and the (latched) mode topics ``modes``,
    each under its name."""

    def __init__(self, speed: str, outputs: Mapping[str, str], modes: Mapping[str, str]) -> None:
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
        self.speed = self.node.create_publisher(Int32, speed, 10)
        self.lock = threading.Lock()
        self.events: list[tuple[str, Any]] = []
        for name, topic in outputs.items():
            self.node.create_subscription(Int32, topic, self._recorder(name), 10)
        latched = QoSProfile(
            history=HistoryPolicy.KEEP_LAST,
            depth=1,
            reliability=ReliabilityPolicy.RELIABLE,
            durability=DurabilityPolicy.TRANSIENT_LOCAL,
        )
        for name, topic in modes.items():
            self.node.create_subscription(String, topic, self._recorder(name), latched)
        # the IDE's live states: every entry as the event "state <node path>". Every node latches its
        # own message on this one topic, so a late reader receives one per node at once: a reader
        # depth of 1 would keep only the last of them (as the simulator's reader, keep 10).
        states = QoSProfile(
            history=HistoryPolicy.KEEP_LAST,
            depth=10,
            reliability=ReliabilityPolicy.RELIABLE,
            durability=DurabilityPolicy.TRANSIENT_LOCAL,
        )
        self.node.create_subscription(String, "/maa/automaton_states", self._states, states)
        # the trace: every transition taken as the event "transition <node path>" with from, to, index
        events = QoSProfile(history=HistoryPolicy.KEEP_LAST, depth=100, reliability=ReliabilityPolicy.RELIABLE)
        self.node.create_subscription(String, "/maa/transitions", self._transition, events)
        self.running = True
        self.thread = threading.Thread(target=self._loop, daemon=True)
        self.thread.start()

    def _recorder(self, name: str) -> Any:
        return lambda m: self._event(name, m.data)

    def _states(self, msg: Any) -> None:
        for node, state in json.loads(msg.data).items():
            self._event(f"state {node}", state)

    def _transition(self, msg: Any) -> None:
        data = json.loads(msg.data)
        self._event(f"transition {data.pop('node')}", data)

    def _event(self, name: str, value: Any) -> None:
        with self.lock:
            self.events.append((name, value))

    def values(self, name: str, since: int = 0) -> list[Any]:
        """What arrived under ``name`` after the first ``since`` events."""
        with self.lock:
            return [v for n, v in self.events[since:] if n == name]

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
        """Waits for an event after the first ``since`` events with ``value`` (or one ``value`` accepts, if callable),
        publishing ``resend`` again while waiting: port topics are volatile, a message sent before every
        subscription matched is lost."""
        deadline = time.monotonic() + TIMEOUT
        while time.monotonic() < deadline:
            with self.lock:
                if any(n == name and (value(v) if callable(value) else v == value) for n, v in self.events[since:]):
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


def generate_package(app: Path, out: Path, name: str) -> Path:
    """The ament package ``name`` of ``app`` generated for rospython into ``out``."""
    result = maa_gen(["generate", str(app), "--platform", "rospython", "--out", str(out)])
    assert result.returncode == 0, f"maa-gen generate failed:\n{result.stdout}\n{result.stderr}"
    return out / "rospython" / name


@pytest.fixture(scope="module")
def package(tmp_path_factory: pytest.TempPathFactory) -> Path:
    return generate_package(MODES_APP, tmp_path_factory.mktemp("modes"), "gearbox")


@pytest.fixture(scope="module")
def selector_package(tmp_path_factory: pytest.TempPathFactory) -> Path:
    return generate_package(MODE_PARAMS_APP, tmp_path_factory.mktemp("mode-params"), "selector_pair")


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
    # the mode automaton is the root instance's automaton, under the manager's namespace
    (automaton,) = data["automata"]
    assert automaton["node"] == "/gearbox" and automaton["kind"] == "modes"
    assert [s["path"] for s in automaton["states"]] == ["First", "Second"]
    assert [(t["index"], t["from"], t["to"]) for t in automaton["transitions"]] == [
        (0, "First", "Second"),
        (1, "Second", "First"),
    ]
    publishers: dict[str, str] = {}
    for n in data["nodes"]:
        for t in n["publishes"]:
            assert t["topic"] not in publishers, f"{t['topic']} has two publishers"
            publishers[t["topic"]] = n["name"]


@contextlib.contextmanager
def probing(
    package: Path, log_dir: Path, speed: str, outputs: Mapping[str, str], modes: Mapping[str, str]
) -> Iterator[Probe]:
    """A probe on the deployed nodes of ``package`` while the block runs."""
    p = Probe(speed, outputs, modes)
    try:
        with deployed_nodes(package, log_dir):
            yield p
    finally:
        p.close()


@pytest.fixture()
def probe(package: Path, ros_domain: int, tmp_path: Path) -> Iterator[Probe]:
    del ros_domain
    with probing(
        package,
        tmp_path,
        "/gearbox/speed",
        {"o": "/gearbox/o", "total": "/gearbox/total"},
        {"mode": "/gearbox/maa_modes/mode"},
    ) as p:
        yield p


@pytest.fixture()
def selector_probe(selector_package: Path, ros_domain: int, tmp_path: Path) -> Iterator[Probe]:
    del ros_domain
    root = "/selector_pair"
    with probing(
        selector_package,
        tmp_path,
        f"{root}/speed",
        {"slow": f"{root}/a/o", "fast": f"{root}/b/o"},
        {"a": f"{root}/a/maa_modes/mode", "b": f"{root}/b/maa_modes/mode"},
    ) as p:
        yield p


def test_a_mode_switch_changes_which_subcomponent_reaches_the_out_port(probe: Probe) -> None:
    # the initial mode First: s1 scales by 1 and its output reaches o
    probe.wait_for("mode", "First")
    probe.wait_for("o", 3, resend=3)
    # a negative speed switches to Second before it is relayed: s10 scales by 10, t sums up
    since = probe.mark()
    probe.send(-1)
    probe.wait_for("mode", "Second", since)
    # the mode is the live state of the mode component's instance (the root: /gearbox), as the IDE reads it
    probe.wait_for("state /gearbox", "Second", since)
    # and its mode transition is the instance's transition, with its index in the automata table
    probe.wait_for("transition /gearbox", {"from": "First", "to": "Second", "index": 0}, since)
    # (resent: the relay to s10 carries its first message now, which is lost if its subscription
    # has not been matched yet on a loaded machine; more -1 keep the mode)
    probe.wait_for("o", -10, since, resend=-1)
    # t sums s10's outputs (its first may be lost as above): a total of some -10s
    probe.wait_for("total", lambda v: v < 0 and v % 10 == 0, since)
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
    after = probe.values("o", since)
    assert set(after) <= {0, 4}, f"only s1's outputs reach o in mode First: {after}"
    # the two switches are the only transitions taken: a message whose guard does not hold takes none
    assert probe.values("transition /gearbox") == [
        {"from": "First", "to": "Second", "index": 0},
        {"from": "Second", "to": "First", "index": 1},
    ]


def test_the_mode_managers_take_enum_parameters_as_the_nodes_do(selector_package: Path) -> None:
    data = json.loads((selector_package / "deployment.json").read_text(encoding="utf-8"))
    managers = {n["namespace"]: n for n in data["nodes"] if n["name"] == "maa_modes"}
    # Kind.SLOW and Kind.FAST by ordinal, as every node's enum parameters
    assert managers["/selector_pair/a"]["parameters"] == {"kind": 0}
    assert managers["/selector_pair/b"]["parameters"] == {"kind": 1}


def test_a_guard_over_an_enum_parameter_switches_only_the_fast_instance(selector_probe: Probe) -> None:
    probe = selector_probe
    probe.wait_for("a", "Slow")
    probe.wait_for("b", "Slow")
    # a positive input: b (kind FAST) switches to Fast before relaying, a (kind SLOW) stays in Slow
    probe.wait_for("fast", 20, resend=2)
    probe.wait_for("b", "Fast")
    probe.wait_for("state /selector_pair/b", "Fast")
    # a's subscription may match after b's: the input is resent until a relayed it too
    probe.wait_for("slow", 2, resend=2)
    since = probe.mark()
    probe.send(3)
    probe.wait_for("fast", 30, since)
    probe.wait_for("slow", 3, since)
    # zero switches b back
    since = probe.mark()
    probe.send(0)
    probe.wait_for("b", "Slow", since)
    probe.wait_for("fast", 0, since, resend=0)  # b's relay to g1 carries its first message (resent as above)
    assert probe.values("a") == ["Slow"], f"the SLOW selector never leaves its first mode: {probe.values('a')}"
    assert probe.values("state /selector_pair/a") == ["Slow"]
