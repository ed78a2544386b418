"""Time-synchronous execution of a component hierarchy in one process."""

from __future__ import annotations

from collections import deque
from collections.abc import Mapping
from typing import ClassVar

from maa_behavior import Behavior, NoBehavior


class Tick:
    """The end of a time slice on a stream."""

    _instance: Tick | None = None

    def __new__(cls) -> Tick:
        if cls._instance is None:
            cls._instance = super().__new__(cls)
        return cls._instance

    def __repr__(self) -> str:
        return "Tick"


TICK = Tick()

Connector = tuple[str, str, tuple[tuple[str, str], ...]]
"""``(source subcomponent or "", source port, ((target subcomponent or "", target port), ...))``."""


class ComponentType:
    """Generated description of a component type."""

    NAME: ClassVar[str] = ""
    IN_PORTS: ClassVar[tuple[str, ...]] = ()
    OUT_PORTS: ClassVar[tuple[str, ...]] = ()
    PORT_TYPES: ClassVar[Mapping[str, object]] = {}
    PARAMETERS: ClassVar[tuple[str, ...]] = ()

    @classmethod
    def defaults(cls, params: Mapping[str, object]) -> dict[str, object]:
        """The configuration arguments with defaults applied."""
        return dict(params)

    @classmethod
    def instance_class(cls) -> type[Instance]:
        """The class of this type's instances (mode components switch their wiring: modes.py)."""
        return Instance


class AtomicComponent(ComponentType):
    """An atomic component type: its behavior class."""

    BEHAVIOR: ClassVar[type[Behavior]] = NoBehavior


class ComposedComponent(ComponentType):
    """A decomposed component type: subcomponents and connectors."""

    CONNECTORS: ClassVar[tuple[Connector, ...]] = ()

    @classmethod
    def subcomponents(cls, params: Mapping[str, object]) -> list[tuple[str, type[ComponentType], dict[str, object]]]:
        """``(name, type, arguments)`` per subcomponent, in declaration order."""
        return []


Target = tuple["Instance", str]


class Instance:
    """A component instance with its in-port buffers (plus the hidden tick port ``""``)."""

    def __init__(self, system: System, path: tuple[str, ...], ctype: type[ComponentType], params: Mapping[str, object]) -> None:
        self.system = system
        self.path = path
        self.ctype = ctype
        self.params = ctype.defaults(params)
        self.buffers: dict[str, deque[object]] = {p: deque() for p in (*ctype.IN_PORTS, "")}
        #: ticks waiting in each buffer, and how many buffers hold at least one: a sync instance is
        #: ready when every buffer does (kept by deliver and _drain_slice instead of scanning buffers)
        self.ticks: dict[str, int] = {}
        self.ticked = 0
        self.queue: deque[str] = deque()
        self.out_targets: dict[str, list[Target]] = {p: [] for p in ctype.OUT_PORTS}
        self.observers: dict[str, list[object]] = {}
        self.children: list[Instance] = []
        self.in_targets: dict[str, list[Target]] = {p: [] for p in ctype.IN_PORTS}
        self.undriven_out: list[str] = []
        self.behavior: Behavior | None = None
        if issubclass(ctype, AtomicComponent):
            # the behavior emits straight into send (one call less per message than through _emit)
            self.behavior = ctype.BEHAVIOR(self.send, self.params)
            self.behavior.set_delay_hook(self._delay_ticks)
            self.sync = self.behavior.TIMING == "sync"
        else:
            self.sync = False

    def wired(self, children: Mapping[str, Instance]) -> None:
        """Called once a composed instance's subcomponents exist and its connectors are wired."""
        del children

    @property
    def name(self) -> str:
        return ".".join(self.path) or self.ctype.NAME

    # -- sending ------------------------------------------------------------------------
    def _emit(self, port: str, value: object) -> None:
        self.send(port, value)

    def send(self, port: str, item: object) -> None:
        """Sends a message or a tick on an out port: straight through forwarders into buffers."""
        observer = self.observers.get(port)
        if observer is not None:
            observer.append(item)
        targets = self.out_targets.get(port)
        if targets:
            for inst, target in targets:
                inst.deliver(target, item)

    def deliver(self, port: str, item: object) -> None:
        """An item arrives at an in port (``""``: the tick port)."""
        buf = self.buffers[port]
        buf.append(item)
        if item is TICK:
            ticks = self.ticks
            count = ticks.get(port, 0)
            ticks[port] = count + 1
            if not count:
                self.ticked += 1
        elif not self.sync and port and len(buf) == 1 and port not in self.queue:
            self.queue.append(port)

    def _drain_slice(self) -> dict[str, object]:
        """Takes one slice off every in-port buffer (up to and including its tick): the last message of
        each port, None where the slice held none. The '' buffer is the tick-only trigger, not a port.
        Keeps the tick counts."""
        ticks = self.ticks
        inputs: dict[str, object] = {}
        for port, buf in self.buffers.items():
            count = ticks[port] - 1
            ticks[port] = count
            if not count:
                self.ticked -= 1
            last: object = None
            item = buf.popleft()
            while item is not TICK:
                last = item
                item = buf.popleft()
            if port:
                inputs[port] = last
        return inputs

    def _delay_ticks(self) -> None:
        for port in self.ctype.OUT_PORTS:
            if self.behavior is not None and port in self.behavior.DELAYED:
                self.send(port, TICK)

    # -- init and scheduling --------------------------------------------------------------
    def init(self) -> None:
        if self.behavior is not None:
            self.behavior.start()
        else:
            for child in self.children:
                child.init()

    def ready(self) -> bool:
        if self.sync:
            return self.ticked == len(self.buffers)
        if self.queue:
            return True
        return all(buf and buf[0] is TICK for buf in self.buffers.values())

    def execute(self) -> None:
        """One step: a slice (sync), one message, or one tick (event-driven)."""
        if self.sync:
            self._sync_slice()
        elif self.queue:
            port = self.queue.popleft()
            buf = self.buffers[port]
            value = buf.popleft()
            self._message(port, value)
            if buf and buf[0] is not TICK and port not in self.queue:
                self.queue.append(port)
        else:
            ticks = self.ticks
            for port, buf in self.buffers.items():
                buf.popleft()
                count = ticks[port] - 1
                ticks[port] = count
                if not count:
                    self.ticked -= 1
            self._tick()
            for port in self.ctype.IN_PORTS:
                buf = self.buffers[port]
                if buf and buf[0] is not TICK and port not in self.queue:
                    self.queue.append(port)

    def _sync_slice(self) -> None:
        inputs = self._drain_slice()
        assert self.behavior is not None
        self.behavior.step(inputs)
        send = self.send
        for port in self.ctype.OUT_PORTS:
            send(port, TICK)

    def _message(self, port: str, value: object) -> None:
        if self.behavior is not None:
            self.behavior.on_message(port, value)
        else:
            for inst, target in self.in_targets[port]:
                inst.deliver(target, value)

    def _tick(self) -> None:
        if self.behavior is not None:
            self.behavior.on_tick()
            for port in self.ctype.OUT_PORTS:
                self.send(port, TICK)
        else:
            for port in self.ctype.IN_PORTS:
                for inst, target in self.in_targets[port]:
                    inst.deliver(target, TICK)
            for child in self.children:
                child.deliver("", TICK)
            for port in self.undriven_out:
                self.send(port, TICK)


