"""`maa-sim run --record FILE.mcap`: every topic of a run and the scene state in an MCAP file.

The file is what a ROS 2 bag in MCAP holds (profile `ros2`): one channel per topic with message
encoding `cdr`, schemas in `ros2msg` text (maa_sim.msgdefs), so Foxglove/Lichtblick, `ros2 bag`
and the `mcap` reader libraries read it. Messages are stamped with the simulation clock (log and
publish time, in ns), so a player replays the run in simulated time.

Written safely: the recorder writes `FILE.mcap.part` beside the final name, completes a chunk
and writes it out about once a second, and renames the file to `FILE.mcap` when the run ends
(the MCAP summary is complete then). A run that is killed leaves no file under the final name,
only the `.part` file, which holds every chunk written before (readable by a streaming reader, or
after `mcap recover`).
"""

from __future__ import annotations

import os
import threading
import time
from collections.abc import Callable, Iterable
from pathlib import Path
from typing import IO, Any

import mujoco
from mcap.records import Schema
from mcap_ros2.writer import Writer

from .interface import time_message
from .messages import JsonMessage, MessageError, normalize_type
from .msgdefs import message_definition
from .protocol import AUTOMATON_STATES_TOPIC, PROGRAM_STEPS_TOPIC, TRANSITIONS_TOPIC, SimulatorRecording
from .world import ToastKitchen, classify_toast

#: The scene state topic and its type (maa_sim/msg/SceneState.msg)
SCENE_TOPIC = "/sim/scene"
SCENE_TYPE = "maa_sim/msg/SceneState"
#: The application's event topics (std_msgs/msg/String, JSON in `data`): recorded in ROS 2 mode
#: too, where no controller declares them (docs/simulation.md "Recording")
EVENT_TOPICS = (AUTOMATON_STATES_TOPIC, TRANSITIONS_TOPIC, PROGRAM_STEPS_TOPIC)
#: At most a second of a run stays in memory: then the chunk in progress is completed and written.
FLUSH_SECONDS = 1.0


def part_path(path: Path) -> Path:
    """Where a recording is written until it is complete."""
    return path.with_name(path.name + ".part")


class McapRecorder:
    """An MCAP file of ROS 2 messages in JSON form, written to `<path>.part` until `close()`."""

    def __init__(self, path: Path) -> None:
        self.path = path
        self.part = part_path(path)
        self.part.parent.mkdir(parents=True, exist_ok=True)
        self._file: IO[bytes] = open(self.part, "wb")  # noqa: SIM115 - closed in close()
        self._writer = Writer(self._file)
        self._schemas: dict[str, Schema] = {}
        self._types: dict[str, str] = {}
        #: messages written per topic
        self.counts: dict[str, int] = {}
        self._lock = threading.Lock()
        self._last_flush = time.monotonic()
        self._closed = False

    def add_topic(self, topic: str, type_name: str) -> None:
        """Declares a topic's type (its schema is written once per type); MessageError when the type
        has no definition."""
        normalized = normalize_type(type_name)
        with self._lock:
            if normalized not in self._schemas:
                try:
                    definition = message_definition(normalized)
                except (OSError, UnicodeDecodeError) as exc:
                    raise MessageError(f"no definition of {normalized}: {exc}") from None
                self._schemas[normalized] = self._writer.register_msgdef(normalized, definition)
            self._types[topic] = normalized
            self.counts.setdefault(topic, 0)

    def write(self, topic: str, msg: JsonMessage, stamp_ns: int) -> None:
        """Writes a message of a declared topic; after `close()` it is dropped."""
        with self._lock:
            if self._closed:
                return
            schema = self._schemas[self._types[topic]]
            self._writer.write_message(topic, schema, msg, log_time=stamp_ns, publish_time=stamp_ns)
            self.counts[topic] += 1
            now = time.monotonic()
            if now - self._last_flush >= FLUSH_SECONDS:
                # completes the chunk in progress and writes it (mcap_ros2's Writer wraps mcap's,
                # whose flush() does that; it has no flush of its own)
                self._writer._writer.flush()  # type: ignore[no-untyped-call]
                self._last_flush = now

    @property
    def messages(self) -> int:
        with self._lock:
            return sum(self.counts.values())

    def close(self) -> None:
        """Completes the file (summary, footer) and moves it to its final name."""
        with self._lock:
            if self._closed:
                return
            self._closed = True
            try:
                self._writer.finish()  # type: ignore[no-untyped-call]
                self._file.flush()
                os.fsync(self._file.fileno())
            finally:
                self._file.close()
        os.replace(self.part, self.path)

    def summary(self) -> SimulatorRecording:
        """The file, its message count and the count per topic (for the finished line)."""
        with self._lock:
            return {"path": str(self.path), "messages": sum(self.counts.values()), "topics": dict(self.counts)}


