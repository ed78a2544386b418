"""Tests of maa_behavior: Java value semantics and the RobotArm program executor."""

from __future__ import annotations

import math
from collections.abc import Mapping
from enum import Enum

import pytest

from maa_behavior import Behavior, f32, jconcat, jdiv, jmod, jstr
from maa_behavior.robotarm import Fixed, FromPort, Gripper, Keep, Move, RobotArmExecutor


def test_java_division_and_remainder() -> None:
    assert jdiv(7, 2) == 3
    assert jdiv(-7, 2) == -3
    assert jmod(-7, 2) == -1
    assert jdiv(7.0, 2) == 3.5
    assert math.isinf(jdiv(1.0, 0.0))  # type: ignore[arg-type]
    with pytest.raises(ZeroDivisionError):
        jdiv(1, 0)


def test_java_strings_and_floats() -> None:
    assert jconcat("sum=", 3) == "sum=3"
    assert jconcat("b=", True) == "b=true"
    assert jstr(None) == "null"
    assert f32(0.1) != 0.1
    assert f32(1.5) == 1.5


def test_emit_skips_null() -> None:
    sent: list[tuple[str, object]] = []
    b = Behavior(lambda p, v: sent.append((p, v)))
    b._emit("o", None)
    b._emit("o", 1)
    assert sent == [("o", 1)]


class Status(Enum):
    IDLE = 0
    BUSY = 1
    DONE = 2


class Program(Enum):
    NONE = 0
    PICKUP_AND_DEPLOY = 1


DEG = math.pi / 180


class ToastServiceArm(RobotArmExecutor):
    """The paper's Listing 1 as the RobotArm generator translates it."""

    IN_PORTS = ("cmd", "angle", "height")
    OUT_PORTS = ("status",)
    STATUS = Status
    PROGRAMS = {
        "PickupAndDeploy": (
            Move(Keep(), Fixed(0.3), "top"),
            Gripper(close=False),
            Move(Fixed(120 * DEG), Fixed(0.2), "toaster"),
            Gripper(close=True),
            Move(Keep(), Fixed(0.3), "top"),
            Move(FromPort("angle", DEG), FromPort("height", 0.01)),
            Gripper(close=False),
        ),
    }
    COMMANDS = {"PICKUP_AND_DEPLOY": "PickupAndDeploy"}


def _run(arm: ToastServiceArm, slices: list[Mapping[str, object]], idle: Mapping[str, object], limit: int) -> list[object]:
    out: list[object] = []
    arm._emit_fn = lambda port, value: out.append(value)
    for inputs in slices:
        arm.step(inputs)
    for _ in range(limit):
        if Status.DONE in out:
            break
        arm.step(idle)
    return out


def test_listing1_drives_the_joint_space_trajectory_in_order() -> None:
    statuses: list[object] = []
    arm = ToastServiceArm(lambda port, value: statuses.append(value))
    arm.start()
    assert statuses == [Status.IDLE]
    out = _run(arm, [{"cmd": Program.PICKUP_AND_DEPLOY, "angle": 90, "height": 10}], {"cmd": None}, 1000)
    assert out == [Status.BUSY, Status.DONE]
    kinds = [(c[0], round(c[1], 4), round(c[2], 4)) for c in arm.arm.commands]
    assert kinds == [
        ("joints", 0.0, 0.3),  # move top (the base keeps its angle)
        ("gripper", 0.06, 0.0),  # open
        ("joints", round(120 * DEG, 4), 0.2),  # move toaster
        ("gripper", 0.0, 0.0),  # close
        ("joints", round(120 * DEG, 4), 0.3),  # move top
        ("joints", round(90 * DEG, 4), 0.1),  # move angle height (deg, cm)
        ("gripper", 0.06, 0.0),  # open
    ]
    # the arm really arrived: joint positions are tracked over time
    assert math.isclose(arm.arm.angle, 90 * DEG) and math.isclose(arm.arm.height, 0.1)


def test_a_move_waits_for_its_port_values_and_commands_during_a_run_are_ignored() -> None:
    arm = ToastServiceArm(lambda port, value: None)
    arm.start()
    out = _run(arm, [{"cmd": Program.PICKUP_AND_DEPLOY}], {"cmd": Program.PICKUP_AND_DEPLOY}, 600)
    assert out == [Status.BUSY]  # still waiting for angle/height, the second command is ignored
    assert arm.program == "PickupAndDeploy"
    out = _run(arm, [{"angle": 45, "height": 500}], {}, 600)
    assert out == [Status.DONE]
    assert math.isclose(arm.arm.height, 0.3)  # clamped to the lift's range
