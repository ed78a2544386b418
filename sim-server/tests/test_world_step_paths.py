"""`ToastKitchen.step`'s inlined reference ramps, the toaster frame taken once per reset and the
colour in plain floats give what the plain computations give, bit for bit (sim-server/bench:
lock-step speed)."""

from __future__ import annotations

import math

import mujoco
import numpy as np

from maa_sim.world import LEVER_DOWN, ToastKitchen, _toast_rgba_floats, toast_rgba


def plain_step(world: ToastKitchen, n: int) -> None:
    """The world's step written the plain way: every moving reference through
    `_Reference.advance`, all controls written by `_apply_ctrl`, the toaster frame read from
    `data` and the colour drawn by numpy."""
    m, d = world.model, world.data
    dt = world.timestep
    refs = (world._yaw, world._lift, world._grip)
    toasted = False
    for _ in range(n):
        moving = False
        for ref in refs:
            if not ref.settled:
                ref.advance(dt)
                moving = True
        if moving:
            world._apply_ctrl()
        mujoco.mj_step(m, d)
        rot = d.xmat[world.toaster_body].reshape(3, 3)
        local = rot.T @ (d.xpos[world.bread_body] - d.xpos[world.toaster_body])
        in_slot = abs(local[0]) < 0.015 and abs(local[1]) < 0.06 and 0.0 < local[2] < 0.2
        if d.qpos[world._qadr["toaster_lever"]] < LEVER_DOWN + 0.01 and in_slot:
            world.toast_level += dt / world.config.golden_seconds
            toasted = True
    if toasted:
        m.geom_rgba[world.bread_geom] = toast_rgba(world.toast_level)


def same_state(a: ToastKitchen, b: ToastKitchen) -> bool:
    return (
        np.array_equal(a.data.qpos, b.data.qpos)
        and np.array_equal(a.data.qvel, b.data.qvel)
        and np.array_equal(a.data.ctrl, b.data.ctrl)
        and a.toast_level == b.toast_level
        and np.array_equal(a.model.geom_rgba[a.bread_geom], b.model.geom_rgba[b.bread_geom])
        and [(r.value, r.target) for r in (a._yaw, a._lift, a._grip)]
        == [(r.value, r.target) for r in (b._yaw, b._lift, b._grip)]
    )


def into_the_slot(world: ToastKitchen) -> None:
    """The bread straight into the slot and the lever down: it toasts from the first step."""
    d = world.data
    rot = d.xmat[world.toaster_body].reshape(3, 3)
    bread = world._qadr["bread"]
    d.qpos[bread : bread + 3] = d.xpos[world.toaster_body] + rot @ np.array([0.0, 0.0, 0.05])
    d.qpos[world._qadr["toaster_lever"]] = LEVER_DOWN
    world.command_toaster("START")
    mujoco.mj_forward(world.model, d)


def test_step_moves_the_arm_and_toasts_as_the_plain_step_does() -> None:
    fast, plain = ToastKitchen(), ToastKitchen()
    for world in (fast, plain):
        into_the_slot(world)
    rng = np.random.default_rng(7)
    moved = toasted = 0
    for period in range(150):
        if period % 9 == 0:  # new targets now and then, some out of range (clamped)
            yaw, lift, grip = rng.uniform(-4.0, 4.0), rng.uniform(-0.1, 0.4), rng.uniform(-0.02, 0.1)
            for world in (fast, plain):
                world.command_joints(["base_yaw", "lift"], [yaw, lift])
                world.command_gripper(grip)
        before = fast._lift.value
        n = int(rng.integers(1, 12))
        fast.step(n)
        plain_step(plain, n)
        assert same_state(fast, plain), period
        moved += fast._lift.value != before
        toasted += fast.toast_level > 0.0
    assert moved > 20 and toasted > 20


def test_bread_in_slot_with_the_frame_of_the_reset_is_the_one_read_from_data() -> None:
    world = ToastKitchen()
    assert world._toaster_static and world._toaster_frame is not None
    d = world.data
    rot = d.xmat[world.toaster_body].reshape(3, 3)
    rng = np.random.default_rng(5)
    answers = set()
    for _ in range(2000):
        d.xpos[world.bread_body] = d.xpos[world.toaster_body] + rot @ rng.uniform(
            (-0.03, -0.1, -0.05), (0.03, 0.1, 0.25)
        )
        cached = world.bread_in_slot()
        frame, world._toaster_frame = world._toaster_frame, None
        assert world.bread_in_slot() == cached
        world._toaster_frame = frame
        answers.add(cached)
    assert answers == {True, False}


def test_the_colour_in_floats_is_numpys_bit_for_bit() -> None:
    levels = [-1.0, 0.0, 1e-9, 0.3, 0.8, 1.0, 1.0 + 1e-12, 1.37, 1.6, 2.0, 2.5, math.nextafter(1.0, 2.0)]
    levels += np.random.default_rng(1).uniform(-0.5, 2.5, 500).tolist()
    for level in levels:
        assert _toast_rgba_floats(level) == toast_rgba(level).tolist(), level


def ray_color(world: ToastKitchen) -> str:
    """The colour sensor with its ray always cast."""
    d = world.data
    site = world._color_site
    geom = np.zeros(1, dtype=np.int32)
    dist = mujoco.mj_ray(world.model, d, d.site_xpos[site].copy(), d.site_xmat[site][2::3].copy(), None, 1, -1, geom)
    return "GOLDEN" if 0 <= dist < 0.05 and int(geom[0]) == world.bread_geom else "WHITE"


def test_the_colour_sensor_skips_its_ray_only_where_the_ray_cannot_see_the_bread() -> None:
    world = ToastKitchen()
    world.toast_level = 1.0
    d = world.data
    sensor = d.site_xpos[world._color_site].copy()
    bread = world._qadr["bread"]
    rng = np.random.default_rng(11)
    seen = {"GOLDEN": 0, "WHITE": 0}
    for _ in range(1500):
        d.qpos[bread : bread + 3] = sensor + rng.uniform(-0.12, 0.12, 3)
        quat = rng.normal(size=4)
        d.qpos[bread + 3 : bread + 7] = quat / np.linalg.norm(quat)
        mujoco.mj_forward(world.model, d)
        expected = ray_color(world)
        assert world.color() == expected
        seen[expected] += 1
    assert seen["GOLDEN"] > 20 and seen["WHITE"] > 20
