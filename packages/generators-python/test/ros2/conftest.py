"""Fixtures of the ROS 2 tests (defined in ros2_support.py, a module name no other test folder uses)."""

from ros2_support import generated, installed, pytest_configure, ros_domain

__all__ = ["generated", "installed", "pytest_configure", "ros_domain"]
