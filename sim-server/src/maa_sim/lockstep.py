"""Lock-step mode: the application runs in the simulator's process, one time slice per period.

The python-timesync build of an application implements `LockstepController`; the simulator
calls `step` once per control period with the messages of that instant and applies the
actuator messages it returns before stepping the physics. A package directory for lock-step
mode holds `lockstep.json` (its contract: @maa/protocol's Lockstep, emitted into `protocol.py`):

    {
      "format": "maa-lockstep/1",
      "factory": "toast_service_robot_timesync.sim:create_controller",
      "python_path": ["."],
      "period": 0.02,
      "parameters": {}
    }

`factory` is `module:callable`; it is called with `parameters` and returns the controller.
"""

from __future__ import annotations

import contextlib
import importlib
import json
import math
import sys
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, Protocol, cast, runtime_checkable

from .contracts import problem, validator
from .messages import JsonMessage
from .protocol import LOCKSTEP_SCHEMA
from .protocol import Lockstep as LockstepDict

LOCKSTEP_FORMAT = "maa-lockstep/1"

#: What `step` may return per topic: one message, or several (a port written twice in a slice).
OutputValue = JsonMessage | Sequence[JsonMessage]


@runtime_checkable
class LockstepController(Protocol):
    """An application that runs one architecture time slice per call.

    `inputs` maps topic names to the latest message of each simulator topic (`/clock`,
    `/joint_states`, `/sensors/distance`, `/sensors/color`) plus messages injected over
    rosbridge. The result maps topic names to the messages emitted in this slice: actuator
    topics (`/arm/joint_command`, `/arm/gripper_command`, `/toaster/command`) are applied to
    the simulation; every other topic (internal port topics) is shown over rosbridge. A
    controller may also have `reset()`, called when the simulation is reset, and `topics()`
    returning `{topic: type}` of the port topics it emits.
    """

    def step(self, inputs: Mapping[str, JsonMessage]) -> Mapping[str, OutputValue]: ...


def normalize_outputs(outputs: Mapping[str, OutputValue] | None) -> dict[str, list[JsonMessage]]:
    """The controller's result as lists of messages per topic; rejects anything else."""
    result: dict[str, list[JsonMessage]] = {}
    if outputs is None:
        return result
    if not isinstance(outputs, Mapping):
        raise TypeError("a lock-step controller must return a mapping of topic to message(s)")
    for topic, value in outputs.items():
        kind = type(value)
        if kind is list and type(topic) is str:  # the usual shape (a timesync build's), before the ABC checks
            result[topic] = [dict(v) for v in cast(list[JsonMessage], value)]
            continue
        if not isinstance(topic, str):
            raise TypeError("topic names must be strings")
        if value is None:
            continue
        if isinstance(value, dict | Mapping):
            result[topic] = [dict(value)]
        elif isinstance(value, Sequence) and not isinstance(value, str | bytes):
            result[topic] = [dict(v) for v in value]
        else:
            raise TypeError(f"{topic}: a message must be an object (or a list of objects)")
    return result


_LOCKSTEP = validator(LOCKSTEP_SCHEMA)


def check_lockstep(data: Any, where: str) -> LockstepDict:
    """Checks a parsed `lockstep.json` against its contract (@maa/protocol); the error names the
    file and the JSON pointer of the bad field. JSON has no NaN or infinity (Python reads them):
    a period must be finite."""
    found = problem(_LOCKSTEP, data)
    if found:
        raise ValueError(f"{where}: {found}")
    checked = cast(LockstepDict, data)
    period = checked.get("period")
    if period is not None and not math.isfinite(period):
        raise ValueError(f"{where}: /period: period must be a positive number of seconds")
    return checked


@dataclass
class LockstepPackage:
    """A lock-step build described by its `lockstep.json`."""

    directory: Path
    factory: str
    python_path: list[Path] = field(default_factory=list)
    period: float | None = None
    parameters: dict[str, Any] = field(default_factory=dict)

    @classmethod
    def load(cls, directory: Path) -> LockstepPackage:
        path = directory / "lockstep.json"
        try:
            data = json.loads(path.read_text(encoding="utf-8"))
        except FileNotFoundError:
            raise ValueError(f"{path} does not exist (a lock-step package needs lockstep.json)") from None
        except json.JSONDecodeError as exc:
            raise ValueError(f"{path}: invalid JSON: {exc}") from None
        checked = check_lockstep(data, str(path))
        period = checked.get("period")
        return cls(
            directory=directory,
            factory=checked["factory"],
            python_path=[(directory / p).resolve() for p in checked.get("python_path", ["."])],
            period=float(period) if period is not None else None,
            parameters=dict(checked.get("parameters", {})),
        )

    def create(self) -> LockstepController:
        for entry in reversed(self.python_path):
            if str(entry) not in sys.path:
                sys.path.insert(0, str(entry))
        module_name, _, attr = self.factory.partition(":")
        self._forget_other_build(module_name)
        module = importlib.import_module(module_name)
        factory = getattr(module, attr)
        controller = factory(dict(self.parameters))
        if not callable(getattr(controller, "step", None)):
            raise TypeError(f"{self.factory} did not return a lock-step controller (no step method)")
        return controller  # type: ignore[no-any-return]

    def _forget_other_build(self, module_name: str) -> None:
        """Every timesync build has a `maa_app` (and its own RTE copies): when one process loads a
        second build, the first build's modules leave `sys.modules` so that the second one's load.
        """
        loaded = sys.modules.get(module_name)
        file = getattr(loaded, "__file__", None)
        if loaded is None or file is None:
            return
        roots = [p.resolve() for p in self.python_path]
        where = Path(file).resolve()
        if any(where.is_relative_to(r) for r in roots):
            return
        old_root = where.parent if where.name != "__init__.py" else where.parent.parent
        for _ in range(module_name.count(".")):
            old_root = old_root.parent
        if not (old_root / "lockstep.json").is_file():
            return  # not another lock-step build's folder: leave it alone
        for name, module in list(sys.modules.items()):
            path = getattr(module, "__file__", None)
            if path is not None and Path(path).resolve().is_relative_to(old_root):
                del sys.modules[name]
        with contextlib.suppress(ValueError):
            sys.path.remove(str(old_root))
