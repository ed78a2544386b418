"""One rclpy node per atomic component instance, wrapping its behavior class.

Semantics (docs/generating-ros2.md, "Time and messages"):

- the node's time slice is one period of its clock (parameter ``period``, default 0.02 s;
  with ``use_sim_time`` the simulator's ``/clock`` drives it);
- a ``sync`` behavior steps once per period. An in port of a primitive type is *sampled*: the
  behavior sees the latest value received so far (sensor data is published every period, but
  node timers are not phase-aligned, so a slice may see none or two of them). Every other in
  port is an *event*: the behavior sees the last message received during the period, or
  ``None`` (commands and status changes must not be seen twice). A sync behavior takes its
  first step once every sampled port has received a value (sensor data that is not there yet
  is no reading of 0);
- ``timed``/``untimed`` behaviors get ``on_message`` per message, in arrival order, and
  ``on_tick`` at the end of every period;
- a ``<<delayed>>`` out port publishes what the behavior emitted in one period at the start of
  the next one (after the initial outputs, which are published at once);
- writing a port twice in a period publishes two messages.
"""

from __future__ import annotations

import contextlib
import json
import sys
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass
from typing import Any, ClassVar

import rclpy
from maa_behavior import Behavior, Emit
from maa_behavior.robotarm import Arm, RobotArmExecutor
from maa_ros2.arm import RosArm
from maa_ros2.ports import PortCodec
from rclpy.executors import ExternalShutdownException
from rclpy.node import Node
from rclpy.qos import DurabilityPolicy, HistoryPolicy, QoSProfile, ReliabilityPolicy
from std_msgs.msg import String

#: QoS of every port topic: reliable delivery, volatile, the last 10 messages per topic kept.
#: Events (commands, status changes) must not be lost; volatile keeps a restarted node from
#: receiving stale commands. It matches the simulator's publishers and subscribers (rclpy's
#: default profile), so platform topics and port topics mix freely.
PORT_QOS = QoSProfile(history=HistoryPolicy.KEEP_LAST, depth=10, reliability=ReliabilityPolicy.RELIABLE)

DEFAULT_PERIOD = 0.02

#: Where every node with an automaton publishes its current state (docs/ide.md, "Live values"):
#: std_msgs/String, data = JSON ``{"<node name>": "<state path>"}`` (one key per message), in the
#: first period and in every period in which the state changed. Transient-local (the last message
#: of each node is kept for subscribers that ask for it) and reliable. The mode manager of a mode
#: component publishes the component's current mode the same way, under the instance's node path
#: (the manager's namespace).
STATES_TOPIC = "/maa/automaton_states"
STATES_QOS = QoSProfile(
    history=HistoryPolicy.KEEP_LAST,
    depth=1,
    reliability=ReliabilityPolicy.RELIABLE,
    durability=DurabilityPolicy.TRANSIENT_LOCAL,
)


#: The transitions taken and the RobotArm statements started (docs/generating-ros2.md, "Traces"):
#: std_msgs/String, data = JSON ``{"node", "from", "to", "index"}`` and ``{"node", "program", "step",
#: "line", "text", "file"}``, one message per event in the period it happens; reliable and volatile.
TRANSITIONS_TOPIC = "/maa/transitions"
PROGRAM_STEPS_TOPIC = "/maa/program_steps"
EVENTS_QOS = QoSProfile(history=HistoryPolicy.KEEP_LAST, depth=100, reliability=ReliabilityPolicy.RELIABLE)


def json_message(data: Mapping[str, object]) -> String:
    """A std_msgs/String with ``data`` as JSON."""
    msg = String()
    msg.data = json.dumps(data)
    return msg


def transition_publisher(owner: Node, node: str) -> Callable[[int, str, str], None]:
    """A publisher of :data:`TRANSITIONS_TOPIC` on ``owner`` as a transition hook ``(index, source, target)``:
    the transitions taken by the automaton (or mode automaton) of the instance at node path ``node``."""
    transitions = owner.create_publisher(String, TRANSITIONS_TOPIC, EVENTS_QOS)

    def taken(index: int, source: str, target: str) -> None:
        transitions.publish(json_message({"node": node, "from": source, "to": target, "index": index}))

    return taken


