"""The toast kitchen: a MuJoCo model plus the parts of the world that are not rigid-body physics.

`ToastKitchen` owns the `MjModel`/`MjData` pair and adds, on top of the physics:

* the arm's joint controller: joint commands set targets, and the position actuators follow
  a reference that moves towards the target at a bounded speed (like a robot driver's
  trajectory generator), so the arm does not jerk and a held slice stays in the gripper;
* the toaster: the lever is pushed down by `START` and released by `STOP`; while the lever is
  down and the bread is in the slot, the bread browns (its toast level rises and its colour,
  the geom's rgba, changes);
* the sensors: a distance sensor (MuJoCo rangefinder, millimetres) at the bread holder and a
  colour sensor in the toaster's slot wall (a ray; it classifies the toast level of the bread
  when the ray hits the bread).

Everything here is deterministic: no wall clock, no global random state.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from importlib import resources
from pathlib import Path

import mujoco
import numpy as np
import numpy.typing as npt

PACKAGE = "maa_sim"

#: Joints reported on /joint_states, in this order.
JOINT_NAMES: tuple[str, ...] = ("base_yaw", "lift", "finger_inner", "finger_outer")
#: Joints accepted on /arm/joint_command.
ARM_JOINTS: tuple[str, ...] = ("base_yaw", "lift")

#: Joint limits of the arm (SI units), the reference arm of docs/robotarm.md.
YAW_RANGE = (-math.pi, math.pi)
LIFT_RANGE = (0.02, 0.30)
#: The gripper opening (distance between the finger pads, m).
GRIPPER_RANGE = (0.0, 0.08)
#: The opening that `open` commands in the fixture controllers.
GRIPPER_OPEN = 0.06

#: Speed limits of the joint reference (rad/s, m/s, m/s of opening).
YAW_SPEED = math.radians(120.0)
LIFT_SPEED = 0.20
GRIPPER_SPEED = 0.10

#: Lever positions of the toaster (slide joint, m).
LEVER_UP = 0.0
LEVER_DOWN = -0.10

#: Colour classes of ToastColor, by toast level: 0 = fresh bread, 1 = ideal toast.
TOAST_COLORS: tuple[str, ...] = ("WHITE", "GOLDEN", "BURNT")
GOLDEN_LEVEL = 0.8
BURNT_LEVEL = 1.6
#: The colour sensor sees the bread up to this far along its ray (m).
COLOR_RANGE = 0.05
#: Distance sensor reading when nothing is within the range finder's cut-off (mm).
DISTANCE_MAX_MM = 2000

_BREAD_RGBA = np.array([0.96, 0.90, 0.74, 1.0])
_GOLDEN_RGBA = np.array([0.83, 0.58, 0.24, 1.0])
_BURNT_RGBA = np.array([0.16, 0.09, 0.05, 1.0])

#: Named locations of the scene (angle in degrees, gripper height in centimetres).
LOCATIONS: dict[str, tuple[float, float]] = {
    "bread": (0.0, 7.0),
    "toaster": (120.0, 20.0),
    "plate": (-120.0, 9.0),
    "top": (0.0, 30.0),  # only the height is meaningful: `move top` keeps the angle
}

#: Plate centre (x, y) and radius, top surface height (m).
PLATE_CENTER = (-0.15, -0.25980762)
PLATE_RADIUS = 0.08
PLATE_TOP = 0.01


def scene_path(scene: str) -> Path:
    """The MJCF file of a scene shipped with the package (`toast_kitchen`)."""
    if not scene.replace("_", "").isalnum():
        raise ValueError(f"invalid scene name {scene!r}")
    resource = resources.files(PACKAGE).joinpath("scenes", f"{scene}.xml")
    path = Path(str(resource))
    if not path.is_file():
        raise FileNotFoundError(f"unknown scene {scene!r} (no {path})")
    return path


def _id(model: mujoco.MjModel, kind: mujoco.mjtObj, name: str) -> int:
    found = int(mujoco.mj_name2id(model, kind, name))
    if found < 0:
        raise ValueError(f"the scene has no {kind.name.removeprefix('mjOBJ_').lower()} named {name!r}")
    return found


def toast_rgba(level: float) -> npt.NDArray[np.float64]:
    """The bread's colour for a toast level (0 fresh, 1 golden, 2 burnt)."""
    if level <= 1.0:
        t = max(level, 0.0)
        return (1.0 - t) * _BREAD_RGBA + t * _GOLDEN_RGBA
    t = min(level - 1.0, 1.0)
    return (1.0 - t) * _GOLDEN_RGBA + t * _BURNT_RGBA


