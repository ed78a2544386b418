"""Decomposed components with a mode automaton: subcomponents and connectors per mode.

Every subcomponent of a mode component is instantiated once; a mode activates the component's
own subcomponents and connectors plus its own. Only active subcomponents receive the ticks of
their parent, so the subcomponents of other modes rest (they keep their state) until their mode
comes back. As MontiArc's simulator does it (SEMANTICS.md):

- a ``<<sync>>`` mode component waits for a complete time slice on every in port, first takes
  its mode transition (the first one, in declaration order, from the current mode whose guard
  holds for the slice's values), so the new mode's subcomponents and connectors are active for
  that same slice, then forwards the slice's last message on each in port, followed by the tick;
- an event-based mode component takes the first enabled transition triggered by a message's
  port before forwarding the message, and the first enabled one triggered by ``Tick`` or by
  nothing before forwarding a tick.
"""

from __future__ import annotations

from collections import deque
from collections.abc import Mapping
from typing import ClassVar

from maa_behavior.behavior import TransitionHook
from maa_timesync.runtime import TICK, ComposedComponent, Connector, Instance, Target, _Forward


class ModeComponent(ComposedComponent):
    """A decomposed component type with a mode automaton (generated)."""

    #: The modes in declaration order and the initial one.
    MODES: ClassVar[tuple[str, ...]] = ()
    INITIAL_MODE: ClassVar[str] = ""
    #: ``"sync"``: one mode transition per time slice; otherwise event-based.
    MODE_TIMING: ClassVar[str] = "sync"
    #: The subcomponents each mode declares (the others are active in every mode).
    MODE_SUBCOMPONENTS: ClassVar[Mapping[str, tuple[str, ...]]] = {}
    #: The connectors each mode declares, besides the component's own ``CONNECTORS``.
    MODE_CONNECTORS: ClassVar[Mapping[str, tuple[Connector, ...]]] = {}

    @classmethod
    def mode_transition(
        cls, mode: str, trigger: str | None, inputs: Mapping[str, object], params: Mapping[str, object]
    ) -> tuple[int, str] | None:
        """The index (declaration order, the automata table's) and target of the first enabled transition from ``mode``, if any.

        ``trigger`` is ``None`` for a sync slice, an in port's name for a message on it and
        ``""`` for a tick; ``inputs`` holds the values of the in ports (``None``: no message).
        """
        del mode, trigger, inputs, params
        return None

    @classmethod
    def instance_class(cls) -> type[Instance]:
        return ModeInstance


def port_value(inputs: Mapping[str, object], port: str, default: object) -> object:
    """An in port's value in a guard: ``default`` (Java's for a primitive type) without a message."""
    value = inputs.get(port)
    return default if value is None else value


class _Routes:
    """The wiring of one mode: where the in ports and the subcomponents' out ports deliver."""

    def __init__(self) -> None:
        self.in_targets: dict[str, list[Target]] = {}
        self.out_targets: dict[tuple[str, str], list[Target]] = {}
        self.connected_in: set[tuple[str, str]] = set()
        self.undriven_out: list[str] = []
        self.active: list[str] = []


class ModeInstance(Instance):
    """An instance of a :class:`ModeComponent`: switches its wiring when the mode changes."""

    ctype: type[ModeComponent]

    def __init__(self, *args: object, **kwargs: object) -> None:
        super().__init__(*args, **kwargs)  # type: ignore[arg-type]
        self.sync = self.ctype.MODE_TIMING == "sync"
        self.mode = self.ctype.INITIAL_MODE
        self.named: dict[str, Instance] = {}
        self.routes: dict[str, _Routes] = {}
        self.mode_log: list[str] = []
        #: hears of every mode transition taken (index, source mode, target mode), as an
        #: automaton's hook does of its transitions (``/maa/transitions``); observing only
        self.transition_hook: TransitionHook | None = None

    def wired(self, children: Mapping[str, Instance]) -> None:
        """Called once the subcomponents exist: computes every mode's wiring and enters the initial mode."""
        ctype = self.ctype
        self.named = dict(children)
        in_modes = {name for names in ctype.MODE_SUBCOMPONENTS.values() for name in names}
        for mode in ctype.MODES:
            r = _Routes()
            r.active = [n for n in children if n not in in_modes or n in ctype.MODE_SUBCOMPONENTS.get(mode, ())]
            driven: set[str] = set()
            for src_sub, src_port, targets in (*ctype.CONNECTORS, *ctype.MODE_CONNECTORS.get(mode, ())):
                resolved: list[Target] = []
                for tgt_sub, tgt_port in targets:
                    if tgt_sub:
                        resolved.append((children[tgt_sub], tgt_port))
                        r.connected_in.add((tgt_sub, tgt_port))
                    else:
                        driven.add(tgt_port)
                        resolved.append((_Forward(self, tgt_port), ""))  # type: ignore[arg-type]
                if src_sub:
                    r.out_targets.setdefault((src_sub, src_port), []).extend(resolved)
                else:
                    r.in_targets.setdefault(src_port, []).extend(resolved)
            r.undriven_out = [p for p in ctype.OUT_PORTS if p not in driven]
            self.routes[mode] = r
        # In ports connected in some mode buffer what arrives; in the other modes they get the slice ends.
        for r in self.routes.values():
            for name, port in r.connected_in:
                children[name].buffers.setdefault(port, deque())
        if ctype.INITIAL_MODE in self.routes:
            self._enter(ctype.INITIAL_MODE)

    def _enter(self, mode: str) -> None:
        self.mode = mode
        self.mode_log.append(mode)
        r = self.routes[mode]
        self.in_targets = {p: list(r.in_targets.get(p, ())) for p in self.ctype.IN_PORTS}
        for name, child in self.named.items():
            child.out_targets = {p: list(r.out_targets.get((name, p), ())) for p in child.ctype.OUT_PORTS}
        self.undriven_out = list(r.undriven_out)

    def _switch(self, trigger: str | None, inputs: Mapping[str, object]) -> None:
        taken = self.ctype.mode_transition(self.mode, trigger, inputs, self.params)
        if taken is None or taken[1] not in self.routes:
            return
        index, target = taken
        source = self.mode
        self._enter(target)
        if self.transition_hook is not None:
            self.transition_hook(index, source, target)

    # -- steps ---------------------------------------------------------------------------
    def _sync_slice(self) -> None:
        inputs = self._drain_slice()
        self._switch(None, inputs)
        for port in self.ctype.IN_PORTS:
            value = inputs.get(port)
            if value is not None:
                for inst, target in self.in_targets[port]:
                    inst.deliver(target, value)
        self._slice_end()

    def _message(self, port: str, value: object) -> None:
        self._switch(port, {port: value})
        for inst, target in self.in_targets[port]:
            inst.deliver(target, value)

    def _tick(self) -> None:
        self._switch("", {})
        self._slice_end()

    def _slice_end(self) -> None:
        r = self.routes.get(self.mode)
        for port in self.ctype.IN_PORTS:
            for inst, target in self.in_targets[port]:
                inst.deliver(target, TICK)
        for name in r.active if r else self.named:
            child = self.named[name]
            child.deliver("", TICK)
            # An in port that this mode leaves unconnected ends its slices with the parent's.
            for port in child.ctype.IN_PORTS:
                if port in child.buffers and r is not None and (name, port) not in r.connected_in:
                    child.deliver(port, TICK)
        for port in self.undriven_out:
            self.send(port, TICK)


__all__ = ["ModeComponent", "ModeInstance", "port_value"]
