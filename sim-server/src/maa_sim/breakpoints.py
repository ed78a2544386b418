"""Breakpoints of a lock-step run (docs/simulation.md, "Breakpoints").

A client sets them over rosbridge (`/sim/set_breakpoints`, @maa/protocol's SetBreakpoints): a
state of a node's automaton (`{"node", "state"}`: reached when a transition enters it from
outside) or a transition (`{"node", "from", "to"}`: reached when it is taken). They are checked
against the transitions the application reports on `/maa/transitions` in the period it takes
them; the first one reached pauses the run after that period, and the status names it
(`breakpoint`) until the run resumes, steps or resets.

A name in a breakpoint is a state's name or its dotted path (`Serving`, `Outer.Inner`); it
covers the state and its substates, so a breakpoint on a superstate is reached by its substates.
A mode component's mode automaton is an automaton here too: its node (the instance's node path)
reports its mode transitions on `/maa/transitions`, so a breakpoint names a mode as a state.
Breakpoints are resolved against the build's automata table (@maa/protocol's AutomatonEntry, the
controller's `automata()`): a name no state (or mode) of the node's automaton has is refused.
"""

from __future__ import annotations

import json
import threading
from collections.abc import Callable, Sequence
from typing import Any, cast

from .contracts import problem, validator
from .messages import JsonMessage
from .protocol import (
    SET_BREAKPOINTS_SCHEMA,
    TRANSITIONS_TOPIC,
    SetBreakpointsBreakpointsItem0,
    SetBreakpointsBreakpointsItem1,
)

Breakpoint = SetBreakpointsBreakpointsItem0 | SetBreakpointsBreakpointsItem1

_REQUEST = validator(SET_BREAKPOINTS_SCHEMA)


def check_request(request: Any) -> list[Breakpoint]:
    """The breakpoints of a `/sim/set_breakpoints` request; ValueError naming the bad field."""
    found = problem(_REQUEST, request)
    if found:
        raise ValueError(f"/sim/set_breakpoints: {found}")
    return list(cast(list[Breakpoint], request["breakpoints"]))


def within(path: str, name: str) -> bool:
    """Whether the state path `path` (`Outer.Inner`) is the state `name` (a name or a dotted path) or inside it."""
    if not path:
        return False
    segments = path.split(".")
    wanted = name.split(".")
    n = len(wanted)
    return any(segments[i : i + n] == wanted for i in range(len(segments) - n + 1))


def reached(breakpoint: Breakpoint, event: dict[str, Any]) -> bool:
    """Whether a `/maa/transitions` event reaches the breakpoint."""
    if breakpoint["node"] != event.get("node"):
        return False
    source, target = str(event.get("from", "")), str(event.get("to", ""))
    if "state" in breakpoint:
        state = cast(SetBreakpointsBreakpointsItem0, breakpoint)["state"]
        return within(target, state) and not within(source, state)
    return within(source, breakpoint["from"]) and within(target, breakpoint["to"])


def unresolved(breakpoints: Sequence[Breakpoint], automata: Sequence[dict[str, Any]]) -> list[str]:
    """Why breakpoints do not resolve against the automata table: a state (or mode) name that no
    state of the node's automaton has. Breakpoints on nodes without an entry are not checked here."""
    by_node = {str(entry.get("node")): entry for entry in automata}
    problems: list[str] = []
    for breakpoint in breakpoints:
        entry = by_node.get(breakpoint["node"])
        if entry is None:
            continue
        paths = [str(s.get("path", "")) for s in entry.get("states", [])]
        if "state" in breakpoint:
            names = [cast(SetBreakpointsBreakpointsItem0, breakpoint)["state"]]
        else:
            names = [breakpoint["from"], breakpoint["to"]]
        what = "mode" if entry.get("kind") == "modes" else "state"
        known = ", ".join(paths) or "none"
        for name in names:
            if not any(within(path, name) for path in paths):
                problems.append(f"no {what} {name!r} in the automaton of {breakpoint['node']} ({known})")
    return problems


class Breakpoints:
    """The breakpoints of one run: `set` replaces them; `on_transition` (a subscriber of
    `/maa/transitions`, called in the period's delivery) pauses the run through `pause` when one
    is reached. Thread-safe: the service sets them while the loop's thread checks them."""

    def __init__(self, pause: Callable[[], None]) -> None:
        self._pause = pause
        self._lock = threading.Lock()
        self._breakpoints: list[Breakpoint] = []
        #: the breakpoint the run paused at, None while none is
        self.hit: Breakpoint | None = None

    def set(self, breakpoints: list[Breakpoint]) -> None:
        with self._lock:
            self._breakpoints = list(breakpoints)

    def list(self) -> list[Breakpoint]:
        with self._lock:
            return list(self._breakpoints)

    def clear_hit(self) -> None:
        """The run goes on (resume, step, reset): the status no longer names a breakpoint."""
        self.hit = None

    def on_transition(self, _topic: str, msg: JsonMessage) -> None:
        with self._lock:
            breakpoints = self._breakpoints
        if not breakpoints or self.hit is not None:
            return
        try:
            event = json.loads(str(msg.get("data", "")))
        except ValueError:
            return
        if not isinstance(event, dict):
            return
        for breakpoint in breakpoints:
            if reached(breakpoint, event):
                self.hit = {**breakpoint}  # type: ignore[assignment]
                self._pause()  # the period in progress finishes; none starts after it
                return


__all__ = ["TRANSITIONS_TOPIC", "Breakpoint", "Breakpoints", "check_request", "reached", "unresolved", "within"]