class System:
    """A component hierarchy in one process, driven like MontiArc's coordinating scheduler."""

    def __init__(self, ctype: type[ComponentType], params: Mapping[str, object] | None = None) -> None:
        self.instances: list[Instance] = []
        self.top = self._build((), ctype, params or {})
        self.outputs: dict[str, list[object]] = {p: [] for p in ctype.OUT_PORTS}
        self.top.observers = self.outputs
        self.slices = 0

    def _build(self, path: tuple[str, ...], ctype: type[ComponentType], params: Mapping[str, object]) -> Instance:
        inst = ctype.instance_class()(self, path, ctype, params)
        self.instances.append(inst)
        if issubclass(ctype, ComposedComponent):
            children: dict[str, Instance] = {}
            for name, sub, args in ctype.subcomponents(inst.params):
                child = self._build((*path, name), sub, args)
                children[name] = child
                inst.children.append(child)
            driven: set[str] = set()
            connected_in: set[tuple[str, str]] = set()
            for src_sub, src_port, targets in ctype.CONNECTORS:
                resolved: list[Target] = []
                for tgt_sub, tgt_port in targets:
                    if tgt_sub:
                        resolved.append((children[tgt_sub], tgt_port))
                        connected_in.add((tgt_sub, tgt_port))
                    else:
                        driven.add(tgt_port)
                        resolved.append((_Forward(inst, tgt_port), ""))  # type: ignore[arg-type]
                if src_sub:
                    children[src_sub].out_targets[src_port].extend(resolved)
                else:
                    inst.in_targets[src_port].extend(resolved)
            inst.undriven_out = [p for p in ctype.OUT_PORTS if p not in driven]
            # Unconnected in ports of subcomponents get the slice ends of their parent.
            for name, child in children.items():
                for port in child.ctype.IN_PORTS:
                    if (name, port) not in connected_in:
                        child.buffers.pop(port, None)
            inst.wired(children)
        return inst

    def init(self) -> None:
        self.top.init()

    def receive(self, port: str, item: object) -> None:
        """Feeds one item (a message or :data:`TICK`) into an in port of the top component."""
        self.top.deliver(port, item)

    def _any_ready(self) -> bool:
        return any(i.ready() for i in self.instances)

    def _rounds(self) -> None:
        instances = self.instances
        while True:
            progressed = False
            for inst in instances:
                if inst.ready():
                    inst.execute()
                    progressed = True
            if not progressed:
                return

    def push_tick(self) -> None:
        self.top.deliver("", TICK)
        self.slices += 1

    def run(self, ticks: int | None = None) -> None:
        """``run()``: as many slices as the inputs supply; ``run(n)``: exactly n slices."""
        if ticks is not None:
            for _ in range(ticks):
                self.push_tick()
            self._rounds()
            return
        if not self._any_ready():
            self.push_tick()
        while True:
            self._rounds()
            self.push_tick()
            if not self._any_ready():
                return

    def collect(self) -> dict[str, list[object]]:
        """The output streams observed so far (and forgets them)."""
        out = {p: list(v) for p, v in self.outputs.items()}
        for v in self.outputs.values():
            v.clear()
        return out


class _Forward:
    """A connector target that is an out port of the enclosing component (a pure forwarder)."""

    def __init__(self, inst: Instance, port: str) -> None:
        self.inst = inst
        self.port = port

    def deliver(self, _port: str, item: object) -> None:
        self.inst.send(self.port, item)


def make_system(ctype: type[ComponentType], params: Mapping[str, object] | None = None) -> System:
    """Creates and initializes a system."""
    system = System(ctype, params)
    system.init()
    return system


__all__ = ["TICK", "AtomicComponent", "ComponentType", "ComposedComponent", "Instance", "System", "Tick", "make_system"]
