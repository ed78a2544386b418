"""The RobotArm program executor (docs/robotarm.md, "The port protocol of an embedded robot arm").

A generated class lists the programs (steps with joint-space targets in SI units) and the
command table; :class:`RobotArmExecutor` runs them one time slice at a time: it tracks the
joint positions through an :class:`Arm`, emits joint targets and gripper commands, and reports
``IDLE`` (initially), ``BUSY`` (at a start) and ``DONE`` (at completion) on the status port.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Mapping
from dataclasses import dataclass, field
from enum import Enum
from typing import ClassVar

from maa_behavior.behavior import Behavior, Emit

ANGLE_RANGE = (-math.pi, math.pi)
HEIGHT_RANGE = (0.02, 0.30)
GRIPPER_OPEN = 0.06
GRIPPER_CLOSED = 0.0


@dataclass(frozen=True)
class Fixed:
    """A joint value in SI units (rad, m)."""

    si: float


@dataclass(frozen=True)
class Keep:
    """The joint keeps its current value."""


@dataclass(frozen=True)
class FromPort:
    """The latest value of an in port (or input), converted with ``to_si``."""

    port: str
    to_si: float


JointSource = Fixed | Keep | FromPort


@dataclass(frozen=True)
class Move:
    angle: JointSource
    height: JointSource
    target: str | None = None


@dataclass(frozen=True)
class Gripper:
    close: bool


Step = Move | Gripper

StepHook = Callable[[str, int, int, str], None]
"""``hook(program, step, line, text)``: a program started its statement ``step`` (0-based), which is
at ``line`` (1-based) of its file and reads ``text``."""


@dataclass
class Arm:
    """The arm's joints as the executor sees them: a kinematic model moving at bounded speed.

    Platforms may replace it (e.g. by one that publishes commands to a simulator and reads its
    joint states). ``commands`` records every command in order.
    """

    angle: float = 0.0
    height: float = 0.30
    opening: float = GRIPPER_OPEN
    angle_speed: float = math.radians(120.0)
    height_speed: float = 0.2
    gripper_speed: float = 0.1
    target_angle: float = 0.0
    target_height: float = 0.30
    target_opening: float = GRIPPER_OPEN
    commands: list[tuple[str, float, float]] = field(default_factory=list)

    def command_joints(self, angle: float, height: float) -> None:
        self.target_angle, self.target_height = angle, height
        self.commands.append(("joints", angle, height))

    def command_gripper(self, opening: float) -> None:
        self.target_opening = opening
        self.commands.append(("gripper", opening, 0.0))

    def advance(self, dt: float) -> None:
        self.angle = _toward(self.angle, self.target_angle, self.angle_speed * dt)
        self.height = _toward(self.height, self.target_height, self.height_speed * dt)
        self.opening = _toward(self.opening, self.target_opening, self.gripper_speed * dt)

    def joints_reached(self) -> bool:
        return abs(self.angle - self.target_angle) < 1e-6 and abs(self.height - self.target_height) < 1e-6

    def gripper_reached(self) -> bool:
        return abs(self.opening - self.target_opening) < 1e-6


def _toward(value: float, target: float, step: float) -> float:
    if abs(target - value) <= step:
        return target
    return value + math.copysign(step, target - value)


def _clamp(value: float, bounds: tuple[float, float]) -> float:
    return min(max(value, bounds[0]), bounds[1])


class RobotArmExecutor(Behavior):
    """Runs RobotArm programs; generated subclasses fill in the class variables."""

    TIMING = "sync"
    PROGRAMS: ClassVar[Mapping[str, tuple[Step, ...]]] = {}
    COMMANDS: ClassVar[Mapping[str, str]] = {}
    #: the programs' file (relative to the model root) and (line, source) of every step (generated)
    FILE: ClassVar[str] = ""
    SOURCES: ClassVar[Mapping[str, tuple[tuple[int, str], ...]]] = {}
    STATUS: ClassVar[type[Enum] | None] = None
    CMD_PORT: ClassVar[str] = "cmd"
    STATUS_PORT: ClassVar[str] = "status"
    PERIOD: ClassVar[float] = 0.02

    def __init__(self, emit: Emit, params: Mapping[str, object] | None = None) -> None:
        super().__init__(emit, params)
        self.arm = Arm()
        self.latest: dict[str, float] = {}
        self.program: str | None = None
        self._steps: list[Step] = []
        self._active: Step | None = None
        self._step_hook: StepHook | None = None

    def set_step_hook(self, hook: StepHook | None) -> None:
        """Called by the platform: ``hook`` hears of every statement a program starts (``/maa/program_steps``)."""
        self._step_hook = hook

    def _status(self, name: str) -> None:
        value: object = self.STATUS[name] if self.STATUS is not None else name
        self._emit(self.STATUS_PORT, value)

    def init(self) -> None:
        self._status("IDLE")

    def current_state(self) -> str | None:
        return self.program

    def step(self, inputs: Mapping[str, object]) -> None:
        for port, value in inputs.items():
            if port != self.CMD_PORT and isinstance(value, (int, float)) and not isinstance(value, bool):
                self.latest[port] = float(value)
        cmd = inputs.get(self.CMD_PORT)
        name = cmd.name if isinstance(cmd, Enum) else (str(cmd) if cmd is not None else None)
        if self.program is None and name is not None and name in self.COMMANDS:
            self.program = self.COMMANDS[name]
            self._steps = list(self.PROGRAMS[self.program])
            self._active = None
            self._status("BUSY")
            self._run(advance=False)
            return
        if self.program is not None:
            self.arm.advance(self.PERIOD)
            self._run(advance=True)

    def _run(self, advance: bool) -> None:
        """Completes reached steps and starts the next ones; emits DONE after the last."""
        del advance
        while True:
            if self._active is not None:
                reached = self.arm.joints_reached() if isinstance(self._active, Move) else self.arm.gripper_reached()
                if not reached:
                    return
                self._active = None
            if not self._steps:
                self.program = None
                self._status("DONE")
                return
            if not self._start(self._steps[0]):
                return  # waits for a port value
            self._active = self._steps.pop(0)
            if self._step_hook is not None and self.program is not None:
                self._started(self.program, len(self.PROGRAMS[self.program]) - len(self._steps) - 1)

    def _started(self, program: str, step: int) -> None:
        assert self._step_hook is not None
        sources = self.SOURCES.get(program, ())
        line, text = sources[step] if step < len(sources) else (1, "")
        self._step_hook(program, step, line, text)

    def _joint(self, source: JointSource, current: float) -> float | None:
        if isinstance(source, Fixed):
            return source.si
        if isinstance(source, Keep):
            return current
        value = self.latest.get(source.port)
        return None if value is None else value * source.to_si

    def _start(self, step: Step) -> bool:
        if isinstance(step, Gripper):
            self.arm.command_gripper(GRIPPER_CLOSED if step.close else GRIPPER_OPEN)
            return True
        angle = self._joint(step.angle, self.arm.target_angle)
        height = self._joint(step.height, self.arm.target_height)
        if angle is None or height is None:
            return False
        self.arm.command_joints(_clamp(angle, ANGLE_RANGE), _clamp(height, HEIGHT_RANGE))
        return True
