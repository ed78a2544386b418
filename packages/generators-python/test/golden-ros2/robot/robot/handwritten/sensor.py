"""Handwritten ROS 2 implementation of robot.Sensor (created once by ros2.Components; yours to edit).

Put the implementation in the model root as ``Sensor.ros2.py`` next to ``Sensor.arc`` to
have it copied here on the first generation.
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import ClassVar

from rclpy.node import Node
from robot.handwritten.sensor_base import SensorBase


class Sensor(SensorBase):
    """Talks to the platform: create publishers and subscriptions of platform topics in ``attach``."""

    SUBSCRIBES: ClassVar[dict[str, str]] = {}
    PUBLISHES: ClassVar[dict[str, str]] = {}

    def attach(self, node: Node) -> None:
        self.node = node

    def step(self, inputs: Mapping[str, object]) -> None:
        """One time slice: read ``inputs``, send outputs with the ``send_*`` methods."""
        del inputs
