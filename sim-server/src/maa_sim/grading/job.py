"""Reading a grade job (`maa-grade-job/1`, @maa/protocol's GradeJob contract) into tasks."""

from __future__ import annotations

import json
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from maa_sim.contracts import problem, validator
from maa_sim.protocol import GRADE_JOB_SCHEMA, GradeJobTask

_VALIDATOR = validator(GRADE_JOB_SCHEMA)


class JobError(Exception):
    """The job file cannot be run: unreadable, not JSON, not the contract, or an input directory is missing."""


@dataclass(frozen=True)
class JobTask:
    """One task: its input directory (bundled into the Ray task), argv and limits, env for the sandbox."""

    id: str
    input: Path
    argv: tuple[str, ...]
    wall_seconds: float
    cpu_seconds: int
    memory_mb: int
    processes: int
    file_size_mb: int
    env: dict[str, str] = field(default_factory=dict)

    @staticmethod
    def of(task: GradeJobTask) -> JobTask:
        limits = task["limits"]
        return JobTask(
            id=task["id"],
            input=Path(task["input"]),
            argv=tuple(task["argv"]),
            wall_seconds=float(limits["wallSeconds"]),
            cpu_seconds=limits["cpuSeconds"],
            memory_mb=limits["memoryMB"],
            processes=limits["processes"],
            file_size_mb=limits["fileSizeMB"],
            env=dict(task["env"]),
        )

    def wire(self) -> dict[str, Any]:
        """The task as the worker receives it (plain data: Ray pickles it to the worker)."""
        return {
            "id": self.id,
            "argv": list(self.argv),
            "env": dict(self.env),
            "limits": {
                "wallSeconds": self.wall_seconds,
                "cpuSeconds": self.cpu_seconds,
                "memoryMB": self.memory_mb,
                "processes": self.processes,
                "fileSizeMB": self.file_size_mb,
            },
        }


def check_job(data: Any, where: str) -> list[JobTask]:
    """The tasks of `data`, or JobError naming the first problem (`<where>: <pointer>: <message>`)."""
    found = problem(_VALIDATOR, data)
    if found:
        raise JobError(f"{where}: {found}")
    tasks = [JobTask.of(t) for t in data["tasks"]]
    seen: set[str] = set()
    for index, task in enumerate(tasks):
        if task.id in seen:
            raise JobError(f"{where}: /tasks/{index}/id: the task id '{task.id}' is used twice")
        seen.add(task.id)
        if not task.input.is_dir():
            raise JobError(f"{where}: /tasks/{index}/input: {task.input} is not a directory")
    return tasks


def load_job(path: Path) -> list[JobTask]:
    """Reads and checks the job file at `path`."""
    try:
        text = path.read_text(encoding="utf-8")
    except OSError as error:
        raise JobError(f"{path}: cannot read the job file ({error.strerror or error})") from error
    try:
        data = json.loads(text)
    except json.JSONDecodeError as error:
        raise JobError(f"{path}: not JSON ({error.msg} at line {error.lineno}, column {error.colno})") from error
    return check_job(data, str(path))
