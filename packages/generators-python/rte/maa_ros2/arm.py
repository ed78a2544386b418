"""The RobotArm executor's arm on ROS 2: commands to the simulator's topics, feedback from ``/joint_states``.

``maa_behavior.robotarm.RobotArmExecutor`` runs programs against an ``Arm``; on ROS 2 the node
replaces its kinematic model by :class:`RosArm` (docs/simulation.md, "Topics"):

- ``/arm/joint_command`` (``sensor_msgs/msg/JointState``): ``base_yaw`` (rad) and ``lift`` (m) targets;
- ``/arm/gripper_command`` (``std_msgs/msg/Float64``): the opening between the pads in m;
- ``/joint_states`` (``sensor_msgs/msg/JointState``): the positions a step waits for.

A move completes when both joints are within tolerance of their targets; ``open``/``close``
complete when the fingers have reached the opening or stopped (closing on a slice stops early).
"""

from __future__ import annotations

from typing import Any

from maa_behavior.robotarm import Arm

JOINT_COMMAND = "/arm/joint_command"
GRIPPER_COMMAND = "/arm/gripper_command"
JOINT_STATES = "/joint_states"
ANGLE_TOLERANCE = 0.01  # rad
HEIGHT_TOLERANCE = 0.003  # m
OPENING_TOLERANCE = 0.004  # m
STILL_VELOCITY = 0.002  # m/s
SETTLE_MESSAGES = 5

PLATFORM_SUBSCRIBES = {JOINT_STATES: "sensor_msgs/msg/JointState"}
PLATFORM_PUBLISHES = {JOINT_COMMAND: "sensor_msgs/msg/JointState", GRIPPER_COMMAND: "std_msgs/msg/Float64"}


class RosArm(Arm):
    """An ``Arm`` whose joints are the simulator's (or a robot driver's)."""

    def __init__(self, node: Any, qos: Any) -> None:
        super().__init__()
        from sensor_msgs.msg import JointState
        from std_msgs.msg import Float64

        self._joint_state_type = JointState
        self._float_type = Float64
        self._joint_pub = node.create_publisher(JointState, JOINT_COMMAND, qos)
        self._gripper_pub = node.create_publisher(Float64, GRIPPER_COMMAND, qos)
        node.create_subscription(JointState, JOINT_STATES, self._on_joint_states, qos)
        self.have_state = False
        self.finger_velocity = 0.0
        self._since_gripper_command = 0

    def command_joints(self, angle: float, height: float) -> None:
        super().command_joints(angle, height)
        command = self._joint_state_type(name=["base_yaw", "lift"], position=[float(angle), float(height)])
        self._joint_pub.publish(command)

    def command_gripper(self, opening: float) -> None:
        super().command_gripper(opening)
        self._since_gripper_command = 0
        self._gripper_pub.publish(self._float_type(data=float(opening)))

    def advance(self, dt: float) -> None:
        """Positions come from ``/joint_states``; nothing to integrate."""
        del dt

    def _on_joint_states(self, msg: Any) -> None:
        position = dict(zip(msg.name, msg.position, strict=False))
        velocity = dict(zip(msg.name, msg.velocity, strict=False))
        if "base_yaw" in position:
            self.angle = float(position["base_yaw"])
        if "lift" in position:
            self.height = float(position["lift"])
        if "finger_inner" in position and "finger_outer" in position:
            self.opening = float(position["finger_inner"]) + float(position["finger_outer"])
            inner, outer = velocity.get("finger_inner", 0.0), velocity.get("finger_outer", 0.0)
            self.finger_velocity = abs(float(inner)) + abs(float(outer))
        self.have_state = True
        self._since_gripper_command += 1

    def joints_reached(self) -> bool:
        return (
            self.have_state
            and abs(self.angle - self.target_angle) < ANGLE_TOLERANCE
            and abs(self.height - self.target_height) < HEIGHT_TOLERANCE
        )

    def gripper_reached(self) -> bool:
        if not self.have_state or self._since_gripper_command < SETTLE_MESSAGES:
            return False
        return abs(self.opening - self.target_opening) < OPENING_TOLERANCE or self.finger_velocity < STILL_VELOCITY
