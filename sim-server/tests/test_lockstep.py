"""Lock-step mode: the fixture application delivers the toast, deterministically."""

from __future__ import annotations

from pathlib import Path
from typing import Any

import numpy as np
import pytest
from toast_app.lockstep import create_controller

from maa_sim.lockstep import LockstepController, LockstepPackage, normalize_outputs
from maa_sim.runs import lockstep_session, run_lockstep
from maa_sim.transport import LocalBus

#: The toast must be on the plate within this much simulated time.
TIME_BOUND = 30.0


def test_fixture_implements_the_protocol() -> None:
    assert isinstance(create_controller({}), LockstepController)


def test_toast_ends_on_the_plate() -> None:
    result = run_lockstep(create_controller({}), max_sim_time=TIME_BOUND)
    assert result.goal_reached, f"no toast on the plate after {result.sim_time:.1f} s"
    assert result.sim_time < TIME_BOUND


def test_two_runs_are_identical_bit_for_bit() -> None:
    a = run_lockstep(create_controller({}), seed=7, max_sim_time=12.0, stop_on_goal=False, record=True)
    b = run_lockstep(create_controller({}), seed=7, max_sim_time=12.0, stop_on_goal=False, record=True)
    assert a.trajectory.shape == b.trajectory.shape and a.trajectory.shape[0] == 600
    assert a.trajectory.tobytes() == b.trajectory.tobytes()
    assert np.ptp(a.trajectory[:, 0]) > 1.0  # the arm did move


def test_the_seed_changes_the_scene() -> None:
    from maa_sim.world import ToastKitchen, WorldConfig

    a = ToastKitchen(config=WorldConfig(seed=1, bread_jitter=0.001))
    b = ToastKitchen(config=WorldConfig(seed=2, bread_jitter=0.001))
    assert not np.array_equal(a.bread_position(), b.bread_position())


def test_ports_are_observable_on_the_bus() -> None:
    bus = LocalBus()
    seen: list[tuple[str, dict[str, object]]] = []
    session, runner = lockstep_session(create_controller({}), bus=bus)
    bus.subscribe("/toast/ctrl/arm", None, lambda t, m: seen.append((t, m)))
    bus.subscribe("/sensors/distance", None, lambda t, m: seen.append((t, m)))
    for _ in range(5):
        runner.cycle()
    assert ("/toast/ctrl/arm", {"data": "FETCH"}) in seen
    assert any(t == "/sensors/distance" for t, _ in seen)
    assert dict(bus.topics())["/toast/ctrl/arm"] == "std_msgs/msg/String"
    assert session.periods == 5


def test_package_loads_from_lockstep_json(toast_app_dir: Path) -> None:
    package = LockstepPackage.load(toast_app_dir)
    assert package.period == 0.02
    controller = package.create()
    assert controller.step({}) is not None


def test_invalid_lockstep_json(tmp_path: Path) -> None:
    (tmp_path / "lockstep.json").write_text('{"format": "maa-lockstep/1", "factory": "nocolon"}')
    with pytest.raises(ValueError, match="factory"):
        LockstepPackage.load(tmp_path)
    with pytest.raises(ValueError, match="does not exist"):
        LockstepPackage.load(tmp_path / "missing")


def test_outputs_are_normalized() -> None:
    outputs: dict[str, Any] = {"/a": {"data": 1}, "/b": [{"data": 1}, {"data": 2}], "/c": None}
    assert normalize_outputs(outputs) == {
        "/a": [{"data": 1}],
        "/b": [{"data": 1}, {"data": 2}],
    }
    with pytest.raises(TypeError):
        normalize_outputs({"/a": 3})  # type: ignore[dict-item]
