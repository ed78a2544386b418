"""The simulator's lock-step interface (``maa_sim.lockstep.LockstepController``) for a timesync build.

Each ``step(inputs)`` is one time slice of the architecture: handwritten platform components read
the simulator's messages of that instant through :func:`platform` and publish actuator messages
the same way; the result maps topic names to the messages published in the slice.
"""

from __future__ import annotations

import json
import math
from collections.abc import Callable, Mapping
from enum import Enum
from typing import Any

from maa_behavior.behavior import Behavior, TransitionHook
from maa_behavior.robotarm import Arm, RobotArmExecutor
from maa_timesync.modes import ModeInstance
from maa_timesync.runtime import TICK, ComponentType, System
from maa_timesync.streams import decode_value, encode_item

JsonMessage = dict[str, Any]


class Platform:
    """The simulator topics as seen by the platform components during one slice."""

    def __init__(self) -> None:
        self.inputs: dict[str, JsonMessage] = {}
        self.outbox: dict[str, list[JsonMessage]] = {}
        self.time = 0.0

    def latest(self, topic: str) -> JsonMessage | None:
        """The latest message of a simulator topic (``None`` before the first one)."""
        return self.inputs.get(topic)

    def publish(self, topic: str, message: JsonMessage) -> None:
        """Publishes a message on a topic in this slice."""
        self.outbox.setdefault(topic, []).append(message)


_PLATFORM = Platform()


def platform() -> Platform:
    """The platform of the running application (one per process)."""
    return _PLATFORM


class SimulatorArm(Arm):
    """The arm of the simulator: commands go to its topics, joint positions come from ``/joint_states``."""

    TOLERANCE_ANGLE = 0.02
    TOLERANCE_HEIGHT = 0.003
    TOLERANCE_GRIPPER = 0.004
    _still = 0  # periods the fingers have not moved while short of the target

    def command_joints(self, angle: float, height: float) -> None:
        super().command_joints(angle, height)
        _PLATFORM.publish("/arm/joint_command", {"name": ["base_yaw", "lift"], "position": [angle, height]})

    def command_gripper(self, opening: float) -> None:
        super().command_gripper(opening)
        _PLATFORM.publish("/arm/gripper_command", {"data": opening})

    def advance(self, dt: float) -> None:
        del dt
        msg = _PLATFORM.latest("/joint_states")
        if msg is None:
            return
        joints = dict(zip(msg.get("name", []), msg.get("position", []), strict=False))
        self.angle = float(joints.get("base_yaw", self.angle))
        self.height = float(joints.get("lift", self.height))
        if "finger_inner" in joints and "finger_outer" in joints:
            self.opening = float(joints["finger_inner"]) + float(joints["finger_outer"])

    def joints_reached(self) -> bool:
        return abs(self.angle - self.target_angle) < self.TOLERANCE_ANGLE and abs(self.height - self.target_height) < self.TOLERANCE_HEIGHT

    def gripper_reached(self) -> bool:
        """At the target opening, or stopped for a few periods (closing on an object stops early)."""
        if abs(self.opening - self.target_opening) < self.TOLERANCE_GRIPPER:
            self._still = 0
            return True
        msg = _PLATFORM.latest("/joint_states")
        velocity = dict(zip(msg.get("name", []), msg.get("velocity", []), strict=False)) if msg else {}
        still = bool(velocity) and all(abs(float(velocity.get(f, 0.0))) < 1e-3 for f in ("finger_inner", "finger_outer"))
        self._still = self._still + 1 if still else 0
        if self._still >= 5:
            self._still = 0
            return True
        return False


#: The topic of the automaton states (docs/ide.md, "Live values").
STATES_TOPIC = "/maa/automaton_states"
STATES_TYPE = "std_msgs/msg/String"
#: The transitions taken (``{"node", "from", "to", "index"}``) and the RobotArm statements started
#: (``{"node", "program", "step", "line", "text", "file"}``), JSON in std_msgs/String (docs/generating-timesync.md).
TRANSITIONS_TOPIC = "/maa/transitions"
PROGRAM_STEPS_TOPIC = "/maa/program_steps"


