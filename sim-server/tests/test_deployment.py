"""deployment.json: the fixture loads; mistakes are named."""

from __future__ import annotations

import copy
import json
from pathlib import Path
from typing import Any

import pytest

from maa_sim.deployment import Deployment, DeploymentError, check_deployment


def test_fixture_deployment_loads(toast_app_dir: Path) -> None:
    deployment = Deployment.load(toast_app_dir)
    assert [n.fqn for n in deployment.nodes] == ["/toast/ctrl", "/toast/arm"]
    assert deployment.nodes[0].parameters == {"threshold": 25}
    assert deployment.topics()["/toast/ctrl/arm"] == "std_msgs/msg/String"
    assert deployment.python_path == [toast_app_dir.resolve()]


BASE: dict[str, Any] = {
    "format": "maa-deployment/1",
    "nodes": [{"name": "a", "module": "m", "publishes": [{"topic": "/t", "type": "std_msgs/Int32"}]}],
}


def mutate(change: Any) -> dict[str, Any]:
    data = copy.deepcopy(BASE)
    change(data)
    return data


@pytest.mark.parametrize(
    ("change", "message"),
    [
        (lambda d: d.update(format="x"), "format"),
        (lambda d: d.update(nodes=[]), "nodes"),
        (lambda d: d["nodes"][0].update(name="a-b"), "name"),
        (lambda d: d["nodes"][0].update(executable="x"), "exactly one"),
        (lambda d: d["nodes"][0].update(namespace="rel"), "namespace"),
        (lambda d: d["nodes"][0].update(parameters={"p": {"x": 1}}), "parameter p"),
        (lambda d: d["nodes"][0].update(parameters={"use_sim_time": False}), "use_sim_time"),
        (lambda d: d["nodes"].append(copy.deepcopy(d["nodes"][0])), "two nodes"),
        (
            lambda d: d["nodes"].append(
                {"name": "b", "module": "m", "publishes": [{"topic": "/t", "type": "std_msgs/Int32"}]}
            ),
            "two publishers",
        ),
        (
            lambda d: d["nodes"].append(
                {"name": "b", "module": "m", "subscribes": [{"topic": "/t", "type": "std_msgs/String"}]}
            ),
            "two types",
        ),
        (lambda d: d["nodes"][0]["publishes"][0].update(topic="no slash"), "topic"),
        (lambda d: d.update(env={"ROS_DOMAIN_ID": "3"}), "ROS_DOMAIN_ID"),
    ],
)
def test_errors_name_the_problem(tmp_path: Path, change: Any, message: str) -> None:
    path = tmp_path / "deployment.json"
    path.write_text(json.dumps(mutate(change)))
    with pytest.raises(DeploymentError, match=message):
        Deployment.load(tmp_path)


def test_invalid_json(tmp_path: Path) -> None:
    (tmp_path / "deployment.json").write_text("{")
    with pytest.raises(DeploymentError, match="invalid JSON"):
        Deployment.load(tmp_path)


@pytest.mark.parametrize(
    ("change", "message"),
    [
        (lambda d: d["nodes"][0].update(name="a-b"), r"deployment\.json: /nodes/0/name: name must be a ROS node name"),
        (lambda d: d["nodes"][0].pop("module"), r"\.json: /nodes/0: give exactly one of module and executable"),
        (lambda d: d["nodes"][0]["publishes"][0].update(topic="t"), r": /nodes/0/publishes/0/topic: topic must be"),
        (lambda d: d.update(python_path=[1]), r": /python_path/0: python_path must be a list of strings"),
        (lambda d: d["nodes"][0].update(parameters={"p": float("nan")}), r": /nodes/0/parameters/p: .* finite"),
    ],
)
def test_errors_name_file_and_json_pointer(tmp_path: Path, change: Any, message: str) -> None:
    path = tmp_path / "deployment.json"
    path.write_text(json.dumps(mutate(change)))
    with pytest.raises(DeploymentError, match=message):
        Deployment.load(tmp_path)


GENERATOR_TESTS = Path(__file__).resolve().parents[2] / "packages" / "generators-python" / "test"
GENERATED = sorted(GENERATOR_TESTS.glob("golden*/**/deployment.json"))


@pytest.mark.parametrize("path", GENERATED, ids=lambda p: str(p.parent.name))
def test_generated_deployments_keep_the_contract(path: Path) -> None:
    """What the ros2-python generator really writes (its golden files) passes the schema and the reader."""
    data = json.loads(path.read_text(encoding="utf-8"))
    assert check_deployment(data, str(path)) == data
    deployment = Deployment.load(path)
    assert [n.name for n in deployment.nodes] == [n["name"] for n in data["nodes"]]


def test_generated_deployments_exist() -> None:
    assert GENERATED, "no generated deployment.json found under packages/generators-python/test"
