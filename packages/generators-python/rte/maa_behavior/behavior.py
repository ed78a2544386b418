"""The interface every generated behavior class implements."""

from __future__ import annotations

from collections.abc import Callable, Mapping
from typing import ClassVar

Emit = Callable[[str, object], None]
"""``emit(port, value)``: sends one message on an out port (``None`` sends nothing)."""

TransitionHook = Callable[[int, str, str], None]
"""``hook(index, source, target)``: an automaton took its transition ``index`` (0-based, in the
automaton's order of transitions) from state path ``source`` to state path ``target``."""


class Behavior:
    """Base class of generated behaviors.

    ``TIMING`` is ``"sync"`` (one :meth:`step` per time slice) or ``"timed"``/``"untimed"``
    (:meth:`on_message` per message, :meth:`on_tick` per slice end). Ticks are the platform's
    business: a behavior never sends one.
    """

    TIMING: ClassVar[str] = "sync"
    IN_PORTS: ClassVar[tuple[str, ...]] = ()
    OUT_PORTS: ClassVar[tuple[str, ...]] = ()
    DELAYED: ClassVar[frozenset[str]] = frozenset()

    def __init__(self, emit: Emit, params: Mapping[str, object] | None = None) -> None:
        self._emit_fn = emit
        self._params: Mapping[str, object] = params or {}
        self._delay_hook: Callable[[], None] | None = None
        self._delay_done = False
        self._transition_hook: TransitionHook | None = None

    # -- the platform's side ------------------------------------------------------------
    def set_delay_hook(self, hook: Callable[[], None]) -> None:
        """Called by the platform: ``hook`` sends the initial tick of every delayed out port."""
        self._delay_hook = hook

    def set_transition_hook(self, hook: TransitionHook | None) -> None:
        """Called by the platform: ``hook`` hears of every transition taken (``/maa/transitions``).

        Observing only: the hook must not emit on ports (stream semantics stay as they are).
        """
        self._transition_hook = hook

    def start(self) -> None:
        """Runs :meth:`init` and makes sure the delay point was passed exactly once."""
        self._delay_done = False
        self.init()
        self._delay_point()

    # -- the generated side -------------------------------------------------------------
    def init(self) -> None:
        """Produces the initial outputs (initial action, entry actions, ``init`` block)."""

    def step(self, inputs: Mapping[str, object]) -> None:
        """A sync behavior's time slice: the last message of every in port, or ``None``."""

    def on_message(self, port: str, value: object) -> None:
        """An event-driven behavior's message on an in port."""

    def on_tick(self) -> None:
        """The end of a time slice for an event-driven behavior."""

    def current_state(self) -> str | None:
        """The innermost current state (automata), for tests and tools."""
        return None

    def state_path(self) -> str | None:
        """The current state of an automaton as a dotted path from its top state (``Outer.Inner``).

        ``None`` for behaviors that are no automaton (they have no ``_PARENT`` table of states).
        """
        parents: Mapping[str, str | None] | None = getattr(type(self), "_PARENT", None)
        state = self.current_state() if parents is not None else None
        if state is None or parents is None:
            return None
        return self._path_of(state, parents)

    @staticmethod
    def _path_of(state: str, parents: Mapping[str, str | None]) -> str:
        """The dotted path of a state from its top state."""
        path = [state]
        parent = parents.get(state)
        while parent is not None and len(path) <= len(parents):
            path.append(parent)
            parent = parents.get(parent)
        return ".".join(reversed(path))

    def _taken(self, index: int, source: str) -> None:
        """Called by a generated automaton after its transition ``index`` fired in state ``source``."""
        hook = self._transition_hook
        if hook is not None:
            parents: Mapping[str, str | None] = getattr(type(self), "_PARENT", {})
            hook(index, self._path_of(source, parents), self.state_path() or "")

    def _emit(self, port: str, value: object) -> None:
        if value is not None:
            self._emit_fn(port, value)

    def _delay_point(self) -> None:
        """Where delayed out ports get their initial tick (between initial and entry actions)."""
        if not self._delay_done:
            self._delay_done = True
            if self._delay_hook is not None:
                self._delay_hook()

    @staticmethod
    def _in(inputs: Mapping[str, object], port: str, default: object) -> object:
        """A slice's value of a port of primitive type: Java's default when it got no message."""
        value = inputs.get(port)
        return default if value is None else value

    def _param(self, name: str, default: object = None) -> object:
        return self._params.get(name, default)


class NoBehavior(Behavior):
    """The behavior of an atomic component without behavior: every slice only ends."""
