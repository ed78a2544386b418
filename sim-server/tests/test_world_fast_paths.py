"""The world's fast paths give what the plain computations give (sim-server/bench: lock-step speed).

`bread_in_slot` computes the toaster-frame coordinates in plain floats and leaves points near a
bound of the slot to numpy; `joint_state` reads the joints with one fancy index per array; `step`
draws the bread's colour once per call.
"""

from __future__ import annotations

import mujoco
import numpy as np

from maa_sim.world import JOINT_NAMES, LEVER_DOWN, ToastKitchen, toast_rgba

#: The slot in the toaster's frame: |x| < 0.015, |y| < 0.06, 0 < z < 0.2.
BOUNDS = ((0.015, 0), (-0.015, 0), (0.06, 1), (-0.06, 1), (0.0, 2), (0.2, 2))


def numpy_in_slot(world: ToastKitchen) -> bool:
    d = world.data
    rot = d.xmat[world.toaster_body].reshape(3, 3)
    local = rot.T @ (d.xpos[world.bread_body] - d.xpos[world.toaster_body])
    return bool(abs(local[0]) < 0.015 and abs(local[1]) < 0.06 and 0.0 < local[2] < 0.2)


def place(world: ToastKitchen, local: np.ndarray) -> None:
    """Puts the bread's frame position at a point given in the toaster's frame."""
    d = world.data
    rot = d.xmat[world.toaster_body].reshape(3, 3)
    d.xpos[world.bread_body] = d.xpos[world.toaster_body] + rot @ local


def test_bread_in_slot_agrees_with_numpy_inside_outside_and_on_the_bounds() -> None:
    world = ToastKitchen()
    rng = np.random.default_rng(3)
    inside = outside = 0
    for _ in range(3000):
        local = rng.uniform((-0.03, -0.1, -0.05), (0.03, 0.1, 0.25))
        place(world, local)
        expected = numpy_in_slot(world)
        assert world.bread_in_slot() == expected
        inside, outside = inside + expected, outside + (not expected)
    # right at a bound (within rounding): the answer is numpy's
    for bound, axis in BOUNDS:
        for offset in (-1e-15, 0.0, 1e-15, -1e-10, 1e-10, -1e-8, 1e-8):
            local = np.array([0.0, 0.0, 0.1])
            local[axis] = bound + offset
            place(world, local)
            assert world.bread_in_slot() == numpy_in_slot(world), (bound, axis, offset)
    assert inside > 100 and outside > 100


def test_joint_state_reads_every_joint() -> None:
    world = ToastKitchen()
    world.command_joints(["base_yaw", "lift"], [0.5, 0.1])
    world.step(50)
    sample = world.joint_state()
    d = world.data
    assert sample.name == JOINT_NAMES
    for i, name in enumerate(JOINT_NAMES):
        assert sample.position[i] == float(d.qpos[world._qadr[name]])
        assert sample.velocity[i] == float(d.qvel[world._dadr[name]])
        assert sample.effort[i] == float(d.qfrc_actuator[world._dadr[name]])
        assert type(sample.position[i]) is float


def test_the_bread_is_drawn_in_the_colour_of_its_toast_level_after_every_step() -> None:
    world = ToastKitchen()
    m, d = world.model, world.data
    # the bread straight into the slot, the lever pushed down: it toasts
    rot = d.xmat[world.toaster_body].reshape(3, 3)
    bread = world._qadr["bread"]
    d.qpos[bread : bread + 3] = d.xpos[world.toaster_body] + rot @ np.array([0.0, 0.0, 0.05])
    d.qpos[world._qadr["toaster_lever"]] = LEVER_DOWN
    world.command_toaster("START")
    mujoco.mj_forward(m, d)
    levels = []
    for _ in range(20):
        world.step(7)
        levels.append(world.toast_level)
        drawn = m.geom_rgba[world.bread_geom]
        assert np.array_equal(drawn, toast_rgba(world.toast_level).astype(drawn.dtype))
    assert levels[-1] > 0.0 and levels == sorted(levels)
