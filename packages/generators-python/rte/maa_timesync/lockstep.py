"""The simulator's lock-step interface (``maa_sim.lockstep.LockstepController``) for a timesync build.

Each ``step(inputs)`` is one time slice of the architecture: handwritten platform components read
the simulator's messages of that instant through :func:`platform` and publish actuator messages
the same way; the result maps topic names to the messages published in the slice.
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

from maa_behavior.robotarm import Arm, RobotArmExecutor
from maa_timesync.runtime import ComponentType, System

JsonMessage = dict[str, Any]


class Platform:
    """The simulator topics as seen by the platform components during one slice."""

    def __init__(self) -> None:
        self.inputs: dict[str, JsonMessage] = {}
        self.outbox: dict[str, list[JsonMessage]] = {}
        self.time = 0.0

    def latest(self, topic: str) -> JsonMessage | None:
        """The latest message of a simulator topic (``None`` before the first one)."""
        return self.inputs.get(topic)

    def publish(self, topic: str, message: JsonMessage) -> None:
        """Publishes a message on a topic in this slice."""
        self.outbox.setdefault(topic, []).append(message)


_PLATFORM = Platform()


def platform() -> Platform:
    """The platform of the running application (one per process)."""
    return _PLATFORM


class SimulatorArm(Arm):
    """The arm of the simulator: commands go to its topics, joint positions come from ``/joint_states``."""

    TOLERANCE_ANGLE = 0.02
    TOLERANCE_HEIGHT = 0.003
    TOLERANCE_GRIPPER = 0.004
    _still = 0  # periods the fingers have not moved while short of the target

    def command_joints(self, angle: float, height: float) -> None:
        super().command_joints(angle, height)
        _PLATFORM.publish("/arm/joint_command", {"name": ["base_yaw", "lift"], "position": [angle, height]})

    def command_gripper(self, opening: float) -> None:
        super().command_gripper(opening)
        _PLATFORM.publish("/arm/gripper_command", {"data": opening})

    def advance(self, dt: float) -> None:
        del dt
        msg = _PLATFORM.latest("/joint_states")
        if msg is None:
            return
        joints = dict(zip(msg.get("name", []), msg.get("position", []), strict=False))
        self.angle = float(joints.get("base_yaw", self.angle))
        self.height = float(joints.get("lift", self.height))
        if "finger_inner" in joints and "finger_outer" in joints:
            self.opening = float(joints["finger_inner"]) + float(joints["finger_outer"])

    def joints_reached(self) -> bool:
        return abs(self.angle - self.target_angle) < self.TOLERANCE_ANGLE and abs(self.height - self.target_height) < self.TOLERANCE_HEIGHT

    def gripper_reached(self) -> bool:
        """At the target opening, or stopped for a few periods (closing on an object stops early)."""
        if abs(self.opening - self.target_opening) < self.TOLERANCE_GRIPPER:
            self._still = 0
            return True
        msg = _PLATFORM.latest("/joint_states")
        velocity = dict(zip(msg.get("name", []), msg.get("velocity", []), strict=False)) if msg else {}
        still = bool(velocity) and all(abs(float(velocity.get(f, 0.0))) < 1e-3 for f in ("finger_inner", "finger_outer"))
        self._still = self._still + 1 if still else 0
        if self._still >= 5:
            self._still = 0
            return True
        return False


class LockstepApp:
    """One architecture time slice per ``step``; implements the simulator's lock-step protocol."""

    def __init__(self, root: type[ComponentType], parameters: Mapping[str, object] | None = None) -> None:
        self.root = root
        self.parameters = dict(parameters or {})
        self.system: System = self._start()

    def _start(self) -> System:
        _PLATFORM.inputs = {}
        _PLATFORM.outbox = {}
        system = System(self.root, self.parameters)
        # Robot arms drive the simulator's arm instead of their kinematic model.
        for inst in system.instances:
            if isinstance(inst.behavior, RobotArmExecutor):
                inst.behavior.arm = SimulatorArm()
        system.init()
        return system

    def reset(self) -> None:
        """Restarts the application in its initial state."""
        self.system = self._start()

    def step(self, inputs: Mapping[str, JsonMessage]) -> dict[str, list[JsonMessage]]:
        """Runs one time slice with the simulator's messages of this instant."""
        for topic, message in inputs.items():
            _PLATFORM.inputs[topic] = dict(message)
        self.system.run(1)
        out = _PLATFORM.outbox
        _PLATFORM.outbox = {}
        return out

    def topics(self) -> dict[str, str]:
        """Port topics this build emits (none besides the actuator topics)."""
        return {}
