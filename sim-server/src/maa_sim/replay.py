"""`maa-sim replay FILE.mcap`: a recording of `maa-sim run --record` played back.

The recording is read once (every message decoded with its ROS 2 schema, mcap-ros2-support).
The 3D scene is the viser scene of the live run (the MuJoCo model's geoms, viewer.SceneView),
its bodies moved to the poses the recording's `/sim/scene` holds at the time sought. A rosbridge
endpoint (the same guards as a run's) offers the replay's services:

- `/sim/seek {"time": s}`: moves the scene to the last scene state at or before `s` (simulated
  seconds of the recording); answers the status;
- `/sim/get_status {}`: the recording's span, the time shown and the scene state there;
- `/sim/replay_messages {"exclude": [topics]}`: every recorded message but the scene poses, as
  `{"t", "topic", "message"}` in time order (the simulate view fills its timeline store with them).

Nothing is simulated: the poses are the recorded ones, so a replay shows exactly what the run did.
"""

from __future__ import annotations

import bisect
import contextlib
import struct
import threading
from collections.abc import Callable, Iterable, Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, overload

import mujoco

from .access import AccessPolicy, resolve_token
from .messages import JsonMessage
from .recorder import SCENE_TOPIC
from .transport import LocalBus
from .viewer import CAMERA_PRESETS, SceneView, _rgb
from .world import ToastKitchen, toast_rgba

#: a message of the recording: simulated seconds, topic, the message in rosbridge's JSON form
TimedMessage = tuple[float, str, JsonMessage]


class RecordingError(Exception):
    """A file that is no readable recording (not MCAP, truncated, no scene states)."""


def to_json(value: Any) -> Any:
    """A message decoded by mcap-ros2-support (objects with `__slots__`) in rosbridge's JSON form."""
    if isinstance(value, (bool, int, float, str)) or value is None:
        return value
    if isinstance(value, (bytes, bytearray)):
        return list(value)
    if isinstance(value, (list, tuple)):
        return [to_json(v) for v in value]
    slots = getattr(type(value), "__slots__", None)
    if slots is not None:
        return {name: to_json(getattr(value, name)) for name in slots if not name.startswith("_")}
    if hasattr(value, "tolist"):  # numpy arrays of fixed-size fields
        return value.tolist()
    return str(value)


class LazyScenes(Sequence[JsonMessage]):
    """The scene states of a recording, decoded when first asked for (they are most of a recording's
    bytes and of its decoding time; a replay shows only those it seeks to). The same object is
    returned for an index every time."""

    def __init__(self) -> None:
        self._data: list[bytes] = []
        self._decode: list[Callable[[bytes], Any]] = []
        self._decoded: dict[int, JsonMessage] = {}

    def append_raw(self, data: bytes, decode: Callable[[bytes], Any]) -> None:
        self._data.append(data)
        self._decode.append(decode)

    def __len__(self) -> int:
        return len(self._data)

    @overload
    def __getitem__(self, index: int) -> JsonMessage: ...
    @overload
    def __getitem__(self, index: slice) -> Sequence[JsonMessage]: ...
    def __getitem__(self, index: int | slice) -> JsonMessage | Sequence[JsonMessage]:
        if isinstance(index, slice):
            return [self[i] for i in range(*index.indices(len(self)))]
        i = index + len(self._data) if index < 0 else index
        if not 0 <= i < len(self._data):
            raise IndexError(index)
        scene = self._decoded.get(i)
        if scene is None:
            scene = to_json(self._decode[i](self._data[i]))
            self._decoded[i] = scene
        return scene


@dataclass
class Recording:
    """What a recording holds: the scene states by time and every other message."""

    path: Path
    scene_times: list[float] = field(default_factory=list)
    scenes: LazyScenes = field(default_factory=LazyScenes)
    messages: list[TimedMessage] = field(default_factory=list)

    @property
    def start(self) -> float:
        firsts = self.scene_times[:1] + [m[0] for m in self.messages[:1]]
        return min(firsts) if firsts else 0.0

    @property
    def end(self) -> float:
        lasts = self.scene_times[-1:] + [m[0] for m in self.messages[-1:]]
        return max(lasts) if lasts else 0.0

    def scene_at(self, t: float) -> JsonMessage | None:
        """The last scene state at or before `t` (the first one before the recording's first)."""
        if not self.scenes:
            return None
        i = bisect.bisect_right(self.scene_times, t)
        return self.scenes[max(i - 1, 0)]

    def topics(self) -> list[str]:
        return sorted({topic for _, topic, _ in self.messages} | ({SCENE_TOPIC} if self.scenes else set()))

    def select(self, exclude: Iterable[str] = ()) -> list[JsonMessage]:
        """The messages (without the scene poses) as the simulate view's TimedMessage objects."""
        left_out = set(exclude)
        return [{"t": t, "topic": topic, "message": msg} for t, topic, msg in self.messages if topic not in left_out]


