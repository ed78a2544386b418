"""Mode automata on ROS 2: the mode manager node of a decomposed component with a mode automaton.

Semantics (docs/generating-ros2.md, "Mode automata"): one :class:`ModeManagerNode` per instance of
a mode component. It subscribes to the component's in ports, takes the mode transitions and
publishes the current mode on its mode topic (std_msgs/String, latched). The nodes of the
subcomponents declared in modes follow that topic (``maa_ros2.node.ModeGate``) and rest while
their mode is inactive. Every connector declared in a mode is a :class:`Relay` of the manager: it
forwards the messages of the connector's source topic to the target's topic while one of its
modes is current.

The current mode is also published on ``maa_ros2.node.STATES_TOPIC`` (the IDE's live states)
under the instance's node path, the manager's namespace, and every mode transition taken on
``maa_ros2.node.TRANSITIONS_TOPIC`` under the same node path (``{"node", "from", "to", "index"}``).

- ``<<sync>>``: a message on an in port updates the port's value (primitive ports keep their
  last value, others hold it until the end of the period) and the transitions are taken with
  those values before the message is relayed, so the new mode's connectors carry it; at the end
  of every period the transitions are taken again;
- event-based: a message on an in port takes the first enabled transition triggered by that
  port before the message is relayed; the end of every period takes those triggered by ``Tick``
  or by nothing.
"""

from __future__ import annotations

from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass
from typing import Any

from maa_ros2.node import (
    DEFAULT_PERIOD,
    MODE_QOS,
    PORT_QOS,
    STATES_QOS,
    STATES_TOPIC,
    InPort,
    ParameterValue,
    state_message,
    transition_publisher,
)
from maa_ros2.ports import PortCodec
from rclpy.node import Node
from rclpy.publisher import Publisher
from std_msgs.msg import String

#: ``(mode, trigger, inputs, params) -> (index, target mode) or None``; ``trigger`` is ``None`` in a
#: sync automaton, an in port's name for a message on it and ``""`` for the end of a period; the
#: index is the transition's declaration order (the automata table's, ``/maa/transitions``).
Transition = Callable[[str, str | None, Mapping[str, object], Mapping[str, object]], tuple[int, str] | None]


@dataclass(frozen=True)
class Relay:
    """A connector declared in ``modes``: messages on ``source`` go on to ``target`` while one of them is current."""

    source: str
    target: str
    codec: PortCodec
    modes: tuple[str, ...]


def port_value(inputs: Mapping[str, object], port: str, default: object) -> object:
    """An in port's value in a guard: ``default`` (Java's for a primitive type) without a message."""
    value = inputs.get(port)
    return default if value is None else value


class ModeManagerNode(Node):
    """Takes a component's mode transitions, publishes its mode and relays its modes' connectors."""

    def __init__(
        self,
        name: str,
        mode_topic: str,
        initial: str,
        timing: str,
        transition: Transition,
        inputs: Sequence[InPort],
        relays: Sequence[Relay],
        parameters: Mapping[str, ParameterValue] | None = None,
        period: float = DEFAULT_PERIOD,
        convert_parameters: Callable[[dict[str, object]], dict[str, object]] | None = None,
    ) -> None:
        super().__init__(name)
        self.params: dict[str, object] = {}
        for key, default in (parameters or {}).items():
            self.params[key] = self.declare_parameter(key, default).value
        # parameters travel as the regular nodes' do (enums by ordinal); the guards read the values
        if convert_parameters is not None:
            self.params = convert_parameters(self.params)
        self.period = float(self.declare_parameter("period", period).value)
        self.mode = initial
        self.sync = timing == "sync"
        self._transition = transition
        self._sampled: dict[str, object] = {}
        self._events: dict[str, object] = {}
        self._mode_publisher = self.create_publisher(String, mode_topic, MODE_QOS)
        # the mode is the instance's live state too (docs/ide.md, "Live values"): under the
        # instance's node path, which is the manager's namespace
        self._state_publisher = self.create_publisher(String, STATES_TOPIC, STATES_QOS)
        # and its transitions are the instance's transitions, as an automaton node reports its own
        self._taken = transition_publisher(self, self.get_namespace())
        self._relay_publishers: dict[str, Publisher[Any]] = {}
        topics: dict[str, tuple[Any, list[InPort], list[Relay]]] = {}
        for p in inputs:
            topics.setdefault(p.topic, (p.codec.msg_type, [], []))[1].append(p)
        for r in relays:
            topics.setdefault(r.source, (r.codec.msg_type, [], []))[2].append(r)
            if r.target not in self._relay_publishers:
                self._relay_publishers[r.target] = self.create_publisher(r.codec.msg_type, r.target, PORT_QOS)
        for topic, (msg_type, ports, routes) in topics.items():
            self.create_subscription(msg_type, topic, self._receiver(ports, routes), PORT_QOS)
        self._publish_mode()
        self.slice_timer = self.create_timer(self.period, self._on_period)

    def _publish_mode(self) -> None:
        msg = String()
        msg.data = self.mode
        self._mode_publisher.publish(msg)
        self._state_publisher.publish(state_message(self.get_namespace(), self.mode))

    def _switch(self, trigger: str | None, inputs: Mapping[str, object]) -> None:
        taken = self._transition(self.mode, trigger, inputs, self.params)
        if taken is None:
            return
        index, target = taken
        source, self.mode = self.mode, target
        self._taken(index, source, target)
        if target != source:
            self._publish_mode()

    def _receiver(self, ports: Sequence[InPort], routes: Sequence[Relay]) -> Callable[[Any], None]:
        def receive(msg: Any) -> None:
            for p in ports:
                value = p.codec.from_msg(msg)
                if self.sync:
                    (self._sampled if p.sampled else self._events)[p.port] = value
                    self._switch(None, {**self._sampled, **self._events})
                else:
                    self._switch(p.port, {p.port: value})
            for r in routes:
                if self.mode in r.modes:
                    self._relay_publishers[r.target].publish(msg)

        return receive

    def _on_period(self) -> None:
        if self.sync:
            inputs = {**self._sampled, **self._events}
            self._events.clear()
            self._switch(None, inputs)
        else:
            self._switch("", {})
