"""maa_ros2's codec of char/Character ports: a code inside the behavior, one character on the topic.

``maa_ros2.ports`` needs no ROS 2; it is loaded from its file so that the package's ``__init__``
(which imports rclpy) is not run.
"""

from __future__ import annotations

import importlib.util
import sys
from dataclasses import dataclass
from pathlib import Path
from typing import Any

RTE = Path(__file__).resolve().parents[2] / "rte" / "maa_ros2" / "ports.py"


def _ports() -> Any:
    spec = importlib.util.spec_from_file_location("maa_ros2_ports_under_test", RTE)
    assert spec is not None and spec.loader is not None
    module = importlib.util.module_from_spec(spec)
    sys.modules[spec.name] = module  # dataclasses resolve annotations through sys.modules
    spec.loader.exec_module(module)
    return module


@dataclass
class FakeString:
    """Stands in for std_msgs/String."""

    data: str = ""


def test_char_port_sends_characters_and_delivers_codes() -> None:
    codec = _ports().char_port(FakeString)
    assert codec.to_msg(97).data == "a"
    assert codec.to_msg("z").data == "z"
    assert codec.from_msg(FakeString("b")) == 98
    assert codec.from_msg(FakeString("")) == 0


def test_std_port_of_strings_is_unchanged() -> None:
    codec = _ports().std_port(FakeString, str)
    assert codec.to_msg("abc").data == "abc"
    assert codec.from_msg(FakeString("abc")) == "abc"
