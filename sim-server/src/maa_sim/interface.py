"""The controller-side interface of the simulator: topic names, message types and their meaning.

This is the contract for the platform components (sensors and actuators) of a generated
application; docs/simulation.md documents it for users. Messages are in JSON form
(`maa_sim.messages`), the same in ROS 2 mode, in lock-step mode and over rosbridge.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any, Literal, cast

from .messages import JsonMessage, MessageError
from .protocol import SIMULATOR_TOPICS
from .world import ARM_JOINTS, JOINT_NAMES, TOAST_COLORS, ToastKitchen

Direction = Literal["sim", "controller"]


@dataclass(frozen=True)
class TopicSpec:
    name: str
    type: str
    #: who publishes: "sim" (sensors and state) or "controller" (actuator commands)
    publisher: Direction
    description: str


#: The platform topics, from @maa/protocol's SIMULATOR_TOPICS (the one definition; the IDE reads it too).
_TOPICS: dict[str, TopicSpec] = {
    t["name"]: TopicSpec(t["name"], t["type"], cast(Direction, t["publisher"]), t["description"])
    for t in SIMULATOR_TOPICS
}
CLOCK = _TOPICS["/clock"]
JOINT_STATES = _TOPICS["/joint_states"]
JOINT_COMMAND = _TOPICS["/arm/joint_command"]
GRIPPER_COMMAND = _TOPICS["/arm/gripper_command"]
TOASTER_COMMAND = _TOPICS["/toaster/command"]
DISTANCE = _TOPICS["/sensors/distance"]
COLOR = _TOPICS["/sensors/color"]

SIM_OUTPUTS: tuple[TopicSpec, ...] = (CLOCK, JOINT_STATES, DISTANCE, COLOR)
SIM_INPUTS: tuple[TopicSpec, ...] = (JOINT_COMMAND, GRIPPER_COMMAND, TOASTER_COMMAND)
ALL_TOPICS: dict[str, TopicSpec] = {t.name: t for t in (*SIM_OUTPUTS, *SIM_INPUTS)}


def time_message(seconds: float) -> JsonMessage:
    """builtin_interfaces/Time of a time in seconds (exact to the nanosecond)."""
    total = round(seconds * 1e9)
    return {"sec": total // 1_000_000_000, "nanosec": total % 1_000_000_000}


def time_seconds(stamp: Any) -> float:
    """Seconds of a builtin_interfaces/Time in JSON form."""
    if not isinstance(stamp, dict):
        raise MessageError("expected a time {sec, nanosec}")
    return float(stamp.get("sec", 0)) + float(stamp.get("nanosec", 0)) * 1e-9


def sim_outputs(world: ToastKitchen, clock: float) -> dict[str, JsonMessage]:
    """The messages the simulator publishes once per control period."""
    stamp = time_message(clock)
    joints = world.joint_state()
    return {
        CLOCK.name: {"clock": stamp},
        JOINT_STATES.name: {
            "header": {"stamp": stamp, "frame_id": ""},
            "name": list(joints.name),
            "position": joints.position,
            "velocity": joints.velocity,
            "effort": joints.effort,
        },
        DISTANCE.name: {"data": world.distance_mm()},
        COLOR.name: {"data": world.color()},
    }


def _number(value: Any, what: str) -> float:
    if isinstance(value, bool) or not isinstance(value, int | float):
        raise MessageError(f"{what} must be a number")
    return float(value)


def apply_command(world: ToastKitchen, topic: str, msg: JsonMessage) -> None:
    """Applies an actuator message to the world; raises MessageError for a message that does not fit."""
    if not isinstance(msg, dict):
        raise MessageError(f"{topic}: a message must be an object")
    try:
        if topic == JOINT_COMMAND.name:
            names = msg.get("name", [])
            positions = msg.get("position", [])
            if not isinstance(names, list) or not all(isinstance(n, str) for n in names):
                raise MessageError("name must be a list of joint names")
            if not isinstance(positions, list):
                raise MessageError("position must be a list of numbers")
            unknown = [n for n in names if n not in ARM_JOINTS]
            if unknown:
                raise MessageError(f"unknown joints {unknown} (expected {list(ARM_JOINTS)})")
            world.command_joints(names, [_number(p, "position") for p in positions])
        elif topic == GRIPPER_COMMAND.name:
            world.command_gripper(_number(msg.get("data", 0.0), "data"))
        elif topic == TOASTER_COMMAND.name:
            data = msg.get("data", "")
            if not isinstance(data, str):
                raise MessageError("data must be START or STOP")
            world.command_toaster(data)
        else:
            raise MessageError(f"{topic} is not an actuator topic")
    except MessageError:
        raise
    except ValueError as exc:
        raise MessageError(str(exc)) from None


def check_client_message(topic: str, msg: JsonMessage) -> None:
    """A client's message (rosbridge) on one of the simulator's own topics must look like the
    simulator's: the nodes and the lock-step controller read these topics trusting their shape
    (all four joints, one value per joint), as they may. MessageError says what is wrong.
    The message has been checked against its type already; other topics pass unchanged."""
    if topic == CLOCK.name:
        raise MessageError("/clock is the simulator's: a client cannot set the simulation time")
    if topic == JOINT_STATES.name:
        names = msg.get("name")
        if not isinstance(names, list) or sorted(names) != sorted(JOINT_NAMES):
            raise MessageError(f"/joint_states: name must list each of {', '.join(JOINT_NAMES)} once")
        for field in ("position", "velocity"):
            values = msg.get(field)
            if not isinstance(values, list) or len(values) != len(names):
                raise MessageError(f"/joint_states: {field} needs one value per name ({len(names)})")
        effort = msg.get("effort")
        if not isinstance(effort, list) or len(effort) not in (0, len(names)):
            raise MessageError("/joint_states: effort needs one value per name, or none")
    elif topic == COLOR.name and msg.get("data") not in TOAST_COLORS:
        raise MessageError(f"/sensors/color: data must be one of {', '.join(TOAST_COLORS)}")