_BREAD_RGBA_F = _BREAD_RGBA.tolist()
_GOLDEN_RGBA_F = _GOLDEN_RGBA.tolist()
_BURNT_RGBA_F = _BURNT_RGBA.tolist()


def _toast_rgba_floats(level: float) -> list[float]:
    """`toast_rgba` in plain floats (the same products and sums per component, so the same
    values bit for bit, a few times faster than numpy for four components)."""
    if level <= 1.0:
        t = max(level, 0.0)
        a, b = _BREAD_RGBA_F, _GOLDEN_RGBA_F
    else:
        t = min(level - 1.0, 1.0)
        a, b = _GOLDEN_RGBA_F, _BURNT_RGBA_F
    s = 1.0 - t
    return [s * a[0] + t * b[0], s * a[1] + t * b[1], s * a[2] + t * b[2], s * a[3] + t * b[3]]


def classify_toast(level: float) -> str:
    """ToastColor of a toast level."""
    if level >= BURNT_LEVEL:
        return "BURNT"
    if level >= GOLDEN_LEVEL:
        return "GOLDEN"
    return "WHITE"


@dataclass
class WorldConfig:
    """Parameters of the world that are not in the MJCF file."""

    #: Seconds of toasting from fresh bread to toast level 1 (golden is classified at 0.8).
    golden_seconds: float = 6.0
    #: Standard deviation of the bread's initial position jitter (m); 0 = none. Drawn from the seed.
    bread_jitter: float = 0.0
    seed: int = 0


@dataclass
class _Reference:
    target: float
    value: float
    speed: float
    low: float
    high: float

    @property
    def settled(self) -> bool:
        return self.value == self.target

    def advance(self, dt: float) -> float:
        step = self.speed * dt
        delta = self.target - self.value
        if abs(delta) <= step:
            self.value = self.target
        else:
            self.value += math.copysign(step, delta)
        return self.value

    def set_target(self, value: float) -> None:
        self.target = min(max(value, self.low), self.high)


@dataclass
class JointStateSample:
    name: tuple[str, ...]
    position: list[float]
    velocity: list[float]
    effort: list[float]