def state_message(node: str, state: str) -> String:
    """A message of :data:`STATES_TOPIC`: the state path (or mode) of the instance at node path ``node``."""
    msg = String()
    msg.data = json.dumps({node: state})
    return msg


@dataclass(frozen=True)
class InPort:
    port: str
    topic: str
    codec: PortCodec
    sampled: bool = False


@dataclass(frozen=True)
class OutPort:
    port: str
    topic: str
    codec: PortCodec
    delayed: bool = False


#: QoS of a mode topic (docs/generating-ros2.md, "Mode automata"): std_msgs/String with the current
#: mode, latched (transient-local, the last message kept) so that a node started late learns it.
MODE_QOS = QoSProfile(
    history=HistoryPolicy.KEEP_LAST,
    depth=1,
    reliability=ReliabilityPolicy.RELIABLE,
    durability=DurabilityPolicy.TRANSIENT_LOCAL,
)


@dataclass(frozen=True)
class ModeGate:
    """A node of a subcomponent declared in modes: active only while the mode on ``topic`` is one of ``modes``."""

    topic: str
    modes: tuple[str, ...]
    initial: str


class PlatformBehavior(Behavior):
    """Base class of handwritten (platform) components on ROS 2.

    Besides the behavior interface, a platform component gets its node in :meth:`attach` and
    may create publishers and subscriptions of platform topics there (sensors, actuators).
    ``SUBSCRIBES`` and ``PUBLISHES`` name those topics with their ROS 2 types
    (``{"/sensors/distance": "std_msgs/msg/Int32"}``): the generator copies them into
    ``deployment.json``, so keep them in step with what :meth:`attach` creates.
    """

    SUBSCRIBES: ClassVar[dict[str, str]] = {}
    PUBLISHES: ClassVar[dict[str, str]] = {}

    def attach(self, node: Node) -> None:
        """Creates the platform topics' publishers and subscriptions on ``node``."""


ParameterValue = bool | int | float | str | list[bool] | list[int] | list[float] | list[str]