def load_recording(path: Path) -> Recording:
    """Reads and decodes a complete recording (a `.part` file of a killed run too, as far as it goes)."""
    from mcap.exceptions import McapError
    from mcap.reader import make_reader
    from mcap_ros2.decoder import DecoderFactory

    recording = Recording(path)
    factory = DecoderFactory()
    decoders: dict[int, Callable[[bytes], Any]] = {}
    try:
        with path.open("rb") as stream:
            reader = make_reader(stream)
            for schema, channel, message in reader.iter_messages(log_time_order=True):
                decode = decoders.get(channel.id)
                if decode is None:
                    found = factory.decoder_for(channel.message_encoding, schema)
                    if found is None:
                        raise ValueError(f"{channel.topic}: no decoder for {channel.message_encoding}")
                    decode = decoders[channel.id] = found
                t = message.log_time / 1e9
                if channel.topic == SCENE_TOPIC:
                    recording.scene_times.append(t)
                    recording.scenes.append_raw(message.data, decode)
                else:
                    recording.messages.append((t, channel.topic, to_json(decode(message.data))))
        if recording.scenes:
            _ = recording.scenes[0]  # a scene that cannot be decoded is found now, not at a seek
    except (OSError, McapError, ValueError, EOFError, struct.error) as exc:
        raise RecordingError(f"cannot read the recording {path.name}: {exc}") from None
    if not recording.scenes:
        raise RecordingError(f"the recording {path.name} holds no scene states ({SCENE_TOPIC})")
    return recording


class ReplayScene:
    """The viser scene of a live run, its bodies placed from a recording's scene states."""

    def __init__(
        self, recording: Recording, host: str, port: int, access: AccessPolicy, scene: str = "toast_kitchen"
    ) -> None:
        self.recording = recording
        self.world = ToastKitchen(scene)
        self.view = StaticSceneView(self.world, host, port, access)
        model = self.world.model
        #: viser frame of each recorded body name
        self._frames: dict[str, Any] = {
            mujoco.mj_id2name(model, mujoco.mjtObj.mjOBJ_BODY, body) or f"body{body}": frame
            for body, frame in self.view.frames.items()
        }
        self._bread = self.view.geoms.get(self.world.bread_geom)
        self._lock = threading.Lock()
        self.time: float | None = None
        self.scene: JsonMessage | None = None
        self.updates = 0

    @property
    def url(self) -> str:
        return str(self.view.url)

    def seek(self, t: float) -> JsonMessage | None:
        """Moves the scene to the recorded state at `t`; returns that state."""
        scene = self.recording.scene_at(t)
        with self._lock:
            self.time = t
            if scene is None or scene is self.scene:
                return scene
            self.scene = scene
            self._apply(scene)
            self.updates += 1
        return scene

    def _apply(self, scene: JsonMessage) -> None:
        server = self.view.server
        with server.atomic():
            for name, pose in zip(scene.get("body_names", []), scene.get("body_poses", []), strict=False):
                frame = self._frames.get(str(name))
                if frame is None:
                    continue
                p, q = pose["position"], pose["orientation"]
                frame.position = (float(p["x"]), float(p["y"]), float(p["z"]))
                frame.wxyz = (float(q["w"]), float(q["x"]), float(q["y"]), float(q["z"]))
            if self._bread is not None:
                self._bread.color = _rgb(toast_rgba(float(scene.get("toast_level", 0.0))))

    def stop(self) -> None:
        self.view.stop()


