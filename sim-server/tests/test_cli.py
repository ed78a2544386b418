"""The maa-sim command line."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import pytest

from maa_sim.cli import build_parser, main

SIM_SERVER = Path(__file__).resolve().parent.parent


def test_help_lists_the_options(capsys: pytest.CaptureFixture[str]) -> None:
    with pytest.raises(SystemExit) as exit_info:
        build_parser().parse_args(["run", "--help"])
    assert exit_info.value.code == 0
    text = capsys.readouterr().out
    for option in ("--package", "--scene", "--mode", "--speed", "--rosbridge-port", "--viser-port", "--until-goal"):
        assert option in text


def test_bad_arguments() -> None:
    with pytest.raises(SystemExit):
        build_parser().parse_args(["run", "--package", ".", "--speed", "-1"])
    with pytest.raises(SystemExit):
        build_parser().parse_args(["run", "--package", ".", "--mode", "fast"])


def test_missing_package_is_an_error(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    code = main(
        ["run", "--package", str(tmp_path), "--mode", "lockstep", "--rosbridge-port", "off", "--viser-port", "off"]
    )
    assert code == 2
    assert "lockstep.json" in capsys.readouterr().err


def test_lockstep_run_until_goal(toast_app_dir: Path) -> None:
    result = subprocess.run(
        [
            sys.executable,
            "-m",
            "maa_sim.cli",
            "run",
            "--package",
            str(toast_app_dir),
            "--mode",
            "lockstep",
            "--until-goal",
            "--max-time",
            "40",
            "--rosbridge-port",
            "off",
            "--viser-port",
            "off",
        ],
        capture_output=True,
        text=True,
        check=False,
        timeout=120,
        cwd=SIM_SERVER,
    )
    assert result.returncode == 0, result.stdout + result.stderr
    assert "toast on the plate: True" in result.stdout
