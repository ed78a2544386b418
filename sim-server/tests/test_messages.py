"""JSON form of ROS 2 messages: strict in, complete out."""

from __future__ import annotations

import pytest

from maa_sim.messages import MessageError, from_json, normalize_type, to_json, validate


def test_type_names() -> None:
    assert normalize_type("std_msgs/String") == "std_msgs/msg/String"
    assert normalize_type("std_msgs/msg/String") == "std_msgs/msg/String"
    for bad in ("String", "a/b/c/d", "std_msgs/", "", "1x/Y"):
        with pytest.raises(MessageError):
            normalize_type(bad)


def test_round_trip_joint_state() -> None:
    data = {
        "header": {"stamp": {"sec": 3, "nanosec": 5}, "frame_id": "x"},
        "name": ["a", "b"],
        "position": [1.0, 2],
        "velocity": [],
        "effort": [],
    }
    out = to_json(from_json("sensor_msgs/msg/JointState", data))
    assert out["name"] == ["a", "b"]
    assert out["position"] == [1.0, 2.0]
    assert out["header"]["stamp"] == {"sec": 3, "nanosec": 5}


def test_defaults_are_filled_in() -> None:
    assert validate("std_msgs/msg/Int32", {}) == {"data": 0}
    assert validate("rosgraph_msgs/msg/Clock", {})["clock"] == {"sec": 0, "nanosec": 0}


@pytest.mark.parametrize(
    ("type_name", "data"),
    [
        ("std_msgs/msg/Int32", {"data": 1.5}),
        ("std_msgs/msg/Int32", {"data": True}),
        ("std_msgs/msg/Int32", {"data": 2**40}),
        ("std_msgs/msg/Int32", {"nope": 1}),
        ("std_msgs/msg/String", {"data": 3}),
        ("std_msgs/msg/Float64", {"data": "1"}),
        ("std_msgs/msg/Bool", {"data": 1}),
        ("sensor_msgs/msg/JointState", {"name": "a"}),
        ("sensor_msgs/msg/JointState", {"header": []}),
        ("sensor_msgs/msg/JointState", {"position": ["x"]}),
        ("std_msgs/msg/Int32", [1]),
        ("no_pkg/msg/Nothing", {}),
    ],
)
def test_mismatches_are_errors(type_name: str, data: object) -> None:
    with pytest.raises(MessageError):
        from_json(type_name, data)
