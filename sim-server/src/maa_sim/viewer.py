"""The viser panel: the MuJoCo scene in the browser, updated at 30 fps.

Every body becomes a frame node `/world/<body>`, every visible geom a primitive under it
(boxes, cylinders, spheres, capsules, planes; meshes as triangle meshes), so an update only
moves the frames. The bread's colour follows its toast level. A HUD shows the simulation time,
the real-time factor and the toast; camera presets look at the whole kitchen, the toaster, the
plate or the bread. Run controls (pause, resume, step, reset, speed) are offered for standalone
use (`maa-sim run`); the IDE, which has its own, turns them off (`--viser-controls off`), so a
run has one set of controls. viser serves its own
web client (shipped in the wheel), which can be embedded in an iframe.

viser itself listens on an internal loopback port; the public port is a `Gate` (gate.py) that
applies maa-sim's Host, Origin and token rules (access.py) before passing a connection on.
"""

from __future__ import annotations

import contextlib
import hmac
import sys
import threading
import time
from collections.abc import Callable, Mapping
from typing import Any

import mujoco
import numpy as np
import viser

from .access import AccessPolicy, resolve_token
from .gate import GATE_HEADER, Gate
from .rosbridge import ServiceError
from .session import Runner
from .world import PLATE_CENTER

FPS = 30.0

#: What a run-control button does, by the name of the service that does the same for the IDE
#: (sim/pause, sim/resume, sim/step, sim/reset, sim/set_speed): the service's arguments in, its
#: reply out.
RunAction = Callable[[dict[str, Any]], object]


def runner_actions(runner: Runner) -> dict[str, RunAction]:
    """The run controls acting on the runner alone (a viewer without an application around it)."""
    return {
        "sim/pause": lambda _args: runner.pause(),
        "sim/resume": lambda _args: runner.resume(),
        "sim/step": lambda args: runner.step(int(args.get("steps", 1))),
        "sim/reset": lambda _args: runner.reset(),
        "sim/set_speed": lambda args: runner.set_speed(float(args["speed"])),
    }


#: Camera presets: name -> (position, look-at).
CAMERA_PRESETS: dict[str, tuple[tuple[float, float, float], tuple[float, float, float]]] = {
    "Overview": ((0.75, -0.75, 0.65), (0.0, 0.0, 0.1)),
    "Toaster": ((-0.45, 0.65, 0.45), (-0.15, 0.26, 0.12)),
    "Plate": ((-0.5, -0.7, 0.35), (PLATE_CENTER[0], PLATE_CENTER[1], 0.03)),
    "Bread": ((0.75, 0.25, 0.3), (0.3, 0.0, 0.05)),
}


def _rgb(rgba: Any) -> tuple[int, int, int]:
    return (round(float(rgba[0]) * 255), round(float(rgba[1]) * 255), round(float(rgba[2]) * 255))