def port_message(value: object) -> JsonMessage:
    """A port value as a rosbridge-JSON message of its lock-step type.

    Numbers, booleans and strings: ``{"data": v}`` (``std_msgs`` Int32, Float64, Bool, String...);
    enums: the constant's name, ``{"data": "GOLDEN"}`` (``std_msgs/String``); class-diagram objects:
    ``{"data": "<JSON of the fields>"}`` (``std_msgs/String``).
    """
    kind = type(value)
    if kind is int or kind is str or kind is bool:  # the common case first, before the isinstance checks
        return {"data": value}
    if isinstance(value, Enum):
        return {"data": value.name}
    if isinstance(value, bool | int | str):
        return {"data": value}
    if isinstance(value, float):
        return {"data": value if math.isfinite(value) else str(value)}
    encoded = encode_item(value)
    return {"data": json.dumps(encoded.get("msg"), sort_keys=True)}


def port_value(message: Mapping[str, Any], port_type: object) -> object:
    """The inverse of :func:`port_message` for an in port of the root (input injection)."""
    data = message.get("data")
    if isinstance(port_type, type) and issubclass(port_type, Enum):
        if not isinstance(data, str) or data not in port_type.__members__:
            raise ValueError(f"{data!r} is not a constant of {port_type.__name__}")
        return port_type[data]
    if isinstance(port_type, type) and isinstance(data, str):  # a class-diagram type: JSON of its fields
        return decode_value(json.loads(data))
    return data


def _mode_of(inst: ModeInstance) -> Callable[[], str | None]:
    """The live state of a mode component: its current mode."""
    return lambda: inst.mode


