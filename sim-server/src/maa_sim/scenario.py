"""Scenario runs: the initial world from a file (`maa-sim run --world FILE`) and the report of the run
(`maa-sim run --report FILE`, format ``maa-scenario-report/1``, docs/lab.md "Grading").

The world file sets what a scenario varies in the toast kitchen::

    { "goldenSeconds": 6, "breadJitter": 0, "seed": 0 }

All fields are optional. `ScenarioObserver` watches a session period by period: what happens in the
world (the bread goes into the toaster, the toaster switches on and off, the toast turns golden or
burnt, the bread falls onto the table, the toast lies on the plate) and every change of the
automaton states on `/maa/automaton_states`; `report` turns that into the report, which
`write_report` writes atomically (a temporary file renamed into place).
"""

from __future__ import annotations

import contextlib
import json
import math
import os
import tempfile
from collections.abc import Mapping
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, Final, Literal

import mujoco

from .messages import JsonMessage
from .protocol import AUTOMATON_STATES_TOPIC, ScenarioEvent, ScenarioReport, ScenarioStateChange, ScenarioWorld
from .session import SimEvent, SimSession
from .transport import LocalBus
from .world import BURNT_LEVEL, GOLDEN_LEVEL, PLATE_CENTER, PLATE_RADIUS, ToastKitchen, WorldConfig, classify_toast

REPORT_FORMAT: Final = "maa-scenario-report/1"
#: The only goal of the toast kitchen: the toasted bread rests on the plate (`ToastKitchen.toast_on_plate`).
GOAL = "toastOnPlate"
#: The automaton states of the application (docs/ide.md, "Live values").
STATES_TOPIC = AUTOMATON_STATES_TOPIC
#: Largest standard deviation of the bread's start position (m): the holder leaves it a few millimetres.
MAX_BREAD_JITTER = 0.005
#: Periods the bread must lie on the table before it counts as dropped (not a graze while carried).
DROP_PERIODS = 5
#: Seconds the bread must be out of the toaster's slot before entering it again counts as loading it again
#: (the carriage lifts the toast out of the slot for a moment when the lever comes up).
SLOT_LEAVE_SECONDS = 1.0
#: How far from its start position the bread still counts as in its holder (m).
HOLDER_RADIUS = 0.04

EventKind = Literal[
    "bread-loaded",
    "toaster-on",
    "toaster-off",
    "toast-golden",
    "toast-burnt",
    "toast-dropped",
    "toast-on-plate",
    "error",
]
#: The fields of a world file (@maa/protocol's ScenarioWorld).
WORLD_FIELDS = ("goldenSeconds", "breadJitter", "seed")


class WorldFileError(ValueError):
    """A world file that cannot be read or has a bad field; the message names the file and the field."""


def _number(where: str, data: Mapping[str, Any], key: str) -> float | None:
    value = data.get(key)
    if value is None and key not in data:
        return None
    if isinstance(value, bool) or not isinstance(value, int | float) or not math.isfinite(value):
        raise WorldFileError(f"{where}: /{key}: must be a number, not {json.dumps(value)}")
    return float(value)


def check_world(data: Any, where: str) -> ScenarioWorld:
    """Checks a parsed world file; the error names the file (`where`) and the field."""
    if not isinstance(data, dict):
        raise WorldFileError(f'{where}: a world file holds a JSON object, e.g. {{"goldenSeconds": 6}}')
    unknown = sorted(set(data) - set(WORLD_FIELDS))
    if unknown:
        raise WorldFileError(f"{where}: /{unknown[0]}: unknown field (a world has goldenSeconds, breadJitter and seed)")
    world: ScenarioWorld = {}
    golden = _number(where, data, "goldenSeconds")
    if golden is not None:
        if not 0 < golden <= 3600:
            raise WorldFileError(
                f"{where}: /goldenSeconds: must be more than 0 and at most 3600 seconds, not {golden:g}"
            )
        world["goldenSeconds"] = golden
    jitter = _number(where, data, "breadJitter")
    if jitter is not None:
        if not 0 <= jitter <= MAX_BREAD_JITTER:
            raise WorldFileError(
                f"{where}: /breadJitter: must be from 0 to {MAX_BREAD_JITTER} (metres), not {jitter:g}"
            )
        world["breadJitter"] = jitter
    if "seed" in data:
        seed = data["seed"]
        if isinstance(seed, bool) or not isinstance(seed, int) or not 0 <= seed < 2**32:
            raise WorldFileError(f"{where}: /seed: must be an integer from 0 to 4294967295, not {json.dumps(seed)}")
        world["seed"] = seed
    return world


