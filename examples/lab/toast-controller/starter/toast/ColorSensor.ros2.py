"""ColorSensor on ROS 2: the toast class the simulator's colour sensor in the toaster slot reports.

Handwritten platform component of toast.ColorSensor. ros2.Components copies this file into the
generated package once (toast_service_robot/handwritten/color_sensor.py) and never overwrites it.
Reads ``/sensors/color`` (std_msgs/msg/String with a ToastColor constant's name) and sends the
latest class on the ``value`` port once per time slice; unknown names are logged and dropped.
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import ClassVar

from rclpy.node import Node
from std_msgs.msg import String
from toast_service_robot.handwritten.color_sensor_base import ColorSensorBase
from toast_service_robot.model.toast.types.types import ToastColor

TOPIC = "/sensors/color"


class ColorSensor(ColorSensorBase):
    """Samples the platform's colour topic."""

    SUBSCRIBES: ClassVar[dict[str, str]] = {"/sensors/color": "std_msgs/msg/String"}
    PUBLISHES: ClassVar[dict[str, str]] = {}

    def attach(self, node: Node) -> None:
        self.node = node
        self.latest: ToastColor | None = None
        node.create_subscription(String, TOPIC, self._on_color, 10)

    def _on_color(self, msg: String) -> None:
        try:
            self.latest = ToastColor[msg.data]
        except KeyError:
            self.node.get_logger().warning(f"{TOPIC}: unknown colour {msg.data!r}")

    def step(self, inputs: Mapping[str, object]) -> None:
        del inputs
        if self.latest is not None:
            self.send_value(self.latest)
