"""`deployment.json`: how to start a generated ROS 2 application without `launch`.

The ros2-python generator writes it next to the launch file; docs/simulation.md specifies the
format. Everything is checked when it is loaded, with messages that name the offending entry.
"""

from __future__ import annotations

import json
import math
import re
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from .messages import MessageError, normalize_type

DEPLOYMENT_FORMAT = "maa-deployment/1"
_NAME_RE = re.compile(r"^[A-Za-z][A-Za-z0-9_]*$")
_NAMESPACE_RE = re.compile(r"^/([A-Za-z][A-Za-z0-9_]*(/[A-Za-z][A-Za-z0-9_]*)*)?$")
_TOPIC_RE = re.compile(r"^/[A-Za-z][A-Za-z0-9_]*(/[A-Za-z][A-Za-z0-9_]*)*$")
_RESERVED_ENV = ("ROS_DOMAIN_ID", "ROS_AUTOMATIC_DISCOVERY_RANGE", "ROS_STATIC_PEERS", "ROS_LOCALHOST_ONLY")

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
        if not isinstance(data, dict):
            raise DeploymentError(f"{where}: expected an object")
        if data.get("format") != DEPLOYMENT_FORMAT:
            raise DeploymentError(f"{where}: format must be {DEPLOYMENT_FORMAT!r}")
        nodes_data = data.get("nodes")
        if not isinstance(nodes_data, list) or not nodes_data:
            raise DeploymentError(f"{where}: nodes must be a non-empty list")
        nodes = [_parse_node(n, f"{where}: nodes[{i}]") for i, n in enumerate(nodes_data)]
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
        python_path = data.get("python_path", [])
        if not isinstance(python_path, list) or not all(isinstance(p, str) for p in python_path):
            raise DeploymentError(f"{where}: python_path must be a list of strings")
        env = data.get("env", {})
        if not isinstance(env, dict) or not all(isinstance(k, str) and isinstance(v, str) for k, v in env.items()):
            raise DeploymentError(f"{where}: env must map names to strings")
        for key in env:
            if key in _RESERVED_ENV:
                raise DeploymentError(f"{where}: env must not set {key} (the simulator sets it)")
        return cls(
            path=path,
            nodes=nodes,
            python_path=[(path.parent / p).resolve() for p in python_path],
            env=dict(env),
            application=str(data.get("application", "")),
            package=str(data.get("package", "")),
        )


def _parse_topics(data: Any, where: str) -> list[PortTopic]:
    if data is None:
        return []
    if not isinstance(data, list):
        raise DeploymentError(f"{where}: expected a list of {{topic, type, port}}")
    result: list[PortTopic] = []
    for i, entry in enumerate(data):
        here = f"{where}[{i}]"
        if not isinstance(entry, dict):
            raise DeploymentError(f"{here}: expected an object")
        topic, type_name, port = entry.get("topic"), entry.get("type"), entry.get("port", "")
        if not isinstance(topic, str) or not _TOPIC_RE.match(topic):
            raise DeploymentError(f"{here}: topic must be an absolute ROS name like /a/b")
        if not isinstance(type_name, str):
            raise DeploymentError(f"{here}: type must be a string like std_msgs/msg/Int32")
        try:
            normalized = normalize_type(type_name)
        except MessageError as exc:
            raise DeploymentError(f"{here}: {exc}") from None
        if not isinstance(port, str):
            raise DeploymentError(f"{here}: port must be a string")
        result.append(PortTopic(topic, normalized, port))
    return result


def _check_parameter(name: str, value: Any, where: str) -> ParameterValue:
    def scalar(v: Any) -> bool:
        return isinstance(v, bool | int | str) or (isinstance(v, float) and math.isfinite(v))

    if scalar(value):
        return value  # type: ignore[no-any-return]
    if isinstance(value, list) and value and all(scalar(v) for v in value):
        kinds = {type(v) for v in value}
        if len(kinds) == 1 or kinds == {int, float}:
            return value
    raise DeploymentError(
        f"{where}: parameter {name} must be a boolean, number, string or a non-empty list of one of them"
    )


def _parse_node(data: Any, where: str) -> NodeSpec:
    if not isinstance(data, dict):
        raise DeploymentError(f"{where}: expected an object")
    name = data.get("name")
    if not isinstance(name, str) or not _NAME_RE.match(name):
        raise DeploymentError(f"{where}: name must be a ROS node name (letters, digits, _)")
    namespace = data.get("namespace", "/")
    if not isinstance(namespace, str) or not _NAMESPACE_RE.match(namespace):
        raise DeploymentError(f"{where}: namespace must be absolute, like / or /toast")
    module, executable = data.get("module"), data.get("executable")
    if (module is None) == (executable is None):
        raise DeploymentError(f"{where}: give exactly one of module and executable")
    if module is not None and (not isinstance(module, str) or not re.match(r"^[A-Za-z_][\w.]*$", module)):
        raise DeploymentError(f"{where}: module must be a dotted Python module name")
    if executable is not None and (not isinstance(executable, str) or not executable):
        raise DeploymentError(f"{where}: executable must be a non-empty string")
    args = data.get("args", [])
    if not isinstance(args, list) or not all(isinstance(a, str) for a in args):
        raise DeploymentError(f"{where}: args must be a list of strings")
    parameters = data.get("parameters", {})
    if not isinstance(parameters, dict):
        raise DeploymentError(f"{where}: parameters must be an object")
    checked = {str(k): _check_parameter(str(k), v, where) for k, v in parameters.items()}
    if "use_sim_time" in checked:
        raise DeploymentError(f"{where}: use_sim_time is set by the simulator")
    return NodeSpec(
        name=name,
        namespace=namespace,
        module=module,
        executable=executable,
        args=list(args),
        parameters=checked,
        publishes=_parse_topics(data.get("publishes"), f"{where}.publishes"),
        subscribes=_parse_topics(data.get("subscribes"), f"{where}.subscribes"),
        component=str(data.get("component", "")),
        instance=str(data.get("instance", "")),
    )
