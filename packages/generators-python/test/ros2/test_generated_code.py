"""The generated ROS 2 code of the example is valid Python, ruff-clean, and its deployment is sim-server's format."""

from __future__ import annotations

import json
import py_compile
import subprocess
import sys
from pathlib import Path

import pytest
from ros2_support import IFACE, PKG, RUFF_CONFIG, Generated

KNOWN_THIRD_PARTY = f"lint.isort.known-third-party=['{PKG}','{IFACE}','maa_behavior','maa_ros2']"
RUFF = [sys.executable, "-m", "ruff", "check", "--no-cache", "--config", str(RUFF_CONFIG)]
DIST = "/toast_service_robot/dist/value"


def python_files(root: Path) -> list[Path]:
    return sorted(p for p in root.rglob("*.py") if "__pycache__" not in p.parts)


def test_every_generated_python_file_compiles(generated: Generated, tmp_path: Path) -> None:
    files = python_files(generated.platform)
    assert len(files) > 20
    for i, f in enumerate(files):
        py_compile.compile(str(f), cfile=str(tmp_path / f"{i}.pyc"), doraise=True)


def test_generated_code_is_ruff_clean(generated: Generated) -> None:
    pytest.importorskip("ruff", reason="needs the venv of scripts/setup_ros2_venv.sh")
    result = subprocess.run(
        [*RUFF, "--config", KNOWN_THIRD_PARTY, str(generated.platform)],
        capture_output=True,
        text=True,
        check=False,
    )
    assert result.returncode == 0, result.stdout + result.stderr


def test_deployment_json_is_in_sim_server_format(generated: Generated) -> None:
    data = json.loads((generated.package / "deployment.json").read_text(encoding="utf-8"))
    assert data["format"] == "maa-deployment/1"
    assert data["application"] == "toast.ToastServiceRobot"
    assert data["package"] == PKG
    assert data["python_path"] == ["."]
    names = {n["name"]: n for n in data["nodes"]}
    assert sorted(names) == ["arm", "color", "ctrl", "dist", "plate", "toaster", "toaster_ctrl"]
    publishers: dict[str, str] = {}
    types: dict[str, str] = {}
    for n in data["nodes"]:
        assert n["namespace"] == "/toast_service_robot"
        assert n["module"] == f"{PKG}.nodes.{n['name']}"
        assert "use_sim_time" not in n["parameters"]
        for t in n["publishes"]:
            assert t["topic"] not in publishers, f"{t['topic']} has two publishers"
            publishers[t["topic"]] = n["name"]
        for t in n["publishes"] + n["subscribes"]:
            assert types.setdefault(t["topic"], t["type"]) == t["type"]
    assert names["ctrl"]["parameters"] == {"threshold": 25}
    ctrl = names["ctrl"]
    assert {"port": "distance", "topic": DIST, "type": "std_msgs/msg/Int32"} in ctrl["subscribes"]
    arm = {"port": "arm", "topic": "/toast_service_robot/ctrl/arm", "type": f"{IFACE}/msg/ArmProgram"}
    assert arm in ctrl["publishes"]
    # the platform components and the RobotArm executor talk to the simulator's topics
    assert {"topic": "/sensors/distance", "type": "std_msgs/msg/Int32"} in names["dist"]["subscribes"]
    assert {"topic": "/sensors/color", "type": "std_msgs/msg/String"} in names["color"]["subscribes"]
    assert {"topic": "/toaster/command", "type": "std_msgs/msg/String"} in names["toaster"]["publishes"]
    assert {"topic": "/joint_states", "type": "sensor_msgs/msg/JointState"} in names["arm"]["subscribes"]
    assert {"topic": "/arm/joint_command", "type": "sensor_msgs/msg/JointState"} in names["arm"]["publishes"]
    assert {"topic": "/arm/gripper_command", "type": "std_msgs/msg/Float64"} in names["arm"]["publishes"]


def test_sim_server_accepts_the_deployment(generated: Generated) -> None:
    """sim-server's own loader, when its sources are there (it needs no ROS to parse)."""
    src = Path(__file__).resolve().parents[4] / "sim-server" / "src"
    if not (src / "maa_sim" / "deployment.py").exists():
        return
    code = (
        "import sys; sys.path.insert(0, sys.argv[1]);"
        "from pathlib import Path; from maa_sim.deployment import Deployment;"
        "d = Deployment.load(Path(sys.argv[2])); print(len(d.nodes))"
    )
    result = subprocess.run(
        [sys.executable, "-c", code, str(src), str(generated.package)], capture_output=True, text=True, check=False
    )
    if "No module named" in result.stderr and "maa_sim" not in result.stderr:
        return  # a dependency of maa_sim's package is not in this venv
    assert result.returncode == 0, result.stderr
    assert result.stdout.strip() == "7"


def test_handwritten_python_is_ruff_clean() -> None:
    """The ROS 2 RTE, these tests and the example's platform components."""
    here = Path(__file__).resolve().parent
    package = here.parents[1]
    example = package.parents[1] / "examples" / "toast-service" / "toast"
    targets = [package / "rte" / "maa_ros2", here, *sorted(example.glob("*.ros2.py"))]
    result = subprocess.run(
        [*RUFF, "--config", KNOWN_THIRD_PARTY, *map(str, targets)],
        capture_output=True,
        text=True,
        check=False,
    )
    assert result.returncode == 0, result.stdout + result.stderr


def test_golden_files_are_ruff_clean() -> None:
    golden = Path(__file__).resolve().parents[1] / "golden-ros2"
    config = "lint.isort.known-third-party=['robot','robot_interfaces','maa_behavior','maa_ros2']"
    result = subprocess.run(
        [*RUFF, "--config", config, str(golden)],
        capture_output=True,
        text=True,
        check=False,
    )
    assert result.returncode == 0, result.stdout + result.stderr


def test_ros2_rte_type_checks() -> None:
    """maa_ros2 is typed: mypy --strict (rclpy and the message packages count as untyped)."""
    pytest.importorskip("mypy", reason="needs the venv of scripts/setup_ros2_venv.sh")
    rte = Path(__file__).resolve().parents[2] / "rte"
    result = subprocess.run(
        [
            sys.executable,
            "-m",
            "mypy",
            "--strict",
            "--ignore-missing-imports",
            "--no-incremental",
            "--cache-dir",
            "/dev/null",
            "-p",
            "maa_ros2",
        ],
        cwd=rte,
        capture_output=True,
        text=True,
        check=False,
    )
    assert result.returncode == 0, result.stdout + result.stderr
