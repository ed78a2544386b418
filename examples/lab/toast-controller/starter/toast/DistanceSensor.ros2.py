"""DistanceSensor on ROS 2: the simulator's (or the robot's) range finder at the bread holder.

Handwritten platform component of toast.DistanceSensor. ros2.Components copies this file into the
generated package once (toast_service_robot/handwritten/distance_sensor.py) and never overwrites it.
Reads ``/sensors/distance`` (std_msgs/msg/Int32, millimetres) and sends the latest reading on the
``value`` port once per time slice.
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import ClassVar

from rclpy.node import Node
from std_msgs.msg import Int32
from toast_service_robot.handwritten.distance_sensor_base import DistanceSensorBase

TOPIC = "/sensors/distance"


class DistanceSensor(DistanceSensorBase):
    """Samples the platform's distance topic."""

    SUBSCRIBES: ClassVar[dict[str, str]] = {"/sensors/distance": "std_msgs/msg/Int32"}
    PUBLISHES: ClassVar[dict[str, str]] = {}

    def attach(self, node: Node) -> None:
        self.latest: int | None = None
        node.create_subscription(Int32, TOPIC, self._on_distance, 10)

    def _on_distance(self, msg: Int32) -> None:
        self.latest = int(msg.data)

    def step(self, inputs: Mapping[str, object]) -> None:
        del inputs
        if self.latest is not None:
            self.send_value(self.latest)
