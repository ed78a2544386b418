"""Headless runs: lock-step to completion, as used by tests, the benchmark and `maa-sim run`."""

from __future__ import annotations

import time
from dataclasses import dataclass, field

import numpy as np
import numpy.typing as npt

from .lockstep import LockstepController
from .session import DEFAULT_PERIOD, Runner, SimSession
from .transport import LocalBus
from .world import ToastKitchen, WorldConfig


@dataclass
class LockstepResult:
    sim_time: float
    periods: int
    goal_reached: bool
    wall_seconds: float
    #: qpos after every period (periods x nq), when recorded
    trajectory: npt.NDArray[np.float64] = field(default_factory=lambda: np.zeros((0, 0)))


def lockstep_session(
    controller: LockstepController,
    *,
    seed: int = 0,
    period: float = DEFAULT_PERIOD,
    scene: str = "toast_kitchen",
    bus: LocalBus | None = None,
    config: WorldConfig | None = None,
) -> tuple[SimSession, Runner]:
    """A session on a local bus with the controller's port topics declared, and its runner.
    `config`: the initial world (its seed wins over `seed`)."""
    bus = bus or LocalBus()
    topics = getattr(controller, "topics", None)
    if callable(topics):
        for name, type_name in dict(topics()).items():
            bus.declare(name, type_name)
    world = ToastKitchen(scene, config if config is not None else WorldConfig(seed=seed))
    session = SimSession(world, bus, period)
    return session, Runner(session, speed=0.0, controller=controller)


def run_lockstep(
    controller: LockstepController,
    *,
    seed: int = 0,
    period: float = DEFAULT_PERIOD,
    max_sim_time: float = 60.0,
    stop_on_goal: bool = True,
    record: bool = False,
    scene: str = "toast_kitchen",
) -> LockstepResult:
    """Runs the controller in lock-step as fast as possible until the toast is on the plate."""
    session, runner = lockstep_session(controller, seed=seed, period=period, scene=scene)
    world = session.world
    rows: list[npt.NDArray[np.float64]] = []
    reached = False
    start = time.perf_counter()
    while world.time < max_sim_time - 1e-9:
        runner.cycle()
        if record:
            rows.append(np.array(world.data.qpos))
        if stop_on_goal and world.toast_on_plate():
            reached = True
            break
    wall = time.perf_counter() - start
    trajectory = np.stack(rows) if rows else np.zeros((0, world.model.nq))
    return LockstepResult(world.time, session.periods, reached, wall, trajectory)
