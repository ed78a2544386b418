"""A simulation session: the world, its topics, and the loop that advances it.

`SimSession` advances the world by one control period at a time: it applies the actuator
commands received since the last period, steps the physics and publishes the sensor topics.
`Runner` drives a session in a thread, paced to real time times a speed factor (or as fast as
possible), and implements the control services: pause, resume, step, reset, speed. With a
lock-step controller the runner calls it once per period, in the loop, synchronously.

Two times: `clock`, the simulated time the application sees (`/clock`), which a reset sets back
to 0 (a fresh run), and `elapsed`, the simulated time since the session began, which never goes
back (pacing, the real-time factor, and the time stamps of a recording, which must not jump back).
"""

from __future__ import annotations

import contextlib
import copy
import math
import threading
import time
from collections import deque
from collections.abc import Callable, Mapping
from dataclasses import dataclass, field
from typing import Any

from . import interface
from .lockstep import LockstepController, normalize_outputs
from .messages import JsonMessage, MessageError
from .transport import LocalBus, Transport
from .world import ToastKitchen

#: Default control period (s): one architecture time slice in lock-step mode, one /clock tick.
DEFAULT_PERIOD = 0.02


@dataclass
class SimEvent:
    """Something the user should know: a rejected command, a crashed node, ..."""

    time: float
    level: str
    source: str
    message: str
    details: dict[str, Any] = field(default_factory=dict)

    def as_json(self) -> JsonMessage:
        return {
            "time": self.time,
            "level": self.level,
            "source": self.source,
            "message": self.message,
            **({"details": self.details} if self.details else {}),
        }


class SimSession:
    """The world plus its topics on a transport."""

    def __init__(
        self,
        world: ToastKitchen,
        transport: Transport,
        period: float = DEFAULT_PERIOD,
        publish_outputs: bool = True,
    ) -> None:
        steps = round(period / world.timestep)
        if steps < 1 or not math.isclose(steps * world.timestep, period, rel_tol=1e-9):
            raise ValueError(f"the period {period} s is not a multiple of the physics step {world.timestep} s")
        self.world = world
        self.transport = transport
        self.period = period
        self.steps_per_period = steps
        self.publish_outputs = publish_outputs
        self.lock = threading.RLock()
        #: the simulated time of the runs before the last reset (elapsed = this + the world's time)
        self.elapsed_before_reset = 0.0
        self.periods = 0
        self._pending: list[tuple[str, JsonMessage]] = []
        self._pending_lock = threading.Lock()
        self.events: deque[SimEvent] = deque(maxlen=200)
        self.event_listeners: list[Callable[[SimEvent], None]] = []
        #: called after every period with the world and the elapsed time, under the session lock
        #: (the recorder: its time stamps must not go back at a reset)
        self.period_listeners: list[Callable[[ToastKitchen, float], None]] = []
        if isinstance(transport, LocalBus):
            for spec in (*interface.SIM_OUTPUTS, *interface.SIM_INPUTS):
                transport.declare(spec.name, spec.type)
        else:
            for spec in interface.SIM_OUTPUTS:
                transport.advertise(spec.name, spec.type)
        for spec in interface.SIM_INPUTS:
            transport.subscribe(spec.name, spec.type, self._on_command)

    @property
    def clock(self) -> float:
        """The published simulation time (`/clock`): 0 at the start and again after a reset."""
        return self.world.time

    @property
    def elapsed(self) -> float:
        """The simulated time since the session began: monotonic across resets."""
        return self.elapsed_before_reset + self.world.time

    def report(self, level: str, source: str, message: str, **details: Any) -> SimEvent:
        event = SimEvent(self.clock, level, source, message, details)
        self.events.append(event)
        for listener in list(self.event_listeners):
            with contextlib.suppress(Exception):  # a listener must not stop the simulation
                listener(event)
        return event

    def _on_command(self, topic: str, msg: JsonMessage) -> None:
        with self._pending_lock:
            self._pending.append((topic, msg))

    def command(self, topic: str, msg: JsonMessage) -> None:
        """Queues an actuator message for the next period (as if it had arrived on its topic)."""
        self._on_command(topic, msg)

    def _apply_pending(self) -> None:
        with self._pending_lock:
            pending, self._pending = self._pending, []
        for topic, msg in pending:
            try:
                interface.apply_command(self.world, topic, msg)
            except MessageError as exc:
                self.report("warning", topic, f"command rejected: {exc}")

    def observe(self) -> dict[str, JsonMessage]:
        """The sensor and state messages of the current instant."""
        return interface.sim_outputs(self.world, self.clock)

    def advance(self) -> dict[str, JsonMessage]:
        """One control period: apply commands, step the physics, publish and return the outputs."""
        with self.lock:
            self._apply_pending()
            self.world.step(self.steps_per_period)
            self.periods += 1
            outputs = self.observe()
            for listener in self.period_listeners:
                listener(self.world, self.elapsed)
        if self.publish_outputs:
            self.publish(outputs)
        return outputs

    def publish(self, outputs: Mapping[str, JsonMessage]) -> None:
        transport = self.transport
        if isinstance(transport, LocalBus):
            transport.deliver_all(outputs.items())
            return
        for topic, msg in outputs.items():
            transport.publish(topic, msg)

    def reset(self, seed: int | None = None) -> None:
        """Back to the initial scene; the clock starts again at 0 (`elapsed` keeps counting)."""
        with self.lock:
            self.elapsed_before_reset += self.world.time
            with self._pending_lock:
                self._pending.clear()
            self.world.reset(seed)


