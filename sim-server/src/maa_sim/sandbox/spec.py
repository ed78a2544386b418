"""What a sandboxed run may see and use (`SandboxSpec`, `Limits`) and how it ended (`SandboxResult`)."""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import Literal


class SandboxError(Exception):
    """The sandbox cannot be set up (bubblewrap missing, a path to bind missing, a bad spec)."""


@dataclass(frozen=True)
class Limits:
    """Resource limits of one run (rlimits of every process in it, and a wall-clock kill).

    ``wall_seconds`` <= 0 means no wall-clock limit (live simulations end when the lab stops them);
    ``memory_mb`` is the address space of each process (RLIMIT_AS), ``processes`` the number of
    processes and threads of the run's user (RLIMIT_NPROC), ``file_size_mb`` the largest file a
    process may write (RLIMIT_FSIZE, also the size of the sandbox's /tmp and /dev/shm).
    """

    wall_seconds: float
    cpu_seconds: int
    memory_mb: int
    processes: int
    file_size_mb: int
    open_files: int = 256

    def check(self) -> None:
        """Raises SandboxError for a limit that makes no sense."""
        for name in ("cpu_seconds", "memory_mb", "processes", "file_size_mb", "open_files"):
            value = getattr(self, name)
            if not isinstance(value, int) or value < 1:
                raise SandboxError(f"limit {name} must be a positive whole number, not {value!r}")


@dataclass(frozen=True)
class SandboxSpec:
    """The file system view, network, environment and limits of a run.

    ``readonly`` and ``writable`` are bound at their own paths (nothing else of the host's file
    system but the system directories and the interpreter's prefixes is visible); ``cwd`` must lie
    in one of them (or be /tmp). ``env`` is added to the minimal environment (PATH, HOME=/tmp,
    LANG); ``ros_domain`` sets ROS_DOMAIN_ID.
    """

    readonly: Sequence[Path]
    writable: Sequence[Path]
    cwd: Path
    limits: Limits
    network: Literal["none", "host"] = "none"
    env: Mapping[str, str] = field(default_factory=dict)
    ros_domain: int | None = None


@dataclass
class SandboxResult:
    """How a run ended. ``stdout``/``stderr`` are the tails of its output (at most 64 KiB each)."""

    exit_code: int | None
    signal: int | None
    timed_out: bool
    wall_seconds: float
    stdout: str
    stderr: str
    #: in plain words: "exited with 0", "killed: wall time limit (120 s)", "killed: CPU time limit (100 s)", ...
    reason: str
    #: CPU seconds the run's processes used (user + system)
    cpu_seconds: float = 0.0

    @property
    def ok(self) -> bool:
        return self.exit_code == 0 and not self.timed_out