class StaticSceneView(SceneView):
    """viewer.SceneView without a simulation behind it: the scene is built from the MuJoCo model,
    only the camera presets are offered, and nothing follows a runner (the replay moves the frames)."""

    def __init__(self, world: ToastKitchen, host: str, port: int, access: AccessPolicy) -> None:
        # SceneView.__init__ needs a runner; this sets what its scene building uses instead.
        self.world = world
        self.access = access
        self._serve("maa-sim: replay", host, port)
        self.updates = 0
        self._build_scene()
        with self.server.gui.add_folder("Camera"):
            for name in CAMERA_PRESETS:
                self.server.gui.add_button(name).on_click(self._look_handler(name))

    def _update_poses(self) -> None:
        """The model's initial poses."""
        d = self.world.data
        for body, frame in self.frames.items():
            frame.position = tuple(float(v) for v in d.xpos[body])
            frame.wxyz = tuple(float(v) for v in d.xquat[body])


@dataclass
class ReplayServer:
    """A recording served for the simulate view: the scene (viser) and the services (rosbridge)."""

    recording: Recording
    host: str = "127.0.0.1"
    rosbridge_port: int = 0
    viser_port: int | None = 0
    token: str | None = None
    scene: ReplayScene | None = None
    rosbridge: Any = None

    def start(self) -> None:
        from .rosbridge import RosbridgeServer

        token = resolve_token(self.token)
        self.token = token
        if self.viser_port is not None:
            self.scene = ReplayScene(
                self.recording, self.host, self.viser_port, AccessPolicy(token, bind_host=self.host)
            )
            self.scene.seek(self.recording.start)
        self.rosbridge = RosbridgeServer(
            LocalBus(),
            host=self.host,
            port=self.rosbridge_port,
            services=self.services(),
            access=AccessPolicy(token, bind_host=self.host),
        )
        try:
            self.rosbridge.start()
        except BaseException:
            self.stop()
            raise

    def status(self, with_scene: bool = False) -> JsonMessage:
        """The recording's span, the time shown and the toast there (`with_scene`: the scene state shown)."""
        shown = self.scene.time if self.scene is not None else None
        t = shown if shown is not None else self.recording.start
        scene = self.recording.scene_at(t)
        status: JsonMessage = {
            "replay": self.recording.path.name,
            "start": self.recording.start,
            "end": self.recording.end,
            "time": t,
            "paused": True,
            "toast_level": scene.get("toast_level") if scene is not None else None,
            "toast_on_plate": scene.get("toast_on_plate") if scene is not None else None,
            "topics": self.recording.topics(),
            "messages": len(self.recording.messages) + len(self.recording.scenes),
        }
        if with_scene:
            status["scene"] = scene
        return status

    def seek(self, args: JsonMessage) -> JsonMessage:
        t = args.get("time")
        if isinstance(t, bool) or not isinstance(t, (int, float)) or t != t:  # noqa: PLR0124 - NaN
            return {"success": False, "message": "time must be a number (simulated seconds)", "status": self.status()}
        scene = self.scene.seek(float(t)) if self.scene is not None else self.recording.scene_at(float(t))
        return {"success": True, "message": "", "status": self.status(), "scene": scene}

    def messages(self, args: JsonMessage) -> JsonMessage:
        exclude = args.get("exclude", [])
        if not isinstance(exclude, list) or not all(isinstance(e, str) for e in exclude):
            return {"success": False, "message": "exclude must be a list of topic names", "messages": []}
        return {"success": True, "message": "", **self.status(), "messages": self.recording.select(exclude)}

    def services(self) -> dict[str, Any]:
        from .rosbridge import BlockingService

        return {
            "sim/seek": self.seek,
            "sim/get_status": lambda _args: self.status(with_scene=True),
            # the whole recording in one answer: serialized on a worker thread, not the server's loop
            "sim/replay_messages": BlockingService(self.messages),
        }

    def ready_line(self) -> JsonMessage:
        """The `--status-json` ready line (the IDE backend reads the endpoints from it, like a run's)."""
        return {
            "event": "ready",
            "mode": "replay",
            "replay": self.recording.path.name,
            "start": self.recording.start,
            "end": self.recording.end,
            "rosbridge": self.rosbridge.url if self.rosbridge is not None else None,
            "viser": self.scene.url if self.scene is not None else None,
            "token": self.token,
        }

    def stop(self) -> None:
        if self.rosbridge is not None:
            with contextlib.suppress(Exception):
                self.rosbridge.stop()
        if self.scene is not None:
            self.scene.stop()
