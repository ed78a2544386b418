"""maa-ros2: the run-time environment of the ros2-python generator family (``ros2.*``).

A generated node module builds one :class:`ComponentNode` per atomic component instance: an
rclpy node that wraps the component's behavior class (``maa_behavior.Behavior``), subscribes
its in ports, publishes its out ports and steps the behavior once per period of the node's
clock (simulation time with ``use_sim_time``). See docs/generating-ros2.md.
"""

from maa_ros2.arm import RosArm
from maa_ros2.modes import ModeManagerNode, Relay, port_value
from maa_ros2.node import ComponentNode, InPort, ModeGate, OutPort, PlatformBehavior, run_node
from maa_ros2.ports import PortCodec, char_port, class_port, enum_port, std_port

__all__ = [
    "ComponentNode",
    "InPort",
    "ModeGate",
    "ModeManagerNode",
    "OutPort",
    "PlatformBehavior",
    "PortCodec",
    "Relay",
    "RosArm",
    "char_port",
    "class_port",
    "enum_port",
    "port_value",
    "run_node",
    "std_port",
]
