"""The wire contracts maa-sim reads (@maa/protocol, emitted into maa_sim/protocol.py) against what
the generators really write: every golden lockstep.json, a timesync build generated now (its
lockstep.json and what its controller's `step` returns), and the contract's error messages."""

from __future__ import annotations

import copy
import json
from pathlib import Path
from typing import Any

import pytest
from test_generated_lockstep import TOAST_APP, generate, lockstep_app

from maa_sim import interface
from maa_sim.contracts import problem, validator
from maa_sim.lockstep import LockstepPackage, check_lockstep, normalize_outputs
from maa_sim.protocol import (
    DEPLOYMENT_SCHEMA,
    LOCKSTEP_SCHEMA,
    SIMULATOR_STATUS_SCHEMA,
    SIMULATOR_TOPICS,
    STEP_OUTPUTS_SCHEMA,
)

GENERATOR_TESTS = Path(__file__).resolve().parents[2] / "packages" / "generators-python" / "test"
GOLDEN_LOCKSTEP = sorted(GENERATOR_TESTS.glob("golden*/**/lockstep.json"))


def test_emitted_schemas_are_json_schemas() -> None:
    for schema in (DEPLOYMENT_SCHEMA, LOCKSTEP_SCHEMA, STEP_OUTPUTS_SCHEMA, SIMULATOR_STATUS_SCHEMA):
        validator(schema)  # raises SchemaError for an invalid schema


def test_golden_lockstep_files_exist() -> None:
    assert GOLDEN_LOCKSTEP, "no generated lockstep.json under packages/generators-python/test"


@pytest.mark.parametrize("path", GOLDEN_LOCKSTEP, ids=lambda p: str(p.parent.name))
def test_generated_lockstep_files_keep_the_contract(path: Path) -> None:
    data = json.loads(path.read_text(encoding="utf-8"))
    assert check_lockstep(data, str(path)) == data
    assert LockstepPackage.load(path.parent).factory == data["factory"]


BASE: dict[str, Any] = {"format": "maa-lockstep/1", "factory": "maa_app:create_controller", "period": 0.02}


@pytest.mark.parametrize(
    ("change", "message"),
    [
        (lambda d: d.update(format="maa-lockstep/2"), r"lockstep\.json: /format: format must be 'maa-lockstep/1'"),
        (lambda d: d.pop("factory"), r": /factory: factory must be 'module:callable'"),
        (lambda d: d.update(factory="no_colon"), r": /factory: factory must be 'module:callable'"),
        (lambda d: d.update(period=0), r": /period: period must be a positive number"),
        (lambda d: d.update(period=float("inf")), r": /period: period must be a positive number"),
        (lambda d: d.update(python_path=["a", 1]), r": /python_path/1: python_path must be a list of strings"),
        (lambda d: d.update(parameters=[1]), r": /parameters: parameters must be an object"),
    ],
)
def test_lockstep_errors_name_file_and_pointer(tmp_path: Path, change: Any, message: str) -> None:
    data = copy.deepcopy(BASE)
    change(data)
    (tmp_path / "lockstep.json").write_text(json.dumps(data))
    with pytest.raises(ValueError, match=message):
        LockstepPackage.load(tmp_path)


def test_a_generated_controller_keeps_the_step_contract(tmp_path: Path) -> None:
    """What a freshly generated python-timesync controller returns from `step` is what the schema says."""
    build = generate(TOAST_APP, tmp_path / "out")
    package = LockstepPackage.load(build)
    assert check_lockstep(json.loads((build / "lockstep.json").read_text(encoding="utf-8")), "lockstep.json")
    controller = package.create()
    checker = validator(STEP_OUTPUTS_SCHEMA)
    seen: set[str] = set()
    for step in range(20):
        clock = {"clock": {"sec": step // 50, "nanosec": (step % 50) * 20_000_000}}
        outputs = controller.step({"/clock": clock, "/sensors/distance": {"data": 100}})
        assert problem(checker, dict(outputs)) is None, outputs
        seen.update(normalize_outputs(outputs))
    assert "/toast_service_robot/ctrl/arm" in seen

    # The simulator running this build answers /sim/get_status as the IDE's contract says.
    app = lockstep_app(build, max_sim_time=1.0, speed=0.0)
    app.start()
    try:
        status_checker = validator(SIMULATOR_STATUS_SCHEMA)
        assert problem(status_checker, app.status()) is None, app.status()
        assert app.runner is not None
        app.runner.resume()
        assert app.wait(timeout=120)
        final = app.status()
        assert problem(status_checker, final) is None, final
        assert final["finished"] is not None
    finally:
        app.stop()


def test_the_platform_topics_are_the_protocols() -> None:
    assert [(t.name, t.type, t.publisher, t.description) for t in interface.ALL_TOPICS.values()] == sorted(
        ((t["name"], t["type"], t["publisher"], t["description"]) for t in SIMULATOR_TOPICS),
        key=lambda t: list(interface.ALL_TOPICS).index(t[0]),
    )


def test_the_step_contract_wants_absolute_topics_and_message_objects() -> None:
    checker = validator(STEP_OUTPUTS_SCHEMA)
    assert problem(checker, {"/t": {"data": 1}, "/u": [{"data": 1}, {"data": 2}], "/v": None}) is None
    assert problem(checker, {"/t": 3}) is not None
    assert problem(checker, {"t": {"data": 1}}) is not None