class LockstepApp:
    """One architecture time slice per ``step``; implements the simulator's lock-step protocol.

    With ``port_topics`` (``"<instance path>.<out port>"`` of atomic instances and ``"<in port>"`` of
    the root -> ``(topic, type)``, generated into ``maa_app.PORT_TOPICS``) every slice's result also
    holds the value of every port that got one in that slice, under its ROS 2 topic name, and the
    automaton states and the modes of mode components on :data:`STATES_TOPIC` (in the first slice and
    whenever one changed). Messages on the root's in-port topics among the inputs are fed into those
    ports for the slice.
    """

    def __init__(
        self,
        root: type[ComponentType],
        parameters: Mapping[str, object] | None = None,
        port_topics: Mapping[str, tuple[str, str]] | None = None,
        node_names: Mapping[str, str] | None = None,
        automata: Mapping[str, str] | None = None,
    ) -> None:
        self.root = root
        self.parameters = dict(parameters or {})
        self.port_topics = dict(port_topics or {})
        self.node_names = dict(node_names or {})
        #: the automata table (``maa_app.AUTOMATA``: instance path -> AutomatonEntry as JSON)
        self._automata_table = dict(automata or {})
        self._in_topics = {topic: port for port, (topic, _) in self.port_topics.items() if "." not in port}
        self.system: System = self._start()

    def _start(self) -> System:
        _PLATFORM.inputs = {}
        _PLATFORM.outbox = {}
        system = System(self.root, self.parameters)
        # Robot arms drive the simulator's arm instead of their kinematic model.
        for inst in system.instances:
            if isinstance(inst.behavior, RobotArmExecutor):
                inst.behavior.arm = SimulatorArm()
        # Observers of the live values: the out ports of atomic instances with a topic.
        self._observed: list[tuple[str, list[object]]] = []
        for inst in system.instances:
            if inst.behavior is None:
                continue
            for port in inst.ctype.OUT_PORTS:
                entry = self.port_topics.get(f"{'.'.join(inst.path)}.{port}")
                if entry is not None:
                    self._observed.append((entry[0], inst.observers.setdefault(port, [])))
        self._states: dict[str, str] | None = None
        self._events: dict[str, list[JsonMessage]] = {}
        for inst in system.instances:
            node = self.node_names.get(".".join(inst.path), ".".join(inst.path))
            if inst.behavior is not None:
                self._observe_events(inst.behavior, node)
            elif isinstance(inst, ModeInstance):  # its mode transitions, as an automaton's transitions
                inst.transition_hook = self._transition_hook(node)
        system.init()
        # live states: the state path of every automaton and the mode of every mode component
        self._automata: list[tuple[str, Callable[[], str | None]]] = []
        for inst in system.instances:
            node = self.node_names.get(".".join(inst.path), ".".join(inst.path))
            if isinstance(inst, ModeInstance):
                self._automata.append((node, _mode_of(inst)))
            elif inst.behavior is not None and inst.behavior.state_path() is not None:
                self._automata.append((node, inst.behavior.state_path))
        return system

    def _transition_hook(self, node: str) -> TransitionHook:
        """Collects the transitions taken by the automaton (or mode automaton) of ``node`` for the slice's result."""
        events = self._events

        def taken(index: int, source: str, target: str) -> None:
            data = {"node": node, "from": source, "to": target, "index": index}
            events.setdefault(TRANSITIONS_TOPIC, []).append({"data": json.dumps(data)})

        return taken

    def _observe_events(self, behavior: Behavior, node: str) -> None:
        """Collects the behavior's transitions and program steps for the slice's result."""
        events = self._events

        def started(program: str, step: int, line: int, text: str) -> None:
            data = {"node": node, "program": program, "step": step, "line": line, "text": text, "file": file}
            events.setdefault(PROGRAM_STEPS_TOPIC, []).append({"data": json.dumps(data)})

        behavior.set_transition_hook(self._transition_hook(node))
        file = getattr(behavior, "FILE", "")
        if isinstance(behavior, RobotArmExecutor):
            behavior.set_step_hook(started)

    def reset(self) -> None:
        """Restarts the application in its initial state."""
        self.system = self._start()

    def step(self, inputs: Mapping[str, JsonMessage]) -> dict[str, list[JsonMessage]]:
        """Runs one time slice with the simulator's messages of this instant."""
        fed: dict[str, list[JsonMessage]] = {}
        for topic, message in inputs.items():
            port = self._in_topics.get(topic)
            if port is None:
                _PLATFORM.inputs[topic] = dict(message)
                continue
            try:
                value = port_value(message, self.root.PORT_TYPES.get(port))
            except ValueError:
                continue  # not a value of the port's type (validate_input tells the sender)
            self.system.receive(port, value)
            fed[topic] = [dict(message)]
        for port in self.root.IN_PORTS:
            self.system.receive(port, TICK)  # the slice ends on every input stream of the root
        self.system.run(1)
        out = _PLATFORM.outbox
        _PLATFORM.outbox = {}
        if self._events:
            out.update(self._events)
            self._events.clear()
        if self.port_topics:
            out.update(fed)
            for topic, items in self._observed:
                if len(items) == 1 and items[0] is TICK:  # the usual slice of a port without a message
                    items.clear()
                    continue
                values = [port_message(v) for v in items if v is not TICK]
                items.clear()
                if values:
                    out.setdefault(topic, []).extend(values)
            states = self.states()
            if states != self._states:
                self._states = states
                out[STATES_TOPIC] = [{"data": json.dumps(states)}]
        return out

    def validate_input(self, topic: str, message: Mapping[str, Any]) -> None:
        """Raises ValueError when a message for a root in-port topic does not fit the port's type."""
        port = self._in_topics.get(topic)
        if port is not None:
            port_value(message, self.root.PORT_TYPES.get(port))

    def states(self) -> dict[str, str]:
        """The current state path of every automaton and mode of every mode component, by ROS 2 node name."""
        return {node: state() or "" for node, state in self._automata}

    def automata(self) -> list[dict[str, Any]]:
        """The automata table (@maa/protocol AutomatonEntry): automata and mode automata with their states and transitions."""
        return [json.loads(entry) for entry in self._automata_table.values()]

    def topics(self) -> dict[str, str]:
        """The port topics this build emits (and the root's in ports it reads), with their types."""
        result = {topic: type_name for topic, type_name in self.port_topics.values()}
        if self.port_topics:
            result[STATES_TOPIC] = STATES_TYPE
            result[TRANSITIONS_TOPIC] = STATES_TYPE
            result[PROGRAM_STEPS_TOPIC] = STATES_TYPE
        return result