class SceneView:
    """A viser server showing one session's world."""

    def __init__(
        self,
        runner: Runner,
        host: str = "127.0.0.1",
        port: int = 8080,
        fps: float = FPS,
        access: AccessPolicy | None = None,
        controls: bool = True,
        actions: Mapping[str, RunAction] | None = None,
    ) -> None:
        self.runner = runner
        #: whether the panel offers the run controls (False: the HUD and the camera presets only)
        self.controls = controls
        #: what the run controls do: `maa-sim run` passes its control services, so that a Reset
        #: here restarts ROS 2 mode's nodes and a Resume goes on past a breakpoint, as from the IDE
        self.actions: Mapping[str, RunAction] = actions if actions is not None else runner_actions(runner)
        #: the run controls' GUI handles (empty without them)
        self.run_controls: list[Any] = []
        self.session = runner.session
        self.world = runner.session.world
        self.fps = fps
        self.access = access if access is not None else AccessPolicy(resolve_token(), bind_host=host)
        self._serve("maa-sim: toast kitchen", host, port)
        self.updates = 0
        self._build_scene()
        self._build_gui()

    @property
    def url(self) -> str:
        """The panel's address (without the token: see `url_with_token`)."""
        host = f"[{self.host}]" if ":" in self.host else self.host
        return f"http://{host}:{self.port}"

    @property
    def url_with_token(self) -> str:
        """The address a person opens: the token in the query becomes a cookie for the page."""
        return f"{self.url}/?token={self.access.token}"

    def _serve(self, label: str, host: str, port: int) -> None:
        """Starts viser on an internal port behind the access gate on `host:port`, with no frames yet."""
        # viser prints a banner on stdout; stdout belongs to maa-sim's own output (--status-json).
        # Port 0: viser moves on to the next port when one is taken, which must not happen to
        # an internal port that some other server might be on.
        with contextlib.redirect_stdout(sys.stderr):
            self.server = viser.ViserServer(host="127.0.0.1", port=0, label=label, verbose=False)
        self.gate = Gate(self.access, self.server.get_port(), host=host, port=port)
        self._refuse_ungated_websockets()
        try:
            self.gate.start()
        except RuntimeError:
            with contextlib.suppress(Exception), contextlib.redirect_stdout(sys.stderr):
                self.server.stop()
            raise
        self.port = self.gate.port
        self.host = host
        self.frames: dict[int, Any] = {}
        self.geoms: dict[int, Any] = {}
        self._geom_rgb: dict[int, tuple[int, int, int]] = {}
        self._stop = threading.Event()
        self._thread: threading.Thread | None = None

    def _refuse_ungated_websockets(self) -> None:
        """Defence in depth for the internal port, which any local process or web page could find:
        a WebSocket that did not come through the gate is closed before viser reads a message from
        it. Uses viser's private connection table (no public API shows a client's request); if a
        viser version lacks it, the check is skipped and the internal port is only loopback."""
        websock = getattr(self.server, "_websock_server", None)
        connections = getattr(websock, "_live_connections", None)
        if websock is None or not isinstance(connections, dict):
            return
        secret = self.gate.secret.encode()

        async def check(client: Any) -> None:
            connection = connections.get(client.client_id)
            request = getattr(connection, "request", None)
            if connection is None or request is None:
                return
            given = request.headers.get_all(GATE_HEADER)
            if not any(hmac.compare_digest(value.encode("utf-8", "surrogateescape"), secret) for value in given):
                await connection.close(1008, "maa-sim: connect through the panel's public port")

        websock.on_client_connect(check)

    # ----------------------------------------------------------------------------- scene

    def _build_scene(self) -> None:
        m = self.world.model
        scene = self.server.scene
        scene.set_up_direction("+z")
        cam_pos, cam_look = CAMERA_PRESETS["Overview"]
        self.server.initial_camera.position = cam_pos
        self.server.initial_camera.look_at = cam_look
        for body in range(m.nbody):
            name = mujoco.mj_id2name(m, mujoco.mjtObj.mjOBJ_BODY, body) or f"body{body}"
            path = "/world" if body == 0 else f"/world/{name}"
            if body != 0:
                self.frames[body] = scene.add_frame(path, show_axes=False)
        for geom in range(m.ngeom):
            if int(m.geom_group[geom]) >= 3 or float(m.geom_rgba[geom][3]) == 0.0:
                continue
            body = int(m.geom_bodyid[geom])
            body_name = mujoco.mj_id2name(m, mujoco.mjtObj.mjOBJ_BODY, body) or f"body{body}"
            parent = "/world" if body == 0 else f"/world/{body_name}"
            name = mujoco.mj_id2name(m, mujoco.mjtObj.mjOBJ_GEOM, geom) or f"geom{geom}"
            handle = self._add_geom(f"{parent}/{name}", geom)
            if handle is not None:
                self.geoms[geom] = handle
                self._geom_rgb[geom] = _rgb(m.geom_rgba[geom])
        self._update_poses()

    def _add_geom(self, path: str, geom: int) -> Any:
        m = self.world.model
        scene = self.server.scene
        kind = int(m.geom_type[geom])
        size = m.geom_size[geom]
        rgba = m.geom_rgba[geom]
        pose: dict[str, Any] = {"position": tuple(m.geom_pos[geom]), "wxyz": tuple(m.geom_quat[geom])}
        color = _rgb(rgba)
        opacity = float(rgba[3]) if rgba[3] < 1 else None
        g = mujoco.mjtGeom
        if kind == g.mjGEOM_PLANE:
            sx = float(size[0]) * 2 if size[0] > 0 else 4.0
            sy = float(size[1]) * 2 if size[1] > 0 else 4.0
            pose["position"] = (pose["position"][0], pose["position"][1], pose["position"][2] - 0.001)
            return scene.add_box(path, color=color, dimensions=(sx, sy, 0.002), opacity=opacity, **pose)
        if kind == g.mjGEOM_BOX:
            dims = (2 * float(size[0]), 2 * float(size[1]), 2 * float(size[2]))
            return scene.add_box(path, color=color, dimensions=dims, opacity=opacity, **pose)
        if kind == g.mjGEOM_CYLINDER:
            return scene.add_cylinder(
                path, radius=float(size[0]), height=2 * float(size[1]), color=color, opacity=opacity, **pose
            )
        if kind == g.mjGEOM_SPHERE:
            return scene.add_icosphere(path, radius=float(size[0]), color=color, opacity=opacity, **pose)
        if kind == g.mjGEOM_CAPSULE:
            handle = scene.add_frame(path, show_axes=False, **pose)
            r, h = float(size[0]), float(size[1])
            scene.add_cylinder(f"{path}/body", radius=r, height=2 * h, color=color, opacity=opacity)
            scene.add_icosphere(f"{path}/top", radius=r, color=color, position=(0, 0, h), opacity=opacity)
            scene.add_icosphere(f"{path}/bottom", radius=r, color=color, position=(0, 0, -h), opacity=opacity)
            return handle
        if kind == g.mjGEOM_ELLIPSOID:
            return scene.add_icosphere(
                path, radius=1.0, color=color, scale=(float(size[0]), float(size[1]), float(size[2])), **pose
            )
        if kind == g.mjGEOM_MESH:
            mesh = int(m.geom_dataid[geom])
            v0, nv = int(m.mesh_vertadr[mesh]), int(m.mesh_vertnum[mesh])
            f0, nf = int(m.mesh_faceadr[mesh]), int(m.mesh_facenum[mesh])
            vertices = np.array(m.mesh_vert[v0 : v0 + nv], dtype=np.float32)
            faces = np.array(m.mesh_face[f0 : f0 + nf], dtype=np.uint32)
            return scene.add_mesh_simple(path, vertices, faces, color=color, opacity=opacity, **pose)
        return None

    def _update_poses(self) -> None:
        d = self.world.data
        with self.session.lock:
            xpos = np.array(d.xpos)
            xquat = np.array(d.xquat)
            rgba = {g: _rgb(self.world.model.geom_rgba[g]) for g in self.geoms}
        with self.server.atomic():
            for body, frame in self.frames.items():
                frame.position = tuple(float(v) for v in xpos[body])
                frame.wxyz = tuple(float(v) for v in xquat[body])
            for geom, rgb in rgba.items():
                if self._geom_rgb.get(geom) != rgb:
                    self._geom_rgb[geom] = rgb
                    self.geoms[geom].color = rgb
        self.updates += 1

    # ----------------------------------------------------------------------------- GUI

    def _build_gui(self) -> None:
        gui = self.server.gui
        self.hud = gui.add_markdown(self._hud_text())
        if self.controls:
            self._build_run_controls()
        else:
            # embedded in the IDE, whose status line shows the time and the toast: a small panel,
            # folded at first (its button opens the HUD and the camera presets), so the 3D view
            # keeps the room
            gui.configure_theme(control_width="small", show_share_button=False)
            gui.main_panel.minimize()
        self._build_camera_folder()

    def _build_run_controls(self) -> None:
        gui = self.server.gui
        with gui.add_folder("Simulation"):
            pause = gui.add_button("Pause")
            resume = gui.add_button("Resume")
            step = gui.add_button("Step")
            reset = gui.add_button("Reset")
            speed = gui.add_slider(
                "Speed", min=0.1, max=10.0, step=0.1, initial_value=max(0.1, self.runner.speed or 1.0)
            )
        self.run_controls = [pause, resume, step, reset, speed]
        for button in (pause, resume, step, reset):
            button.on_click(self._press_handler(button.label))

        def set_speed(_event: Any) -> None:
            self._act("sim/set_speed", {"speed": float(speed.value)})

        speed.on_update(set_speed)

    def _press_handler(self, label: str) -> Callable[[Any], None]:
        def handler(_event: Any) -> None:
            self.press(label)

        return handler

    #: the run-control buttons' services and arguments
    _BUTTONS: dict[str, tuple[str, dict[str, Any]]] = {
        "Pause": ("sim/pause", {}),
        "Resume": ("sim/resume", {}),
        "Step": ("sim/step", {"steps": 1}),
        "Reset": ("sim/reset", {}),
    }

    def press(self, label: str) -> threading.Thread:
        """What a click on a run-control button does; the returned thread ends when it is done."""
        service, args = self._BUTTONS[label]
        return self._act(service, args)

    def _act(self, service: str, args: dict[str, Any]) -> threading.Thread:
        # on a thread of its own: ROS 2 mode's reset restarts every node (seconds), and viser's
        # callbacks should not wait for it
        def run() -> None:
            try:
                self.actions[service](args)
            except (ValueError, ServiceError) as exc:  # reported; the panel keeps serving
                print(f"maa-sim: viser {service}: {exc}", file=sys.stderr, flush=True)

        thread = threading.Thread(target=run, name=f"viser {service}", daemon=True)
        thread.start()
        return thread

    def _build_camera_folder(self) -> None:
        gui = self.server.gui
        with gui.add_folder("Camera"):
            for name in CAMERA_PRESETS:
                button = gui.add_button(name)
                button.on_click(self._look_handler(name))

    def _look_handler(self, preset: str) -> Callable[[Any], None]:
        def handler(_event: Any) -> None:
            self.look(preset)

        return handler

    def look(self, preset: str) -> None:
        position, look_at = CAMERA_PRESETS[preset]
        for client in self.server.get_clients().values():
            with client.atomic():
                client.camera.position = position
                client.camera.look_at = look_at

    def _hud_text(self) -> str:
        status = self.runner.status()
        world = self.world
        state = "paused" if status["paused"] else "running"
        return (
            f"**sim time** {status['time']:.2f} s &nbsp; **real-time factor** {status['real_time_factor']:.2f}x"
            f" &nbsp; ({state})  \n**toast** {world.color()} (level {world.toast_level:.2f})"
            f"{' &nbsp; **on the plate**' if status['toast_on_plate'] else ''}"
        )

    # ----------------------------------------------------------------------------- loop

    def start(self) -> None:
        self._thread = threading.Thread(target=self._loop, name="maa-sim-viser", daemon=True)
        self._thread.start()

    def _loop(self) -> None:
        period = 1.0 / self.fps
        next_time = time.perf_counter()
        hud_every = max(1, round(self.fps / 5))
        while not self._stop.is_set():
            with contextlib.suppress(Exception):  # a disconnecting client must not stop the panel
                self._update_poses()
                if self.updates % hud_every == 0:
                    self.hud.content = self._hud_text()
            next_time += period
            delay = next_time - time.perf_counter()
            if delay < -1.0:
                next_time = time.perf_counter()
            self._stop.wait(max(0.0, delay))

    def stop(self) -> None:
        self._stop.set()
        if self._thread is not None:
            self._thread.join(timeout=2)
        self.gate.stop()
        with contextlib.suppress(Exception), contextlib.redirect_stdout(sys.stderr):
            self.server.stop()