def scene_state(world: ToastKitchen, clock: float) -> JsonMessage:
    """The scene after a period as a maa_sim/msg/SceneState in JSON form."""
    model, data = world.model, world.data
    names: list[str] = []
    poses: list[JsonMessage] = []
    for body in range(1, model.nbody):  # body 0 is the world
        names.append(mujoco.mj_id2name(model, mujoco.mjtObj.mjOBJ_BODY, body) or f"body{body}")
        x, y, z = (float(v) for v in data.xpos[body])
        qw, qx, qy, qz = (float(v) for v in data.xquat[body])
        poses.append({"position": {"x": x, "y": y, "z": z}, "orientation": {"x": qx, "y": qy, "z": qz, "w": qw}})
    return {
        "stamp": time_message(clock),
        "heater_on": world.heater_on,
        "lever_position": float(world.lever_position()),
        "toast_level": float(world.toast_level),
        "toast_class": classify_toast(world.toast_level),
        "bread_held": world.bread_held(),
        "toast_on_plate": world.toast_on_plate(),
        "body_names": names,
        "body_poses": poses,
    }


def record_topics(
    recorder: McapRecorder,
    topics: Iterable[tuple[str, str]],
    subscribe: Callable[[str, str, Callable[[str, JsonMessage], None]], Any],
    clock: Callable[[], float],
    warn: Callable[[str], None],
) -> list[str]:
    """Subscribes the recorder to every topic (stamped with the simulation clock when they arrive).
    A topic whose type has no definition or cannot be subscribed to is reported and left out;
    returns the recorded topics."""
    recorded: list[str] = []
    for topic, type_name in topics:
        try:
            recorder.add_topic(topic, type_name)
            subscribe(topic, type_name, lambda t, msg: recorder.write(t, msg, round(clock() * 1e9)))
        except MessageError as exc:
            warn(f"{topic} ({type_name}) is not recorded: {exc}")
            continue
        recorded.append(topic)
    return recorded


def record_scene(recorder: McapRecorder) -> Callable[[ToastKitchen, float], None]:
    """A period listener that writes the scene state on /sim/scene."""
    recorder.add_topic(SCENE_TOPIC, SCENE_TYPE)

    def on_period(world: ToastKitchen, clock: float) -> None:
        recorder.write(SCENE_TOPIC, scene_state(world, clock), round(clock * 1e9))

    return on_period


def inspect_recording(path: Path) -> JsonMessage:
    """What a recording holds, every message decoded with its schema (`maa-sim inspect`): the
    profile, and per channel the topic, schema name and encodings and the message count."""
    from mcap.reader import make_reader
    from mcap_ros2.decoder import DecoderFactory

    counts: dict[int, int] = {}
    with path.open("rb") as stream:
        reader = make_reader(stream, decoder_factories=[DecoderFactory()])
        header = reader.get_header()
        for _schema, channel, _message, _decoded in reader.iter_decoded_messages():
            counts[channel.id] = counts.get(channel.id, 0) + 1
        summary = reader.get_summary()
    channels: list[JsonMessage] = []
    if summary is not None:
        for channel in sorted(summary.channels.values(), key=lambda c: c.topic):
            schema = summary.schemas.get(channel.schema_id)
            channels.append(
                {
                    "topic": channel.topic,
                    "message_encoding": channel.message_encoding,
                    "schema": schema.name if schema is not None else None,
                    "schema_encoding": schema.encoding if schema is not None else None,
                    "messages": counts.get(channel.id, 0),
                }
            )
    return {
        "path": str(path),
        "profile": header.profile,
        "messages": sum(counts.values()),
        "complete": summary is not None,
        "channels": channels,
    }
