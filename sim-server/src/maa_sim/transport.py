"""Where topics live: the interface the session and the rosbridge endpoint talk to.

Two implementations: `LocalBus` (in-process, lock-step mode and tests) and
`maa_sim.ros2.RosTransport` (a real rclpy node in ROS 2 mode). Messages are in JSON form.
Callbacks run in the publisher's thread (LocalBus) or in the ROS executor's thread.
"""

from __future__ import annotations

import itertools
import threading
from collections.abc import Callable, Iterable
from dataclasses import dataclass, field
from typing import Protocol

from .messages import JsonMessage, MessageError, normalize_type, validate

MessageCallback = Callable[[str, JsonMessage], None]


@dataclass(eq=False)
class Subscription:
    topic: str
    callback: MessageCallback
    id: int = field(default_factory=itertools.count().__next__)


class Transport(Protocol):
    """Topics by name with ROS 2 type names (`pkg/msg/Type`) and JSON messages."""

    def topics(self) -> list[tuple[str, str]]:
        """Every known topic and its type, sorted by name."""
        ...

    def topic_type(self, topic: str) -> str | None: ...

    def advertise(self, topic: str, type_name: str) -> None:
        """Declares a publisher of a type; MessageError when the type is unknown or conflicts."""
        ...

    def publish(self, topic: str, msg: JsonMessage) -> None:
        """Publishes a message on an advertised (or otherwise typed) topic; MessageError when it does not fit."""
        ...

    def subscribe(self, topic: str, type_name: str | None, callback: MessageCallback) -> Subscription: ...

    def unsubscribe(self, subscription: Subscription) -> None: ...

    def nodes(self) -> list[str]: ...


class LocalBus:
    """An in-process topic bus with the same type checking as ROS 2."""

    def __init__(self) -> None:
        self._lock = threading.RLock()
        self._types: dict[str, str] = {}
        self._subs: dict[str, list[Subscription]] = {}

    def declare(self, topic: str, type_name: str) -> None:
        """Makes a topic known (as its publisher would) without checking the type's existence."""
        with self._lock:
            self._types[topic] = normalize_type(type_name)

    def topics(self) -> list[tuple[str, str]]:
        with self._lock:
            return sorted(self._types.items())

    def topic_type(self, topic: str) -> str | None:
        with self._lock:
            return self._types.get(topic)

    def advertise(self, topic: str, type_name: str) -> None:
        normalized = normalize_type(type_name)
        from .messages import message_class

        message_class(normalized)
        with self._lock:
            known = self._types.get(topic)
            if known is not None and known != normalized:
                raise MessageError(f"{topic} already has type {known}, not {normalized}")
            self._types[topic] = normalized

    def publish(self, topic: str, msg: JsonMessage) -> None:
        """Checks the message against the topic's type, fills in defaults, delivers it."""
        type_name = self.topic_type(topic)
        if type_name is None:
            raise MessageError(f"{topic} has no type: advertise it first")
        self.deliver(topic, validate(type_name, msg))

    def has_subscribers(self, topic: str) -> bool:
        with self._lock:
            return bool(self._subs.get(topic))

    def deliver(self, topic: str, msg: JsonMessage) -> None:
        """Delivers a message that is known to fit (the simulator's own messages)."""
        with self._lock:
            subs = list(self._subs.get(topic, ()))
        for sub in subs:
            sub.callback(topic, msg)

    def deliver_all(self, messages: Iterable[tuple[str, JsonMessage]]) -> None:
        """`deliver` of each (topic, message) in order, with the subscribers of all topics taken
        under one lock (the lock-step loop's messages of one period: most topics have none)."""
        batch = list(messages)
        with self._lock:
            subs = self._subs
            found = [(topic, msg, list(subs[topic])) for topic, msg in batch if subs.get(topic)]
        for topic, msg, topic_subs in found:
            for sub in topic_subs:
                sub.callback(topic, msg)

    def subscribe(self, topic: str, type_name: str | None, callback: MessageCallback) -> Subscription:
        normalized = normalize_type(type_name) if type_name else None
        with self._lock:
            known = self._types.get(topic)
            if normalized and known and known != normalized:
                raise MessageError(f"{topic} has type {known}, not {normalized}")
            if normalized and not known:
                self._types[topic] = normalized
            sub = Subscription(topic, callback)
            self._subs.setdefault(topic, []).append(sub)
            return sub

    def unsubscribe(self, subscription: Subscription) -> None:
        with self._lock:
            subs = self._subs.get(subscription.topic, [])
            if subscription in subs:
                subs.remove(subscription)

    def nodes(self) -> list[str]:
        return ["/maa_sim"]