class LastValues:
    """The last message of each topic the application sent since the start or the last reset.

    A port is written when its value changes (a timesync build sends nothing in a slice without a
    message), so a client that subscribes later, or while the run is paused, would see nothing
    until the next change: the rosbridge endpoint sends it this message at once (docs/simulation.md).
    Written by the loop (lock-step: the controller's outputs of each slice; ROS 2: the port topics
    received over DDS), read by the endpoint's threads: single-key reads and writes of a dict are
    atomic in CPython, so no lock is taken in the loop's hot path.
    """

    def __init__(self) -> None:
        self._last: dict[str, JsonMessage] = {}

    def note(self, topic: str, msg: JsonMessage) -> None:
        self._last[topic] = msg

    def note_all(self, outputs: Mapping[str, list[JsonMessage]]) -> None:
        last = self._last
        for topic, messages in outputs.items():
            if messages:
                last[topic] = messages[-1]

    def get(self, topic: str) -> JsonMessage | None:
        return self._last.get(topic)

    def clear(self) -> None:
        self._last = {}


def _snapshot(controller: object) -> dict[str, Any] | None:
    """A deep copy of a controller's attributes (None when they cannot be copied)."""
    state = getattr(controller, "__dict__", None)
    if not isinstance(state, dict):
        return None
    try:
        copied: dict[str, Any] = copy.deepcopy(state)
    except Exception:  # noqa: BLE001 - locks, sockets, ...: no snapshot, the slice is retried anyway
        return None
    return copied


def _restore(controller: object, state: dict[str, Any]) -> bool:
    """Puts a snapshot back in place (the controller object stays the same for its holders)."""
    current = controller.__dict__
    current.clear()
    current.update(state)
    return True