def load_world(path: Path) -> ScenarioWorld:
    """Reads and checks a world file."""
    try:
        text = path.read_text(encoding="utf-8")
    except OSError as exc:
        raise WorldFileError(f"{path}: cannot read the world file: {exc.strerror or exc}") from None
    try:
        data = json.loads(text)
    except json.JSONDecodeError as exc:
        raise WorldFileError(f"{path}: invalid JSON: {exc}") from None
    return check_world(data, str(path))


def world_config(world: ScenarioWorld, seed: int | None = None, golden_seconds: float | None = None) -> WorldConfig:
    """The world's configuration: the file's fields, where the command line gave none."""
    defaults = WorldConfig()
    return WorldConfig(
        golden_seconds=golden_seconds
        if golden_seconds is not None
        else world.get("goldenSeconds", defaults.golden_seconds),
        bread_jitter=world.get("breadJitter", defaults.bread_jitter),
        seed=seed if seed is not None else world.get("seed", defaults.seed),
    )


def world_summary(config: WorldConfig) -> ScenarioWorld:
    """The world of a run as the report shows it."""
    return {"goldenSeconds": config.golden_seconds, "breadJitter": config.bread_jitter, "seed": config.seed}


@dataclass
class _WorldState:
    """What the observer saw of the world in the last period."""

    loaded: bool = False  # the bread is in the slot, or left it less than SLOT_LEAVE_SECONDS ago
    left_slot: float = 0.0  # when it last left the slot
    heater: bool = False
    golden: bool = False
    burnt: bool = False
    on_plate: bool = False
    on_table: int = 0  # consecutive periods the bread lay on the table
    dropped: bool = False  # the current drop was reported