@dataclass
class ToastKitchen:
    """The simulated world of the ToastServiceRobot."""

    scene: str = "toast_kitchen"
    config: WorldConfig = field(default_factory=WorldConfig)

    def __post_init__(self) -> None:
        self.model = mujoco.MjModel.from_xml_path(str(scene_path(self.scene)))
        self.data = mujoco.MjData(self.model)
        m = self.model

        def jid(name: str) -> int:
            return _id(m, mujoco.mjtObj.mjOBJ_JOINT, name)

        def gid(name: str) -> int:
            return _id(m, mujoco.mjtObj.mjOBJ_GEOM, name)

        def bid(name: str) -> int:
            return _id(m, mujoco.mjtObj.mjOBJ_BODY, name)

        def sid(name: str) -> int:
            return _id(m, mujoco.mjtObj.mjOBJ_SITE, name)

        self._qadr = {n: int(m.jnt_qposadr[jid(n)]) for n in (*JOINT_NAMES, "toaster_lever", "bread")}
        self._dadr = {n: int(m.jnt_dofadr[jid(n)]) for n in (*JOINT_NAMES, "toaster_lever", "bread")}
        self._joint_q = np.array([self._qadr[n] for n in JOINT_NAMES], dtype=np.intp)
        self._joint_d = np.array([self._dadr[n] for n in JOINT_NAMES], dtype=np.intp)
        self._act = {mujoco.mj_id2name(m, mujoco.mjtObj.mjOBJ_ACTUATOR, i): i for i in range(m.nu)}
        act = self._act
        self._ctrl_yaw, self._ctrl_lift = act["base_yaw"], act["lift"]
        self._ctrl_fingers = (act["finger_inner"], act["finger_outer"])
        self.bread_geom = gid("bread")
        self.bread_body = bid("bread")
        self.plate_geom = gid("plate")
        self.finger_geoms = (gid("finger_inner"), gid("finger_outer"))
        self.toaster_body = bid("toaster")
        self._color_site = sid("color_sensor")
        self._distance_adr = int(m.sensor_adr[_id(m, mujoco.mjtObj.mjOBJ_SENSOR, "distance")])
        self._ray_geom = np.zeros(1, dtype=np.int32)
        self._initial_bread_pos = np.array(m.body_pos[self.bread_body])
        # views into `data` (its arrays stay where they are for the world's life), read every step
        self._bread_xpos = self.data.xpos[self.bread_body]
        self._toaster_xpos = self.data.xpos[self.toaster_body]
        self._toaster_xmat = self.data.xmat[self.toaster_body]
        self._color_xpos = self.data.site_xpos[self._color_site]
        self._color_xmat = self.data.site_xmat[self._color_site]
        self._bread_geom_xpos = self.data.geom_xpos[self.bread_geom]
        #: the colour ray's range (5 cm) plus the bread's bounding radius, with a margin for rounding
        self._ray_reach = COLOR_RANGE + float(m.geom_rbound[self.bread_geom]) + 1e-6
        self._ray_pnt = np.zeros(3)
        self._ray_vec = np.zeros(3)
        self._toaster_rot_t = self._toaster_xmat.reshape(3, 3).T
        # the toaster is fixed to the world (no joint, not mocap): its frame is the same at every
        # step, so bread_in_slot takes it in plain floats, read after each reset's mj_forward
        tb = self.toaster_body
        self._toaster_static = (
            int(m.body_weldid[tb]) == 0 and int(m.body_mocapid[tb]) < 0 and int(m.body_jntnum[tb]) == 0
        )
        self._toaster_frame: tuple[list[float], list[float]] | None = None
        self.reset(self.config.seed)

    # ----------------------------------------------------------------------------- lifecycle

    @property
    def timestep(self) -> float:
        return float(self.model.opt.timestep)

    @property
    def time(self) -> float:
        return float(self.data.time)

    def reset(self, seed: int | None = None) -> None:
        """Puts everything back: arm at the top, gripper open, lever up, fresh bread in the holder."""
        if seed is not None:
            self.config.seed = seed
        m, d = self.model, self.data
        mujoco.mj_resetData(m, d)
        rng = np.random.default_rng(self.config.seed)
        bread = self._qadr["bread"]
        d.qpos[bread : bread + 3] = self._initial_bread_pos
        if self.config.bread_jitter > 0:
            d.qpos[bread : bread + 2] += rng.normal(0.0, self.config.bread_jitter, 2)
        d.qpos[bread + 3 : bread + 7] = (1.0, 0.0, 0.0, 0.0)
        d.qpos[self._qadr["lift"]] = LIFT_RANGE[1]
        half = GRIPPER_OPEN / 2
        d.qpos[self._qadr["finger_inner"]] = half
        d.qpos[self._qadr["finger_outer"]] = half
        self._yaw = _Reference(0.0, 0.0, YAW_SPEED, *YAW_RANGE)
        self._lift = _Reference(LIFT_RANGE[1], LIFT_RANGE[1], LIFT_SPEED, *LIFT_RANGE)
        self._grip = _Reference(GRIPPER_OPEN, GRIPPER_OPEN, GRIPPER_SPEED, *GRIPPER_RANGE)
        self._lever_target = LEVER_UP
        self.toast_level = 0.0
        # the control targets are applied once here and whenever a reference moves
        m.geom_rgba[self.bread_geom] = toast_rgba(0.0)
        self._apply_ctrl()
        mujoco.mj_forward(m, d)
        static = self._toaster_static
        self._toaster_frame = (self._toaster_xpos.tolist(), self._toaster_xmat.tolist()) if static else None

    # ----------------------------------------------------------------------------- commands

    def command_joints(self, names: list[str], positions: list[float]) -> None:
        """Sets joint targets (`base_yaw` rad, `lift` m); unknown names raise ValueError."""
        if len(names) != len(positions):
            raise ValueError("name and position must have the same length")
        for name, value in zip(names, positions, strict=True):
            if not math.isfinite(value):
                raise ValueError(f"position of {name} is not finite")
            if name == "base_yaw":
                self._yaw.set_target(value)
            elif name == "lift":
                self._lift.set_target(value)
            else:
                raise ValueError(f"unknown joint {name!r} (expected one of {', '.join(ARM_JOINTS)})")

    def command_gripper(self, opening: float) -> None:
        """Sets the gripper opening (m, 0 closes with limited force)."""
        if not math.isfinite(opening):
            raise ValueError("gripper opening is not finite")
        self._grip.set_target(opening)

    def command_toaster(self, command: str) -> None:
        """`START` pushes the lever down, `STOP` releases it."""
        cmd = command.strip().upper()
        if cmd == "START":
            self._lever_target = LEVER_DOWN
        elif cmd == "STOP":
            self._lever_target = LEVER_UP
        else:
            raise ValueError(f"unknown toaster command {command!r} (expected START or STOP)")
        self.data.ctrl[self._act["toaster_lever"]] = self._lever_target

    # ----------------------------------------------------------------------------- stepping

    def _apply_ctrl(self) -> None:
        ctrl = self.data.ctrl
        act = self._act
        ctrl[act["base_yaw"]] = self._yaw.value
        ctrl[act["lift"]] = self._lift.value
        half = self._grip.value / 2
        ctrl[act["finger_inner"]] = half
        ctrl[act["finger_outer"]] = half
        ctrl[act["toaster_lever"]] = self._lever_target

    def step(self, n: int = 1) -> None:
        """Advances the world by n physics steps.

        The per-step work around `mj_step` is the lock-step loop's own cost (sim-server/bench):
        the arrays of `data` are views that stay valid across steps, so they are looked up once;
        the references that move are advanced in local floats with `_Reference.advance`'s
        arithmetic (the same values bit for bit) and only their actuators' controls are written
        (nothing else writes the arm's controls between steps).
        """
        m, d = self.model, self.data
        dt = self.timestep
        refs = (self._yaw, self._lift, self._grip)
        yaw_v, lift_v, grip_v = (r.value for r in refs)
        yaw_t, lift_t, grip_t = (r.target for r in refs)
        yaw_s, lift_s, grip_s = (r.speed * dt for r in refs)
        ctrl = d.ctrl
        c_yaw, c_lift = self._ctrl_yaw, self._ctrl_lift
        c_inner, c_outer = self._ctrl_fingers
        copysign = math.copysign
        qpos = d.qpos
        lever = self._qadr["toaster_lever"]
        heater_below = LEVER_DOWN + 0.01
        in_slot = self.bread_in_slot
        toast_step = dt / self.config.golden_seconds
        step = mujoco.mj_step
        toasted = False
        for _ in range(n):
            if yaw_v != yaw_t:
                delta = yaw_t - yaw_v
                yaw_v = yaw_t if abs(delta) <= yaw_s else yaw_v + copysign(yaw_s, delta)
                ctrl[c_yaw] = yaw_v
            if lift_v != lift_t:
                delta = lift_t - lift_v
                lift_v = lift_t if abs(delta) <= lift_s else lift_v + copysign(lift_s, delta)
                ctrl[c_lift] = lift_v
            if grip_v != grip_t:
                delta = grip_t - grip_v
                grip_v = grip_t if abs(delta) <= grip_s else grip_v + copysign(grip_s, delta)
                half = grip_v / 2
                ctrl[c_inner] = half
                ctrl[c_outer] = half
            step(m, d)
            if qpos[lever] < heater_below and in_slot():
                self.toast_level += toast_step
                toasted = True
        refs[0].value, refs[1].value, refs[2].value = yaw_v, lift_v, grip_v
        if toasted:  # the colour is only drawn (no physics, no sensor reads it): once per call
            m.geom_rgba[self.bread_geom] = _toast_rgba_floats(self.toast_level)

    # ----------------------------------------------------------------------------- state

    @property
    def heater_on(self) -> bool:
        """The heater runs while the lever is (almost) all the way down."""
        return bool(self.data.qpos[self._qadr["toaster_lever"]] < LEVER_DOWN + 0.01)

    def bread_in_slot(self) -> bool:
        """Whether the bread stands in the toaster's slot (its centre within the slot, up to 4 cm above it)."""
        # In plain floats first (a few times faster than numpy for 3 x 3). Its rounding may differ
        # from numpy's in the last bits, so numpy decides whenever a coordinate is that close to a
        # bound of the slot: the answer is numpy's either way.
        bx, by, bz = self._bread_xpos.tolist()
        frame = self._toaster_frame
        if frame is None:
            frame = (self._toaster_xpos.tolist(), self._toaster_xmat.tolist())
        (tx, ty, tz), r = frame
        dx, dy, dz = bx - tx, by - ty, bz - tz
        x = r[0] * dx + r[3] * dy + r[6] * dz
        y = r[1] * dx + r[4] * dy + r[7] * dz
        z = r[2] * dx + r[5] * dy + r[8] * dz
        near = 1e-9
        if abs(abs(x) - 0.015) < near or abs(abs(y) - 0.06) < near or abs(z) < near or abs(z - 0.2) < near:
            local = self._in_toaster_frame(self._bread_xpos).tolist()
            x, y, z = local[0], local[1], local[2]
        return bool(abs(x) < 0.015 and abs(y) < 0.06 and 0.0 < z < 0.2)

    def _in_toaster_frame(self, point: npt.NDArray[np.float64]) -> npt.NDArray[np.float64]:
        result: npt.NDArray[np.float64] = self._toaster_rot_t @ (point - self._toaster_xpos)
        return result

    def joint_state(self) -> JointStateSample:
        d = self.data
        # one fancy index per array (what `tolist` gives are the same Python floats as float(x))
        pos: list[float] = d.qpos[self._joint_q].tolist()
        vel: list[float] = d.qvel[self._joint_d].tolist()
        eff: list[float] = d.qfrc_actuator[self._joint_d].tolist()
        return JointStateSample(JOINT_NAMES, pos, vel, eff)

    def arm_position(self) -> tuple[float, float, float]:
        """(yaw rad, height m, gripper opening m)."""
        q = self.data.qpos
        return (
            float(q[self._qadr["base_yaw"]]),
            float(q[self._qadr["lift"]]),
            float(q[self._qadr["finger_inner"]] + q[self._qadr["finger_outer"]]),
        )

    def lever_position(self) -> float:
        return float(self.data.qpos[self._qadr["toaster_lever"]])

    def distance_mm(self) -> int:
        """The distance sensor's reading: the range finder in whole millimetres."""
        value = float(self.data.sensordata[self._distance_adr])
        if value < 0:
            return DISTANCE_MAX_MM
        return min(round(value * 1000.0), DISTANCE_MAX_MM)

    def color(self) -> str:
        """The colour sensor's reading: WHITE unless its ray hits the bread."""
        # the ray counts only when it hits the bread within 5 cm: with the bread's bounding sphere
        # farther than that from the sensor it cannot, and the ray is not cast (the same answer)
        sx, sy, sz = self._color_xpos.tolist()
        gx, gy, gz = self._bread_geom_xpos.tolist()
        if math.sqrt((gx - sx) ** 2 + (gy - sy) ** 2 + (gz - sz) ** 2) > self._ray_reach:
            return "WHITE"
        pnt, vec = self._ray_pnt, self._ray_vec
        pnt[:] = self._color_xpos  # the sensor's position and its z axis (the column 2 of its frame)
        vec[:] = self._color_xmat[2::3]
        dist = mujoco.mj_ray(self.model, self.data, pnt, vec, None, 1, -1, self._ray_geom)
        if dist >= 0 and dist < COLOR_RANGE and int(self._ray_geom[0]) == self.bread_geom:
            return classify_toast(self.toast_level)
        return "WHITE"

    def bread_position(self) -> npt.NDArray[np.float64]:
        return np.array(self.data.xpos[self.bread_body])

    def bread_speed(self) -> float:
        adr = self._dadr["bread"]
        return float(np.linalg.norm(self.data.qvel[adr : adr + 3]))

    def contacts_of(self, geom: int) -> set[int]:
        """Geoms in contact with a geom."""
        d = self.data
        found: set[int] = set()
        for i in range(d.ncon):
            c = d.contact[i]
            if c.geom1 == geom:
                found.add(int(c.geom2))
            elif c.geom2 == geom:
                found.add(int(c.geom1))
        return found

    def toast_on_plate(self) -> bool:
        """The goal: the toasted bread rests on the plate and nothing holds it."""
        # the cheap conditions first: this is asked after every period of a run
        if self.toast_level < GOLDEN_LEVEL:
            return False
        pos = self.bread_position()
        dx, dy = pos[0] - PLATE_CENTER[0], pos[1] - PLATE_CENTER[1]
        if math.hypot(dx, dy) >= PLATE_RADIUS:
            return False
        touching = self.contacts_of(self.bread_geom)
        return (
            self.plate_geom in touching and not touching.intersection(self.finger_geoms) and self.bread_speed() < 0.02
        )

    def bread_held(self) -> bool:
        """Both fingers touch the bread."""
        touching = self.contacts_of(self.bread_geom)
        return all(g in touching for g in self.finger_geoms)
