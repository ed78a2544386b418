"""The scene: loads, steps, holds the bread by friction, toasts it, senses it."""

from __future__ import annotations

import itertools
import math

import mujoco
import numpy as np
import pytest

from maa_sim.world import (
    DISTANCE_MAX_MM,
    GOLDEN_LEVEL,
    LOCATIONS,
    ToastKitchen,
    classify_toast,
    scene_path,
    toast_rgba,
)


def run(world: ToastKitchen, seconds: float) -> None:
    world.step(round(seconds / world.timestep))


def move(world: ToastKitchen, location: str, seconds: float = 2.0) -> None:
    angle, height = LOCATIONS[location]
    world.command_joints(["base_yaw", "lift"], [math.radians(angle), height / 100])
    run(world, seconds)


def test_scene_loads_and_steps() -> None:
    model = mujoco.MjModel.from_xml_path(str(scene_path("toast_kitchen")))
    assert model.nu == 5
    assert model.opt.timestep == pytest.approx(0.002)
    world = ToastKitchen()
    run(world, 0.5)
    assert world.time == pytest.approx(0.5)
    assert np.all(np.isfinite(world.data.qpos))
    # the bread stands still in its holder
    assert world.bread_position()[2] == pytest.approx(0.045, abs=0.002)
    assert world.bread_speed() < 1e-3


def test_unknown_scene_is_rejected() -> None:
    with pytest.raises(FileNotFoundError):
        scene_path("no_such_scene")
    with pytest.raises(ValueError):
        scene_path("../etc/passwd")


def test_joint_limits_fit_robotarm_profile() -> None:
    world = ToastKitchen()
    m = world.model
    yaw = m.jnt_range[mujoco.mj_name2id(m, mujoco.mjtObj.mjOBJ_JOINT, "base_yaw")]
    lift = m.jnt_range[mujoco.mj_name2id(m, mujoco.mjtObj.mjOBJ_JOINT, "lift")]
    assert yaw[0] == pytest.approx(-math.pi) and yaw[1] == pytest.approx(math.pi)
    assert lift[0] == pytest.approx(0.02) and lift[1] == pytest.approx(0.30)
    for angle, height in LOCATIONS.values():
        assert -180 <= angle <= 180 and 2 <= height <= 30
    # the lift joint is the grasp point's height above the table
    world.command_joints(["lift"], [0.12])
    run(world, 2.0)
    site = mujoco.mj_name2id(m, mujoco.mjtObj.mjOBJ_SITE, "grasp_point")
    assert world.data.site_xpos[site][2] == pytest.approx(0.12, abs=0.002)
    # targets outside the range are clamped
    world.command_joints(["lift"], [5.0])
    run(world, 2.0)
    assert world.arm_position()[1] == pytest.approx(0.30, abs=0.002)


def test_grasped_bread_lifts_with_the_gripper_and_falls_when_released() -> None:
    world = ToastKitchen()
    move(world, "bread")
    world.command_gripper(0.0)
    run(world, 0.8)
    assert world.bread_held()
    assert world.arm_position()[2] == pytest.approx(0.012, abs=0.001)  # the fingers rest on the slice
    world.command_joints(["lift"], [0.25])
    run(world, 1.5)
    z_held = world.bread_position()[2]
    assert z_held == pytest.approx(0.25 - 0.025, abs=0.005)  # carried up, not left behind
    assert world.bread_held()
    world.command_gripper(0.06)
    run(world, 1.0)
    assert not world.bread_held()
    assert world.bread_position()[2] < 0.1  # it fell down


def test_bread_slips_out_when_the_gripper_is_open() -> None:
    world = ToastKitchen()
    move(world, "bread")
    world.command_joints(["lift"], [0.25])
    run(world, 1.5)
    assert world.bread_position()[2] == pytest.approx(0.045, abs=0.003)  # no grip, no lift: no teleporting


def test_toaster_browns_the_bread_and_the_sensors_see_it() -> None:
    world = ToastKitchen()
    assert world.distance_mm() < 25  # bread in the holder
    move(world, "bread")
    world.command_gripper(0.0)
    run(world, 0.8)
    world.command_joints(["lift"], [0.30])
    run(world, 1.5)
    assert world.distance_mm() > 200  # bread gone from the holder
    world.command_joints(["base_yaw"], [math.radians(120)])
    run(world, 1.5)
    move(world, "toaster", 1.0)
    world.command_gripper(0.06)
    run(world, 0.8)
    world.command_joints(["lift"], [0.30])
    run(world, 1.0)
    assert world.bread_in_slot()
    assert world.color() == "WHITE"
    rgba_before = np.array(world.model.geom_rgba[world.bread_geom])
    world.command_toaster("START")
    run(world, 1.0)
    assert world.heater_on
    levels = []
    for _ in range(10):
        run(world, 1.0)
        levels.append(world.toast_level)
    assert all(b > a for a, b in itertools.pairwise(levels))
    assert world.color() in ("GOLDEN", "BURNT")
    assert not np.allclose(world.model.geom_rgba[world.bread_geom], rgba_before)
    world.command_toaster("STOP")
    run(world, 1.0)
    assert not world.heater_on
    level = world.toast_level
    run(world, 1.0)
    assert world.toast_level == level  # no browning with the lever up
    assert world.bread_position()[2] > 0.15  # popped up


def test_toast_colors() -> None:
    assert classify_toast(0.0) == "WHITE"
    assert classify_toast(GOLDEN_LEVEL) == "GOLDEN"
    assert classify_toast(1.7) == "BURNT"
    assert toast_rgba(0.0)[0] > toast_rgba(1.0)[0] > toast_rgba(2.0)[0]


def test_bad_commands_are_rejected() -> None:
    world = ToastKitchen()
    with pytest.raises(ValueError):
        world.command_joints(["elbow"], [1.0])
    with pytest.raises(ValueError):
        world.command_joints(["lift"], [float("nan")])
    with pytest.raises(ValueError):
        world.command_toaster("BREW")


def test_reset_restores_everything() -> None:
    world = ToastKitchen()
    world.command_joints(["base_yaw"], [1.0])
    world.command_toaster("START")
    world.toast_level = 1.0
    run(world, 1.0)
    world.reset()
    assert world.time == 0.0
    assert world.toast_level == 0.0
    assert world.arm_position()[0] == 0.0
    assert world.distance_mm() < 25
    assert world.distance_mm() != DISTANCE_MAX_MM