@dataclass
class ScenarioObserver:
    """Collects the events and state changes of a run (attach it before the first period)."""

    goal: str = GOAL
    events: list[ScenarioEvent] = field(default_factory=list)
    states: list[ScenarioStateChange] = field(default_factory=list)
    final_states: dict[str, str] = field(default_factory=dict)
    goal_time: float | None = None
    dropped: bool = False
    _seen: _WorldState = field(default_factory=_WorldState)
    _session: SimSession | None = None
    _table_geom: int = -1
    _holder: tuple[float, float] = (0.0, 0.0)

    def attach(self, session: SimSession, initial_states: Mapping[str, str] | None = None) -> None:
        """Watches the session: its periods, its error events and the automaton states topic.
        `initial_states`: the automata's states before the first period (LockstepApp.states())."""
        self._session = session
        world = session.world
        self._table_geom = int(mujoco.mj_name2id(world.model, mujoco.mjtObj.mjOBJ_GEOM, "table"))
        start = world.bread_position()
        self._holder = (float(start[0]), float(start[1]))
        if initial_states:
            self._states_at(session.clock, initial_states)
        session.period_listeners.append(self.on_period)
        session.event_listeners.append(self.on_event)
        transport = session.transport
        if isinstance(transport, LocalBus) and transport.topic_type(STATES_TOPIC) is None:
            return  # a lock-step controller without automaton states
        transport.subscribe(STATES_TOPIC, "std_msgs/msg/String", self.on_states)

    def _add(self, time: float, kind: EventKind, text: str) -> None:
        self.events.append({"time": round(time, 6), "kind": kind, "text": text})

    # ----------------------------------------------------------------------------- listeners

    def on_states(self, _topic: str, msg: JsonMessage) -> None:
        try:
            states = json.loads(str(msg.get("data", "")))
        except ValueError:
            return
        if isinstance(states, dict) and self._session is not None:
            self._states_at(self._session.clock, {str(k): str(v) for k, v in states.items()})

    def _states_at(self, time: float, states: Mapping[str, str]) -> None:
        for node, state in states.items():
            if self.final_states.get(node) != state:
                self.final_states[node] = state
                self.states.append({"time": round(time, 6), "node": node, "state": state})

    def on_event(self, event: SimEvent) -> None:
        if event.level == "error":
            self._add(event.time, "error", f"{event.source}: {event.message}")

    def on_period(self, world: ToastKitchen, clock: float) -> None:
        seen = self._seen
        in_slot = world.bread_in_slot()
        if in_slot:
            if not seen.loaded:
                self._add(clock, "bread-loaded", "the bread went into the toaster's slot")
            seen.loaded = True
            seen.left_slot = clock
        elif seen.loaded and clock - seen.left_slot >= SLOT_LEAVE_SECONDS:
            seen.loaded = False
        heater = world.heater_on
        if heater != seen.heater:
            self._add(
                clock, "toaster-on" if heater else "toaster-off", f"the toaster switched {'on' if heater else 'off'}"
            )
        seen.heater = heater
        if not seen.golden and world.toast_level >= GOLDEN_LEVEL:
            seen.golden = True
            self._add(clock, "toast-golden", "the toast is golden")
        if not seen.burnt and world.toast_level >= BURNT_LEVEL:
            seen.burnt = True
            self._add(clock, "toast-burnt", "the toast is burnt")
        self._check_dropped(world, clock)
        on_plate = world.toast_on_plate()
        if on_plate and not seen.on_plate:
            self._add(
                clock, "toast-on-plate", f"the toast lies on the plate ({classify_toast(world.toast_level).lower()})"
            )
            if self.goal_time is None:
                self.goal_time = round(clock, 6)
        seen.on_plate = on_plate

    def _check_dropped(self, world: ToastKitchen, clock: float) -> None:
        """The bread lies on the table: not in the gripper, its holder, the toaster or on the plate."""
        seen = self._seen
        if self._lies_on_table(world):
            seen.on_table += 1
        else:
            seen.on_table = 0
            seen.dropped = False
        if seen.on_table >= DROP_PERIODS and not seen.dropped:
            seen.dropped = self.dropped = True
            x, y, _ = world.bread_position()
            self._add(
                clock,
                "toast-dropped",
                f"the bread fell onto the table at ({x:.2f} m, {y:.2f} m), not into the toaster or onto the plate",
            )

    def _lies_on_table(self, world: ToastKitchen) -> bool:
        touching = world.contacts_of(world.bread_geom)
        if self._table_geom not in touching or touching.intersection(world.finger_geoms) or world.bread_in_slot():
            return False
        x, y, _ = world.bread_position()
        in_holder = math.hypot(x - self._holder[0], y - self._holder[1]) < HOLDER_RADIUS
        on_plate = math.hypot(x - PLATE_CENTER[0], y - PLATE_CENTER[1]) < PLATE_RADIUS
        return not in_holder and not on_plate

    # ----------------------------------------------------------------------------- report

    def report(
        self, world: ToastKitchen, config: WorldConfig, end_reason: str, sim_time: float, error: str | None
    ) -> ScenarioReport:
        level = float(world.toast_level)
        return {
            "format": REPORT_FORMAT,
            "goal": self.goal,
            "goalReached": self.goal_time is not None,
            "goalTime": self.goal_time,
            "endReason": end_reason,
            "simTime": round(sim_time, 6),
            "world": world_summary(config),
            "events": list(self.events),
            "states": list(self.states),
            "finalStates": dict(self.final_states),
            "toast": {
                "level": round(level, 6),
                "color": classify_toast(level),
                "onPlate": world.toast_on_plate(),
                "dropped": self.dropped,
            },
            "error": error,
        }


def failed_report(world: ScenarioWorld, end_reason: str, error: str) -> ScenarioReport:
    """The report of a run that could not start (a bad world file, a package that does not load)."""
    return {
        "format": REPORT_FORMAT,
        "goal": GOAL,
        "goalReached": False,
        "goalTime": None,
        "endReason": end_reason,
        "simTime": 0.0,
        "world": world,
        "events": [{"time": 0.0, "kind": "error", "text": error}],
        "states": [],
        "finalStates": {},
        "toast": None,
        "error": error,
    }


def write_report(path: Path, report: ScenarioReport) -> None:
    """Writes the report atomically: a temporary file next to it, renamed into place."""
    path.parent.mkdir(parents=True, exist_ok=True)
    fd, tmp = tempfile.mkstemp(prefix=f".{path.name}.", suffix=".part", dir=path.parent)
    try:
        with os.fdopen(fd, "w", encoding="utf-8") as out:
            json.dump(report, out, indent=1)
            out.write("\n")
        os.chmod(tmp, 0o644)  # as an ordinary file (mkstemp's is private to the run's user)
        os.replace(tmp, path)
    except BaseException:
        with contextlib.suppress(OSError):
            os.unlink(tmp)
        raise
