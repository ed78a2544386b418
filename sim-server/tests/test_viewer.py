"""The viser panel: serves its web client, builds the scene, follows the simulation."""

from __future__ import annotations

import time
import urllib.request
from collections.abc import Iterator
from pathlib import Path

import pytest
from toast_app.lockstep import create_controller

from maa_sim.app import RunOptions, SimApp
from maa_sim.runs import lockstep_session
from maa_sim.viewer import CAMERA_PRESETS, SceneView


@pytest.fixture
def view() -> Iterator[SceneView]:
    _, runner = lockstep_session(create_controller({}))
    scene = SceneView(runner, port=_free_port())
    scene.start()
    yield scene
    scene.stop()


def _free_port() -> int:
    import socket

    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return int(s.getsockname()[1])


def test_serves_the_client_page(view: SceneView) -> None:
    with urllib.request.urlopen(view.url_with_token, timeout=30) as response:
        body = response.read().decode("utf-8", errors="replace")
        headers = {k.lower(): v for k, v in response.headers.items()}
    assert response.status == 200
    assert "<html" in body.lower()
    # embeddable in an iframe: no header forbids framing
    assert "x-frame-options" not in headers
    assert "frame-ancestors" not in headers.get("content-security-policy", "")


def test_scene_nodes_exist(view: SceneView) -> None:
    m = view.world.model
    assert len(view.frames) == m.nbody - 1
    names = {handle.name for handle in view.geoms.values()}
    for expected in (
        "/world/bread/bread",
        "/world/finger_inner/finger_inner",
        "/world/toaster/toaster_wall_inner",
        "/world/table",
    ):
        assert expected in names
    assert set(CAMERA_PRESETS) == {"Overview", "Toaster", "Plate", "Bread"}


def test_bodies_and_toast_color_follow_the_simulation(view: SceneView) -> None:
    runner = view.runner
    bread = view.geoms[view.world.bread_geom]
    color_before = tuple(bread.color)
    for _ in range(100):
        runner.cycle()  # 2 s: the arm moves
    view.world.toast_level = 1.0
    view.world.model.geom_rgba[view.world.bread_geom] = (0.8, 0.5, 0.2, 1.0)
    updates = view.updates
    time.sleep(0.5)
    assert view.updates >= updates + 10  # about 30 per second
    assert tuple(bread.color) != color_before
    lift_body = view.frames[2]
    assert abs(float(lift_body.position[2]) - view.world.data.xpos[2][2]) < 1e-6
    assert "sim time" in view.hud.content


def test_run_controls_standalone_and_none_when_the_ide_drives_the_run() -> None:
    """Standalone (`maa-sim run`) the panel offers pause/resume/step/reset/speed; the IDE starts it
    with `--viser-controls off`: then only the HUD and the camera presets, one set of controls."""
    _, runner = lockstep_session(create_controller({}))
    standalone = SceneView(runner, port=_free_port())
    embedded = SceneView(runner, port=_free_port(), controls=False)
    try:
        assert [h.label for h in standalone.run_controls] == ["Pause", "Resume", "Step", "Reset", "Speed"]
        assert embedded.run_controls == []
        assert "sim time" in embedded.hud.content
        embedded.look("Plate")  # the camera presets still work
    finally:
        standalone.stop()
        embedded.stop()


def test_the_run_controls_call_the_actions_they_are_given() -> None:
    """`maa-sim run` hands the panel its control services: a button does what the IDE's does."""
    _, runner = lockstep_session(create_controller({}))
    calls: list[tuple[str, dict[str, object]]] = []
    services = ("sim/pause", "sim/resume", "sim/step", "sim/reset", "sim/set_speed")
    actions = {name: (lambda args, name=name: calls.append((name, dict(args)))) for name in services}
    view = SceneView(runner, port=_free_port(), actions=actions)
    try:
        for label in ("Pause", "Resume", "Step", "Reset"):
            view.press(label).join(timeout=30)
        assert calls == [("sim/pause", {}), ("sim/resume", {}), ("sim/step", {"steps": 1}), ("sim/reset", {})]
        assert runner.status()["time"] == 0.0  # the runner itself was left alone
    finally:
        view.stop()


def test_a_refused_run_control_is_reported_and_the_next_one_works(capsys: pytest.CaptureFixture[str]) -> None:
    _, runner = lockstep_session(create_controller({}))

    def refuse(_args: object) -> None:
        raise ValueError("not now")

    view = SceneView(runner, port=_free_port(), actions={"sim/reset": refuse, "sim/pause": lambda _a: runner.pause()})
    try:
        view.press("Reset").join(timeout=30)
        assert "maa-sim: viser sim/reset: not now" in capsys.readouterr().err
        view.press("Pause").join(timeout=30)
        assert runner.paused
    finally:
        view.stop()


def test_maa_sim_run_resets_through_its_own_reset(toast_app_dir: Path) -> None:
    """The standalone panel's Reset is the application's (ROS 2 mode: every node restarts), not the
    runner's alone: here a lock-step run, whose reset also forgets the automaton states."""
    app = SimApp(RunOptions(package=toast_app_dir, mode="lockstep", rosbridge_port=None, viser_port=0, paused=True))
    app.start()
    try:
        assert app.viewer is not None and app.runner is not None
        app.runner.step(50)
        assert app.runner.status()["time"] > 0.5
        app.automaton_states["controller"] = "Toasting"
        app.viewer.press("Reset").join(timeout=60)
        assert app.runner.status()["time"] == 0.0
        assert app._latched_states() == {}
    finally:
        app.stop()