class Runner:
    """Runs a session in a thread: paced (speed > 0) or as fast as possible (speed == 0)."""

    def __init__(
        self,
        session: SimSession,
        speed: float = 1.0,
        controller: LockstepController | None = None,
        stop_when: Callable[[SimSession], bool] | None = None,
        max_sim_time: float | None = None,
    ) -> None:
        if speed < 0 or not math.isfinite(speed):
            raise ValueError("speed must be a finite number >= 0")
        self.session = session
        self.speed = speed
        self.controller = controller
        self.stop_when = stop_when
        self.max_sim_time = max_sim_time
        self.paused = False
        self.finished = threading.Event()
        self.finish_reason = ""
        self._wake = threading.Condition()
        self._stop = False
        self._thread: threading.Thread | None = None
        self._inputs: dict[str, JsonMessage] | None = None
        # pacing statistics
        self.lateness: deque[float] = deque(maxlen=5000)
        self._rtf_window: deque[tuple[float, float]] = deque(maxlen=100)
        self.injected: dict[str, JsonMessage] = {}
        self._injected_lock = threading.Lock()
        #: (periods done, periods asked) of the step in progress, None when none is
        self.stepping: tuple[int, int] | None = None
        self._step_interrupted = ""
        #: the last message of every topic the application sent, for clients that subscribe later
        self.last_values = LastValues()

    # ----------------------------------------------------------------------------- one period

    def cycle(self) -> None:
        """One control period, with the lock-step controller if there is one."""
        session = self.session
        if self.controller is not None:
            with session.lock:
                inputs = self._inputs if self._inputs is not None else session.observe()
                with self._injected_lock:
                    injected, self.injected = self.injected, {}
                outputs = self._controller_step(self.controller, inputs, injected)
                self.last_values.note_all(outputs)
                self._emit_all(outputs)
                self._inputs = session.advance()
        else:
            session.advance()
        self._rtf_window.append((time.perf_counter(), session.elapsed))
        if self.stop_when is not None and self.stop_when(session):
            self.finish("goal reached")
        elif self.max_sim_time is not None and session.world.time >= self.max_sim_time - 1e-9:
            self.finish("time limit reached")

    def _controller_step(
        self, controller: LockstepController, inputs: dict[str, JsonMessage], injected: dict[str, JsonMessage]
    ) -> dict[str, list[JsonMessage]]:
        """One slice of the controller. A slice with a client's injected messages that fails (the
        message fits its type but not what the application expects, e.g. a KeyError) must not end
        the simulation: the controller is put back as it was before the slice, the failure is
        reported, and the slice runs again without the injected messages. A failure without
        injected messages is the application's own and propagates (the run ends with an error)."""
        if not injected:
            return normalize_outputs(controller.step(inputs))
        saved = _snapshot(controller)
        try:
            return normalize_outputs(controller.step({**inputs, **injected}))
        except Exception as exc:  # noqa: BLE001 - any failure of the application on a client's input
            restored = saved is not None and _restore(controller, saved)
            topics = ", ".join(sorted(injected))
            self.session.report(
                "error",
                "injection",
                f"the application failed on the message injected on {topics} ({type(exc).__name__}: {exc}); "
                f"the message was dropped"
                + ("" if restored else " (the application's state could not be saved before the slice)"),
            )
        return normalize_outputs(controller.step(inputs))

    def _emit_all(self, outputs: dict[str, list[JsonMessage]]) -> None:
        """:meth:`_emit` of every message of a slice (on a local bus only topics with subscribers)."""
        transport = self.session.transport
        if isinstance(transport, LocalBus):
            transport.deliver_all((topic, msg) for topic, messages in outputs.items() for msg in messages)
            return
        for topic, messages in outputs.items():
            for msg in messages:
                self._emit(topic, msg)

    def _emit(self, topic: str, msg: JsonMessage) -> None:
        """A controller's message: actuator topics reach the session, every topic its observers."""
        transport = self.session.transport
        if isinstance(transport, LocalBus):
            if transport.has_subscribers(topic):
                transport.deliver(topic, msg)
        elif topic in interface.ALL_TOPICS and interface.ALL_TOPICS[topic].publisher == "controller":
            self.session.command(topic, msg)

    def inject(self, topic: str, msg: JsonMessage) -> None:
        """A message for the lock-step controller's next period (input injection from the IDE)."""
        with self._injected_lock:
            self.injected[topic] = msg

    # ----------------------------------------------------------------------------- thread

    def start(self) -> None:
        self._thread = threading.Thread(target=self._loop, name="maa-sim-runner", daemon=True)
        self._thread.start()

    def run_blocking(self) -> None:
        """Runs in the calling thread until finished or stopped."""
        self._loop()

    def stop(self) -> None:
        with self._wake:
            self._stop = True
            self._interrupt_step("the end of the run")
            self._wake.notify_all()
        if self._thread is not None and self._thread is not threading.current_thread():
            self._thread.join(timeout=5)

    def finish(self, reason: str) -> None:
        self.finish_reason = reason
        self._stop = True
        self.finished.set()

    def _loop(self) -> None:
        period = self.session.period
        start_wall = time.perf_counter()
        start_sim = self.session.elapsed
        try:
            while True:
                with self._wake:
                    while self.paused and not self._stop:
                        self._wake.wait()
                        start_wall, start_sim = time.perf_counter(), self.session.elapsed
                    if self._stop:
                        break
                    speed = self.speed
                with self.session.lock:
                    if self.paused:  # paused meanwhile: no cycle may start after pause() returned
                        continue
                    self.cycle()
                if speed > 0:
                    due = start_wall + (self.session.elapsed - start_sim) / speed
                    now = time.perf_counter()
                    if due > now:
                        time.sleep(due - now)
                        now = time.perf_counter()
                    late = now - due
                    self.lateness.append(late)
                    if late > max(0.5, 10 * period / speed):
                        # fell far behind (machine too slow for this speed): do not race to catch up
                        start_wall, start_sim = now, self.session.elapsed
        except Exception as exc:  # noqa: BLE001 - reported, the servers stay up
            self.session.report("error", "runner", f"simulation stopped: {exc!r}")
            self.finish(f"error: {exc!r}")
        finally:
            self.finished.set()

    # ----------------------------------------------------------------------------- control services

    def pause(self) -> None:
        """Pauses; when it returns, no period is in progress and none starts until resumed (a step
        in progress stops too)."""
        with self._wake:
            self.paused = True
            self._interrupt_step("a pause")
        with self.session.lock:
            pass

    def resume(self) -> None:
        """Continues the loop; a step in progress stops (the loop takes over)."""
        with self._wake:
            self._interrupt_step("a resume")
            self.paused = False
            self._wake.notify_all()

    def _interrupt_step(self, why: str) -> None:
        if self.stepping is not None:
            self._step_interrupted = why

    def step(self, periods: int = 1) -> tuple[int, str]:
        """Advances by a number of periods while paused (pauses first); returns how many periods
        it ran and, when it stopped early, why (a pause, resume, reset or stop meanwhile).

        The session lock is taken per period, not for the whole step, so a long step (up to
        100000 periods, minutes on a slow machine) leaves the other control services and the
        status answering in between; it runs in its caller's thread. One step at a time: a
        second one while a step is in progress is refused (ValueError)."""
        if isinstance(periods, bool) or not isinstance(periods, int) or periods < 1 or periods > 100_000:
            raise ValueError("steps must be between 1 and 100000")
        with self._wake:
            if self.stepping is not None:
                done, total = self.stepping
                raise ValueError(f"a step is in progress ({done} of {total} periods); pause to stop it")
            self.stepping = (0, periods)
            self._step_interrupted = ""
            self.paused = True
        try:
            for done in range(periods):
                with self.session.lock:
                    # checked under the session lock: pause() takes it after setting the flag, so
                    # no period starts once pause() has returned
                    if self._step_interrupted:
                        return done, self._step_interrupted
                    self.cycle()
                self.stepping = (done + 1, periods)
            return periods, ""
        finally:
            with self._wake:
                self.stepping = None

    def reset(self, seed: int | None = None) -> None:
        """Back to the initial scene (see SimSession.reset); a step in progress stops."""
        with self._wake:
            self._interrupt_step("a reset")
        with self.session.lock:
            self.session.reset(seed)
            self.last_values.clear()
            self._inputs = None
            reset = getattr(self.controller, "reset", None)
            if callable(reset):
                reset()

    def set_speed(self, speed: float) -> None:
        if speed < 0 or not math.isfinite(speed) or speed > 1000:
            raise ValueError("speed must be between 0 (as fast as possible) and 1000")
        with self._wake:
            self.speed = speed
            self._wake.notify_all()

    def real_time_factor(self) -> float:
        """Simulated seconds per wall second over the last periods (0 when not running)."""
        if len(self._rtf_window) < 2:
            return 0.0
        (w0, s0), (w1, s1) = self._rtf_window[0], self._rtf_window[-1]
        if w1 - w0 <= 0 or time.perf_counter() - w1 > 1.0:
            return 0.0
        return (s1 - s0) / (w1 - w0)

    def status(self) -> JsonMessage:
        session = self.session
        with session.lock:
            return self._status(session)

    def _status(self, session: SimSession) -> JsonMessage:
        return {
            "time": session.clock,
            "world_time": session.world.time,
            "paused": self.paused,
            "speed": self.speed,
            "real_time_factor": self.real_time_factor(),
            "periods": session.periods,
            "period": session.period,
            "toast_level": session.world.toast_level,
            "toast_on_plate": session.world.toast_on_plate(),
            "finished": self.finish_reason,
            "stepping": list(self.stepping) if self.stepping is not None else None,
        }
