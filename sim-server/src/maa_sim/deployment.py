"""`deployment.json`: how to start a generated ROS 2 application without `launch`.

The ros2-python generator writes it next to the launch file; docs/simulation.md specifies the
format, @maa/protocol (packages/protocol/src/deployment) defines it: its JSON Schema, emitted
into `protocol.py`, is checked when the file is loaded, then the rules across nodes. Messages
name the file and the JSON pointer of the offending entry.
"""

from __future__ import annotations

import json
import math
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, cast

from .contracts import problem, validator
from .messages import MessageError, normalize_type
from .protocol import DEPLOYMENT_SCHEMA
from .protocol import Deployment as DeploymentDict
from .protocol import DeploymentNode as DeploymentNodeDict
from .protocol import PortTopic as PortTopicDict

DEPLOYMENT_FORMAT = "maa-deployment/1"

ParameterValue = bool | int | float | str | list[bool] | list[int] | list[float] | list[str]


class DeploymentError(ValueError):
    pass


@dataclass(frozen=True)
class PortTopic:
    topic: str
    type: str
    port: str = ""


@dataclass
class NodeSpec:
    name: str
    namespace: str = "/"
    module: str | None = None
    executable: str | None = None
    args: list[str] = field(default_factory=list)
    parameters: dict[str, ParameterValue] = field(default_factory=dict)
    publishes: list[PortTopic] = field(default_factory=list)
    subscribes: list[PortTopic] = field(default_factory=list)
    component: str = ""
    instance: str = ""

    @property
    def fqn(self) -> str:
        """The fully qualified node name, e.g. `/toast/ctrl`."""
        return f"{self.namespace.rstrip('/')}/{self.name}"


@dataclass
class Deployment:
    path: Path
    nodes: list[NodeSpec]
    python_path: list[Path] = field(default_factory=list)
    env: dict[str, str] = field(default_factory=dict)
    application: str = ""
    package: str = ""

    @property
    def directory(self) -> Path:
        return self.path.parent

    def topics(self) -> dict[str, str]:
        """Every topic of the application with its type."""
        result: dict[str, str] = {}
        for node in self.nodes:
            for t in (*node.publishes, *node.subscribes):
                result[t.topic] = t.type
        return result

    @classmethod
    def load(cls, directory_or_file: Path) -> Deployment:
        path = directory_or_file
        if path.is_dir():
            path = path / "deployment.json"
        try:
            data = json.loads(path.read_text(encoding="utf-8"))
        except FileNotFoundError:
            raise DeploymentError(f"{path} does not exist") from None
        except (json.JSONDecodeError, UnicodeDecodeError) as exc:
            raise DeploymentError(f"{path}: invalid JSON: {exc}") from None
        return cls.parse(data, path)

    @classmethod
    def parse(cls, data: Any, path: Path) -> Deployment:
        where = str(path)
        checked = check_deployment(data, where)
        nodes = [_node(n, f"{where}: /nodes/{i}") for i, n in enumerate(checked["nodes"])]
        seen: set[str] = set()
        for node in nodes:
            if node.fqn in seen:
                raise DeploymentError(f"{where}: two nodes are named {node.fqn}")
            seen.add(node.fqn)
        types: dict[str, str] = {}
        publishers: dict[str, str] = {}
        for node in nodes:
            for t in (*node.publishes, *node.subscribes):
                if types.setdefault(t.topic, t.type) != t.type:
                    raise DeploymentError(f"{where}: topic {t.topic} has two types, {types[t.topic]} and {t.type}")
            for t in node.publishes:
                if t.topic in publishers:
                    raise DeploymentError(
                        f"{where}: topic {t.topic} has two publishers, {publishers[t.topic]} and {node.fqn}"
                    )
                publishers[t.topic] = node.fqn
        return cls(
            path=path,
            nodes=nodes,
            python_path=[(path.parent / p).resolve() for p in checked.get("python_path", [])],
            env=dict(checked.get("env", {})),
            application=checked.get("application", ""),
            package=checked.get("package", ""),
        )


_VALIDATOR = validator(DEPLOYMENT_SCHEMA)


def check_deployment(data: Any, where: str) -> DeploymentDict:
    """Checks `data` against the deployment contract (@maa/protocol, emitted into protocol.py).

    The error names the file and the JSON pointer of the first bad field:
    `app/deployment.json: /nodes/0/name: name must be a ROS node name (letters, digits, _)`.
    """
    found = problem(_VALIDATOR, data)
    if found:
        raise DeploymentError(f"{where}: {found}")
    return cast(DeploymentDict, data)


def _topics(data: list[PortTopicDict], where: str) -> list[PortTopic]:
    result: list[PortTopic] = []
    for i, entry in enumerate(data):
        try:
            normalized = normalize_type(entry["type"])
        except MessageError as exc:
            raise DeploymentError(f"{where}/{i}/type: {exc}") from None
        result.append(PortTopic(entry["topic"], normalized, entry.get("port", "")))
    return result


def _finite(value: ParameterValue) -> bool:
    """JSON has no NaN or infinity, but Python's json module reads them: refused as parameters."""
    values = value if isinstance(value, list) else [value]
    return all(not isinstance(v, float) or math.isfinite(v) for v in values)


def _node(data: DeploymentNodeDict, where: str) -> NodeSpec:
    for name, value in data.get("parameters", {}).items():
        if not _finite(value):
            raise DeploymentError(f"{where}/parameters/{name}: parameter {name} must be a finite number")
    return NodeSpec(
        name=data["name"],
        namespace=data.get("namespace", "/"),
        module=data.get("module"),
        executable=data.get("executable"),
        args=list(data.get("args", [])),
        parameters=dict(data.get("parameters", {})),
        publishes=_topics(data.get("publishes", []), f"{where}/publishes"),
        subscribes=_topics(data.get("subscribes", []), f"{where}/subscribes"),
        component=data.get("component", ""),
        instance=data.get("instance", ""),
    )