class ComponentNode(Node):
    """An rclpy node that runs one behavior class on port topics."""

    def __init__(
        self,
        name: str,
        behavior_type: Callable[[Emit, Mapping[str, object]], Behavior],
        inputs: Sequence[InPort],
        outputs: Sequence[OutPort],
        parameters: Mapping[str, ParameterValue] | None = None,
        period: float = DEFAULT_PERIOD,
        convert_parameters: Callable[[dict[str, object]], dict[str, object]] | None = None,
        gates: Sequence[ModeGate] = (),
    ) -> None:
        super().__init__(name)
        # the modes of the enclosing mode components: the node rests (does not step, publishes
        # nothing) while one of them is not its mode; what arrives meanwhile waits for its mode
        # (a relay forwards only in the mode, but its message may overtake the mode's)
        self._maa_modes = {g.topic: g.initial for g in gates}
        self._maa_gates = tuple(gates)
        for g in gates:
            self.create_subscription(String, g.topic, self._mode_receiver(g.topic), MODE_QOS)
        values: dict[str, object] = {}
        for key, default in (parameters or {}).items():
            values[key] = self.declare_parameter(key, default).value
        if convert_parameters is not None:
            values = convert_parameters(values)
        self.period = float(self.declare_parameter("period", period).value)
        self._maa_inputs = {p.port: p for p in inputs}
        self._maa_outputs = {p.port: p for p in outputs}
        self._maa_publishers = {p.port: self.create_publisher(p.codec.msg_type, p.topic, PORT_QOS) for p in outputs}
        self._maa_held: dict[str, object] = {}
        self._maa_events: dict[str, object] = {}
        self._maa_queued: list[tuple[str, object]] = []
        self._maa_pending: list[tuple[str, object]] = []
        self._maa_delay_passed = False
        self.behavior = behavior_type(self._emit, values)
        self.behavior.set_delay_hook(self._pass_delay_point)
        for p in inputs:
            self.create_subscription(p.codec.msg_type, p.topic, self._receiver(p), PORT_QOS)
        if isinstance(self.behavior, PlatformBehavior):
            self.behavior.attach(self)
        if isinstance(getattr(self.behavior, "arm", None), Arm):
            # a RobotArm executor: its arm is the simulator's (or robot driver's) on ROS 2
            self.behavior.arm = RosArm(self, PORT_QOS)  # type: ignore[attr-defined]
        self._trace_events()
        self.behavior.start()
        self._maa_delay_passed = True
        self._maa_state: str | None = None
        self._maa_state_publisher = (
            self.create_publisher(String, STATES_TOPIC, STATES_QOS) if self.behavior.state_path() is not None else None
        )
        self.slice_timer = self.create_timer(self.period, self._on_period)

    def _trace_events(self) -> None:
        """Publishes the automaton's transitions and the RobotArm program's steps as they happen."""
        node = self.get_fully_qualified_name()
        if getattr(type(self.behavior), "_PARENT", None) is not None:
            self.behavior.set_transition_hook(transition_publisher(self, node))
        arm = self.behavior
        if isinstance(arm, RobotArmExecutor):
            steps = self.create_publisher(String, PROGRAM_STEPS_TOPIC, EVENTS_QOS)

            def started(program: str, step: int, line: int, text: str) -> None:
                data = {"node": node, "program": program, "step": step, "line": line, "text": text, "file": arm.FILE}
                steps.publish(json_message(data))

            arm.set_step_hook(started)

    # -- modes ------------------------------------------------------------------------------
    def active(self) -> bool:
        """Whether every enclosing mode component is in a mode this node belongs to."""
        return all(self._maa_modes[g.topic] in g.modes for g in self._maa_gates)

    def _mode_receiver(self, topic: str) -> Callable[[Any], None]:
        def receive(msg: Any) -> None:
            self._maa_modes[topic] = str(msg.data)
            if self.active():
                pending, self._maa_pending = self._maa_pending, []
                for port, value in pending:
                    self.behavior.on_message(port, value)

        return receive

    # -- messages ---------------------------------------------------------------------------
    def _receiver(self, port: InPort) -> Callable[[Any], None]:
        def receive(msg: Any) -> None:
            value = port.codec.from_msg(msg)
            if self.behavior.TIMING == "sync":
                if port.sampled:
                    self._maa_held[port.port] = value
                else:
                    self._maa_events[port.port] = value
            elif not self.active():
                self._maa_pending.append((port.port, value))
            else:
                self.behavior.on_message(port.port, value)

        return receive

    def _emit(self, port: str, value: object) -> None:
        out = self._maa_outputs.get(port)
        if out is None:
            raise KeyError(f"{self.get_name()}: the behavior emitted on {port!r}, which is no out port")
        if not self.active():
            return
        if out.delayed and self._maa_delay_passed:
            self._maa_queued.append((port, value))
        else:
            self._publish(port, value)

    def _publish(self, port: str, value: object) -> None:
        self._maa_publishers[port].publish(self._maa_outputs[port].codec.to_msg(value))

    def _pass_delay_point(self) -> None:
        self._maa_delay_passed = True

    # -- time -------------------------------------------------------------------------------
    def _on_period(self) -> None:
        if not self.active():
            return
        queued, self._maa_queued = self._maa_queued, []
        for name, value in queued:
            self._publish(name, value)
        if self.behavior.TIMING == "sync":
            if any(spec.sampled and name not in self._maa_held for name, spec in self._maa_inputs.items()):
                self._publish_state()  # the initial state, before the first step
                return  # not started: a data port has not received its first value yet
            inputs: dict[str, object] = {}
            for name, spec in self._maa_inputs.items():
                inputs[name] = self._maa_held.get(name) if spec.sampled else self._maa_events.get(name)
            self._maa_events.clear()
            self.behavior.step(inputs)
        else:
            self.behavior.on_tick()
        self._publish_state()

    def _publish_state(self) -> None:
        """The automaton's state on STATES_TOPIC, in the first period and whenever it changed."""
        if self._maa_state_publisher is None:
            return
        state = self.behavior.state_path()
        if state is None or state == self._maa_state:
            return
        self._maa_state = state
        self._maa_state_publisher.publish(state_message(self.get_fully_qualified_name(), state))


def run_node(factory: Callable[[], Node], args: Sequence[str] | None = None) -> None:
    """``main()`` of a generated node: init rclpy, spin until shutdown, clean up."""
    rclpy.init(args=list(sys.argv if args is None else args))
    node = factory()
    try:
        rclpy.spin(node)
    except (KeyboardInterrupt, ExternalShutdownException):
        pass
    finally:
        node.destroy_node()
        with contextlib.suppress(Exception):
            rclpy.try_shutdown()
