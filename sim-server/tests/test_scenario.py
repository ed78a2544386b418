"""Scenario runs: `maa-sim run --world FILE --report FILE` (maa_sim.scenario, docs/lab.md "Grading").

The world file sets the initial world; the report says whether the goal was reached, what happened in
the world and which states the automata went through. The example's timesync build and two broken
variants of it (a Controller that never serves, an arm program that opens the gripper over the
table) are generated at test time like test_generated_lockstep's builds.
"""

from __future__ import annotations

import json
import shutil
import signal
import subprocess
import sys
import textwrap
from collections.abc import Callable
from pathlib import Path
from typing import Any

import pytest
from test_generated_lockstep import TOAST_APP, generate

from maa_sim.cli import main
from maa_sim.contracts import problem, validator
from maa_sim.protocol import SCENARIO_REPORT_SCHEMA
from maa_sim.scenario import WorldFileError, check_world, load_world, world_config, write_report

SIM_SERVER = Path(__file__).resolve().parent.parent
EXAMPLE = TOAST_APP.parent
CTRL = "/toast_service_robot/ctrl"
REPORT = validator(SCENARIO_REPORT_SCHEMA)
HEADLESS = ["--mode", "lockstep", "--rosbridge-port", "off", "--viser-port", "off"]


def run_cli(args: list[str], timeout: float = 240) -> subprocess.CompletedProcess[str]:
    """`python -m maa_sim run ...`, as a grading task runs it (grading-design.md)."""
    return subprocess.run(
        [sys.executable, "-m", "maa_sim", "run", *HEADLESS, *args],
        capture_output=True,
        text=True,
        check=False,
        timeout=timeout,
        cwd=SIM_SERVER,
    )


def read_report(path: Path) -> dict[str, Any]:
    report: dict[str, Any] = json.loads(path.read_text(encoding="utf-8"))
    assert problem(REPORT, report) is None, report  # @maa/protocol's contract
    assert report["format"] == "maa-scenario-report/1"
    return report


def kinds(report: dict[str, Any]) -> list[str]:
    return [e["kind"] for e in report["events"]]


def path_of(report: dict[str, Any], node: str) -> list[str]:
    return [s["state"] for s in report["states"] if s["node"] == node]


def variant(tmp: Path, name: str, edits: dict[str, Callable[[str], str]]) -> Path:
    """A copy of the example with some model files changed; its timesync build."""
    copy = tmp / name
    shutil.copytree(EXAMPLE, copy)
    for file, edit in edits.items():
        path = copy / file
        before = path.read_text(encoding="utf-8")
        after = edit(before)
        assert after != before, f"the edit of {file} changed nothing"
        path.write_text(after, encoding="utf-8")
    return Path(generate(copy / TOAST_APP.name, tmp / f"{name}-build"))


# ------------------------------------------------------------------------------------------ world files


def test_world_file_fields(tmp_path: Path) -> None:
    path = tmp_path / "world.json"
    path.write_text('{"goldenSeconds": 3, "breadJitter": 0.001, "seed": 7}', encoding="utf-8")
    world = load_world(path)
    assert world == {"goldenSeconds": 3.0, "breadJitter": 0.001, "seed": 7}
    config = world_config(world)
    assert (config.golden_seconds, config.bread_jitter, config.seed) == (3.0, 0.001, 7)
    # the command line wins over the file; missing fields keep the defaults
    config = world_config({"seed": 7}, seed=2, golden_seconds=4.0)
    assert (config.golden_seconds, config.bread_jitter, config.seed) == (4.0, 0.0, 2)
    assert check_world({}, "w.json") == {}


@pytest.mark.parametrize(
    ("data", "field"),
    [
        ([], "a JSON object"),
        ({"goldenSecond": 6}, "/goldenSecond: unknown field"),
        ({"goldenSeconds": 0}, "/goldenSeconds"),
        ({"goldenSeconds": "6"}, "/goldenSeconds: must be a number"),
        ({"goldenSeconds": True}, "/goldenSeconds: must be a number"),
        ({"breadJitter": -0.001}, "/breadJitter"),
        ({"breadJitter": 0.5}, "/breadJitter"),
        ({"seed": 1.5}, "/seed"),
        ({"seed": -1}, "/seed"),
    ],
)
def test_bad_world_fields(data: object, field: str) -> None:
    with pytest.raises(WorldFileError) as info:
        check_world(data, "scenario/world.json")
    assert str(info.value).startswith("scenario/world.json: ")
    assert field in str(info.value)


def test_unreadable_world_files(tmp_path: Path) -> None:
    with pytest.raises(WorldFileError, match="cannot read"):
        load_world(tmp_path / "missing.json")
    bad = tmp_path / "bad.json"
    bad.write_text("{goldenSeconds: 6}", encoding="utf-8")
    with pytest.raises(WorldFileError, match=r"bad\.json: invalid JSON"):
        load_world(bad)


