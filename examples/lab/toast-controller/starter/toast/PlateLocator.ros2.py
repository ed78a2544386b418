"""PlateLocator on ROS 2: where the plate stands, as ROS parameters of the node.

Handwritten platform component of toast.PlateLocator. ros2.Components copies this file into the
generated package once (toast_service_robot/handwritten/plate_locator.py) and never overwrites it.
The simulator's plate stands at -120deg, 9cm (docs/simulation.md); a real cell sets the node's
parameters ``plate_angle`` (deg) and ``plate_height`` (cm). Sends both every time slice.
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import ClassVar

from rclpy.node import Node
from toast_service_robot.handwritten.plate_locator_base import PlateLocatorBase

DEFAULT_ANGLE = -120
DEFAULT_HEIGHT = 9


class PlateLocator(PlateLocatorBase):
    """Reports the plate's location from the node's parameters."""

    SUBSCRIBES: ClassVar[dict[str, str]] = {}
    PUBLISHES: ClassVar[dict[str, str]] = {}

    def attach(self, node: Node) -> None:
        self.node = node
        node.declare_parameter("plate_angle", DEFAULT_ANGLE)
        node.declare_parameter("plate_height", DEFAULT_HEIGHT)

    def step(self, inputs: Mapping[str, object]) -> None:
        del inputs
        self.send_angle(int(self.node.get_parameter("plate_angle").value))
        self.send_height(int(self.node.get_parameter("plate_height").value))
