"""ToasterActuator on ROS 2: pushes the toaster lever down or releases it.

Handwritten platform component of toast.ToasterActuator. ros2.Components copies this file into the
generated package once (toast_service_robot/handwritten/toaster_actuator.py) and never overwrites it.
Publishes ``START`` or ``STOP`` on ``/toaster/command`` (std_msgs/msg/String) whenever the
``leverDown`` port changes (the first value included).
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import ClassVar

from rclpy.node import Node
from std_msgs.msg import String
from toast_service_robot.handwritten.toaster_actuator_base import ToasterActuatorBase

TOPIC = "/toaster/command"


class ToasterActuator(ToasterActuatorBase):
    """Turns the lever state into toaster commands."""

    SUBSCRIBES: ClassVar[dict[str, str]] = {}
    PUBLISHES: ClassVar[dict[str, str]] = {"/toaster/command": "std_msgs/msg/String"}

    def attach(self, node: Node) -> None:
        self.lever_down: bool | None = None
        self.command = node.create_publisher(String, TOPIC, 10)

    def step(self, inputs: Mapping[str, object]) -> None:
        down = inputs.get("leverDown")
        if isinstance(down, bool) and down != self.lever_down:
            self.lever_down = down
            self.command.publish(String(data="START" if down else "STOP"))