def test_a_bad_world_file_is_an_error_with_a_report(
    toast_app_dir: Path, tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    world = tmp_path / "world.json"
    world.write_text('{"goldenSeconds": -1}', encoding="utf-8")
    report = tmp_path / "out" / "report.json"
    args = ["run", *HEADLESS, "--package", str(toast_app_dir), "--world", str(world), "--report", str(report)]
    assert main(args) == 2
    err = capsys.readouterr().err
    assert str(world) in err and "/goldenSeconds" in err
    found = read_report(report)
    assert found["goalReached"] is False and found["toast"] is None
    assert "/goldenSeconds" in found["error"] and found["endReason"] == "error: bad world file"
    assert kinds(found) == ["error"]


def test_a_package_that_does_not_load_is_an_error_with_a_report(tmp_path: Path) -> None:
    report = tmp_path / "report.json"
    assert main(["run", *HEADLESS, "--package", str(tmp_path), "--report", str(report)]) == 2
    found = read_report(report)
    assert "lockstep.json" in found["error"] and found["world"] == {"goldenSeconds": 6.0, "breadJitter": 0.0, "seed": 0}


def test_the_report_is_written_atomically(tmp_path: Path) -> None:
    target = tmp_path / "report.json"
    target.write_text("old", encoding="utf-8")

    class Unserializable:
        pass

    with pytest.raises(TypeError):
        write_report(target, {"format": "maa-scenario-report/1", "error": Unserializable()})  # type: ignore[typeddict-item]
    assert target.read_text(encoding="utf-8") == "old"  # the old report stays whole
    assert [p.name for p in tmp_path.iterdir()] == ["report.json"]  # no temporary file left
    write_report(target, {"format": "maa-scenario-report/1"})  # type: ignore[typeddict-item]
    assert json.loads(target.read_text(encoding="utf-8")) == {"format": "maa-scenario-report/1"}
    assert target.stat().st_mode & 0o777 == 0o644  # readable by the grader, whoever ran the task


# ------------------------------------------------------------------------------------------ fixture runs


def test_the_world_file_sets_the_toasting_speed(toast_app_dir: Path, tmp_path: Path) -> None:
    """The handwritten fixture application: golden toast after 0.8 * goldenSeconds of toasting."""
    times: dict[float, float] = {}
    for golden in (3.0, 6.0):
        world = tmp_path / f"world-{golden}.json"
        world.write_text(json.dumps({"goldenSeconds": golden, "seed": 1}), encoding="utf-8")
        report = tmp_path / f"report-{golden}.json"
        args = ["--package", str(toast_app_dir), "--world", str(world), "--report", str(report)]
        result = run_cli([*args, "--until-goal", "--max-time", "60"])
        assert result.returncode == 0, result.stdout + result.stderr
        found = read_report(report)
        assert found["world"] == {"goldenSeconds": golden, "breadJitter": 0.0, "seed": 1}
        assert found["goalReached"] is True and found["goalTime"] == found["simTime"]
        assert found["endReason"] == "goal reached" and found["error"] is None
        assert found["states"] == [] and found["finalStates"] == {}  # the fixture has no automaton states
        at = {e["kind"]: e["time"] for e in found["events"]}
        assert kinds(found) == ["bread-loaded", "toaster-on", "toast-golden", "toaster-off", "toast-on-plate"]
        times[golden] = at["toast-golden"] - at["toaster-on"]
        assert found["toast"] == {
            "level": pytest.approx(found["toast"]["level"]),
            "color": "GOLDEN",
            "onPlate": True,
            "dropped": False,
        }
    assert times[3.0] == pytest.approx(0.8 * 3.0, abs=0.1)
    assert times[6.0] == pytest.approx(0.8 * 6.0, abs=0.1)


def test_a_failing_controller_gives_an_error_report(tmp_path: Path) -> None:
    package = tmp_path / "pkg"
    (package / "crashing").mkdir(parents=True)
    (package / "crashing" / "__init__.py").write_text(
        textwrap.dedent(
            """
            class Crashing:
                def __init__(self):
                    self.slices = 0

                def step(self, inputs):
                    self.slices += 1
                    if self.slices == 50:
                        raise RuntimeError("the controller broke")
                    return {}


            def create_controller(parameters):
                return Crashing()
            """
        ),
        encoding="utf-8",
    )
    lockstep = {"format": "maa-lockstep/1", "factory": "crashing:create_controller", "python_path": ["."]}
    (package / "lockstep.json").write_text(json.dumps(lockstep), encoding="utf-8")
    report = tmp_path / "report.json"
    result = run_cli(["--package", str(package), "--report", str(report), "--max-time", "10"])
    assert result.returncode == 1, result.stdout + result.stderr
    found = read_report(report)
    assert found["goalReached"] is False and "the controller broke" in found["error"]
    assert found["endReason"].startswith("error")
    assert kinds(found) == ["error"] and found["simTime"] == pytest.approx(0.98)


def test_an_interrupted_run_writes_its_report(toast_app_dir: Path, tmp_path: Path) -> None:
    report = tmp_path / "report.json"
    args = ["--package", str(toast_app_dir), "--report", str(report), "--speed", "1", "--status-json"]
    with subprocess.Popen(
        [sys.executable, "-m", "maa_sim.cli", "run", *HEADLESS, *args],
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        text=True,
        cwd=SIM_SERVER,
    ) as proc:
        assert proc.stdout is not None
        ready = json.loads(proc.stdout.readline())
        assert ready["event"] == "ready"
        proc.send_signal(signal.SIGINT)
        assert proc.wait(timeout=60) == 0
    found = read_report(report)
    assert found["endReason"] == "signal SIGINT" and found["error"] is None and found["goalReached"] is False


# ------------------------------------------------------------------------------------------ generated builds


def test_the_generated_example_reaches_the_goal(tmp_path_factory: pytest.TempPathFactory) -> None:
    build = generate(TOAST_APP, tmp_path_factory.mktemp("scenario-good"))
    out = tmp_path_factory.mktemp("scenario-good-out")
    world = out / "world.json"
    world.write_text('{"goldenSeconds": 6, "breadJitter": 0, "seed": 0}', encoding="utf-8")
    args = ["--package", str(build), "--world", str(world), "--report", str(out / "report.json")]
    result = run_cli([*args, "--until-goal", "--max-time", "60", "--record", str(out / "recording.mcap")])
    assert result.returncode == 0, result.stdout + result.stderr
    found = read_report(out / "report.json")
    assert found["goalReached"] is True and 5 < found["goalTime"] < 30
    assert path_of(found, CTRL) == ["Idle", "Loading", "Toasting", "Serving"]
    assert path_of(found, "/toast_service_robot/toaster_ctrl") == ["Off", "On", "Off"]
    assert found["states"][0] == {"time": 0.0, "node": CTRL, "state": "Idle"}
    assert found["finalStates"] == {CTRL: "Serving", "/toast_service_robot/toaster_ctrl": "Off"}
    assert kinds(found) == ["bread-loaded", "toaster-on", "toast-golden", "toaster-off", "toast-on-plate"]
    assert (out / "recording.mcap").stat().st_size > 0


def test_a_controller_that_never_serves(tmp_path: Path) -> None:
    build = variant(
        tmp_path,
        "never-serves",
        {
            "toast/Controller.arc": lambda text: "\n".join(
                line for line in text.splitlines() if "Toasting -> Serving" not in line
            )
        },
    )
    report = tmp_path / "report.json"
    result = run_cli(["--package", str(build), "--report", str(report), "--until-goal", "--max-time", "30"])
    assert result.returncode == 1, result.stdout + result.stderr
    found = read_report(report)
    assert found["goalReached"] is False and found["goalTime"] is None
    assert found["endReason"] == "time limit reached" and found["simTime"] == pytest.approx(30.0)
    # the toaster's safety timeout ends the toasting, long after the toast burnt
    assert kinds(found) == ["bread-loaded", "toaster-on", "toast-golden", "toast-burnt", "toaster-off"]
    assert path_of(found, CTRL) == ["Idle", "Loading", "Toasting"]
    assert found["toast"]["color"] == "BURNT" and found["toast"]["onPlate"] is False


def test_an_arm_that_opens_the_gripper_early(tmp_path: Path) -> None:
    def drop_over_the_table(text: str) -> str:
        text = text.replace(
            "location toaster 120deg 20cm;", "location toaster 120deg 20cm;\n    location aboveTable 60deg 30cm;"
        )
        return text.replace(
            "move aboveToaster; move toaster; open; move top;\n    }", "move aboveTable; open; move top;\n    }"
        )

    build = variant(tmp_path, "drops", {"toast/ArmController.arc": drop_over_the_table})
    report = tmp_path / "report.json"
    result = run_cli(["--package", str(build), "--report", str(report), "--until-goal", "--max-time", "30"])
    assert result.returncode == 1, result.stdout + result.stderr
    found = read_report(report)
    assert found["goalReached"] is False
    assert "toast-dropped" in kinds(found) and "bread-loaded" not in kinds(found)
    dropped = next(e for e in found["events"] if e["kind"] == "toast-dropped")
    assert "fell onto the table" in dropped["text"]
    assert found["toast"] == {"level": 0.0, "color": "WHITE", "onPlate": False, "dropped": True}
    assert path_of(found, CTRL) == ["Idle", "Loading", "Toasting"]
