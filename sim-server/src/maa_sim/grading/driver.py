"""The grading driver: runs a job's tasks as Ray tasks and writes their lines and outputs.

One JSON object per line on the driver's output (docs/lab.md, "Grading"): `started`, a `task` line
as each task ends (flushed at once), `finished`. A task's outputs land in `OUTDIR/<id>/` with
`stdout.txt`, `stderr.txt` and `result.json` (its task line). Whatever the tasks do, the run ends:
the sandbox kills a command at its wall time; a task still running `grace` seconds after that is
cancelled (its worker killed) and reported `timeout`; a worker or node that dies gives `error`.
"""

from __future__ import annotations

import importlib
import json
import logging
import os
import re
import secrets
import shutil
import signal
import socket
import tempfile
import threading
import time
from collections import Counter
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path
from types import FrameType
from typing import IO, Any

import ray
from ray import exceptions

from maa_sim.grading.bundle import BundleError, pack_input, unpack
from maa_sim.grading.job import JobTask
from maa_sim.grading.task import run_task

#: Ray's module for the calls its stubs leave untyped
RAY: Any = ray
#: What a task may be: the contract's statuses, in the order `finished` counts them.
STATUSES = ("ok", "failed", "timeout", "killed", "error")
#: The tails of stdout and stderr kept in OUTDIR/<id>/ (bytes).
TAIL_BYTES = 64 * 1024


@dataclass(frozen=True)
class Options:
    """workers: CPUs of the local Ray instance (None: all of this machine's); grace: seconds a task
    may run past its wall time (unpacking, Ray's worker start) before it is cancelled."""

    workers: int | None = None
    grace: float = 30.0


class Lines:
    """The driver's JSON lines, each flushed at once (the caller reads them as progress)."""

    def __init__(self, stream: IO[str]) -> None:
        self.stream = stream

    def emit(self, line: dict[str, Any]) -> None:
        self.stream.write(json.dumps(line) + "\n")
        self.stream.flush()


@dataclass
class Connection:
    mode: str
    address: str | None
    temp_dir: Path | None


def _reachable(address: str, timeout: float = 10.0) -> None:
    """Fails fast (ConnectionError) when the head of `host:port` does not accept connections: Ray
    itself keeps retrying for minutes."""
    host, _, port = address.rpartition(":")
    if not host or not port.isdigit() or "://" in address:
        return
    try:
        socket.create_connection((host, int(port)), timeout=timeout).close()
    except OSError as error:
        raise ConnectionError(f"cannot reach the Ray cluster at RAY_ADDRESS={address}: {error}") from error


def connect(options: Options) -> Connection:
    """Joins the cluster of RAY_ADDRESS, else starts a local Ray instance (quiet, no dashboard).

    A local instance gets a token of its own (RAY_AUTH_MODE=token with a random RAY_AUTH_TOKEN,
    unless the environment sets the mode): nobody else on the network can submit work to it, and
    nothing is written to ~/.ray. A cluster needs the cluster's RAY_AUTH_MODE/RAY_AUTH_TOKEN.
    """
    os.environ.setdefault("RAY_USAGE_STATS_ENABLED", "0")
    address = os.environ.get("RAY_ADDRESS")
    if not address and "RAY_AUTH_MODE" not in os.environ:
        os.environ["RAY_AUTH_MODE"] = "token"
        os.environ["RAY_AUTH_TOKEN"] = secrets.token_hex(32)
    # Ray reads RAY_AUTH_MODE into its configuration when it is imported (before the lines above):
    # read it again, as Ray's own token set-up does.
    importlib.import_module("ray._raylet").Config.initialize("")
    if address:
        _reachable(address)
        ray.init(address=address, logging_level=logging.ERROR, log_to_driver=False)
        return Connection("cluster", address, None)
    # Ray's socket paths must stay short (< 108 bytes): its directory goes under /tmp, not $TMPDIR
    temp_dir = Path(tempfile.mkdtemp(prefix="maa-ray-", dir="/tmp"))
    try:
        ray.init(
            num_cpus=options.workers or os.cpu_count() or 1,
            include_dashboard=False,
            log_to_driver=False,
            logging_level=logging.ERROR,
            _temp_dir=str(temp_dir),
        )
    except BaseException:
        shutil.rmtree(temp_dir, ignore_errors=True)
        raise
    return Connection("local", ray.get_runtime_context().gcs_address, temp_dir)


def disconnect(connection: Connection) -> None:
    ray.shutdown()
    if connection.temp_dir is not None:
        shutil.rmtree(connection.temp_dir, ignore_errors=True)


def cluster_cpus() -> int:
    return max(1, int(RAY.cluster_resources().get("CPU", 1)))


def _tail(text: str) -> str:
    data = text.encode("utf-8", errors="replace")
    return data[-TAIL_BYTES:].decode("utf-8", errors="ignore") if len(data) > TAIL_BYTES else text


def task_line(task_id: str, outcome: dict[str, Any]) -> dict[str, Any]:
    return {
        "event": "task",
        "id": task_id,
        "status": outcome["status"],
        "exitCode": outcome["exitCode"],
        "signal": outcome["signal"],
        "seconds": outcome["seconds"],
        "node": outcome["node"],
        "message": outcome["message"],
    }


def failure(status: str, seconds: float, message: str, node: str = "unknown") -> dict[str, Any]:
    """The outcome of a task that returned nothing (cancelled, its worker died, its input unbundlable)."""
    return {
        "status": status,
        "exitCode": None,
        "signal": None,
        "seconds": round(seconds, 3),
        "node": node,
        "message": message,
        "stdout": "",
        "stderr": "",
        "outputs": b"",
    }


def ray_failure(error: Exception, seconds: float) -> dict[str, Any]:
    """The outcome of a task whose Ray task failed (not the command: the worker, its node, Ray)."""
    if isinstance(error, exceptions.OutOfMemoryError):
        return failure("killed", seconds, "killed by Ray's memory monitor: the node ran out of memory")
    if isinstance(error, exceptions.WorkerCrashedError):
        return failure("error", seconds, "the Ray worker running the task died (its process was killed or crashed)")
    if isinstance(error, exceptions.NodeDiedError | exceptions.LocalRayletDiedError):
        return failure("error", seconds, "the Ray node running the task died")
    cause = error.cause if isinstance(error, exceptions.RayTaskError) and error.cause is not None else error
    text = re.sub(r"\x1b\[[0-9;]*m", "", str(cause)).strip()
    first = text.splitlines()[-1] if text else ""
    return failure("error", seconds, f"Ray could not run the task: {type(cause).__name__}: {first}")


def write_outputs(out_dir: Path, task_id: str, outcome: dict[str, Any]) -> dict[str, Any]:
    """Writes OUTDIR/<id>/ (outputs, stdout.txt, stderr.txt, result.json); returns the task line."""
    target = out_dir / task_id
    shutil.rmtree(target, ignore_errors=True)
    target.mkdir(parents=True)
    if outcome["outputs"]:
        try:
            unpack(outcome["outputs"], target)
        except Exception as error:  # noqa: BLE001 - a broken archive makes the task's result "error"
            outcome = {**outcome, "status": "error", "message": f"{outcome['message']}; its outputs: {error}"}
    (target / "stdout.txt").write_text(_tail(outcome["stdout"]), encoding="utf-8")
    (target / "stderr.txt").write_text(_tail(outcome["stderr"]), encoding="utf-8")
    line = task_line(task_id, outcome)
    (target / "result.json").write_text(json.dumps(line, indent=2) + "\n", encoding="utf-8")
    return line


@dataclass
class Running:
    task: JobTask
    started: float


TaskFunction = Callable[[dict[str, Any], bytes], dict[str, Any]]


class Run:
    """One job's run: submits as many tasks as the cluster has CPUs, collects, cancels the overdue."""

    def __init__(self, tasks: list[JobTask], out_dir: Path, lines: Lines, grace: float, function: TaskFunction) -> None:
        self.pending = list(reversed(tasks))
        self.out_dir = out_dir
        self.lines = lines
        self.grace = grace
        self.remote = ray.remote(num_cpus=1, max_retries=0)(function)
        self.running: dict[Any, Running] = {}
        self.bundles: dict[Path, Any] = {}
        self.uses = Counter(task.input for task in tasks)
        self.counts = Counter({status: 0 for status in STATUSES})

    def finish(self, task: JobTask, outcome: dict[str, Any]) -> None:
        line = write_outputs(self.out_dir, task.id, outcome)
        self.counts[line["status"]] += 1
        self.lines.emit(line)

    def bundle(self, task: JobTask) -> Any:
        """The input bundle of `task` in Ray's object store, put once for the tasks that share an input."""
        ref = self.bundles.get(task.input)
        if ref is None:
            ref = ray.put(pack_input(task.input))
            self.bundles[task.input] = ref
        self.uses[task.input] -= 1
        if self.uses[task.input] == 0:
            del self.bundles[task.input]
        return ref

    def submit(self) -> None:
        while self.pending and len(self.running) < cluster_cpus():
            task = self.pending.pop()
            try:
                ref = self.remote.remote(task.wire(), self.bundle(task))
            except BundleError as error:
                self.finish(task, failure("error", 0.0, f"the task's input cannot be sent: {error}"))
                continue
            self.running[ref] = Running(task, time.monotonic())

    def collect(self) -> None:
        now = time.monotonic()
        deadline = min(r.started + r.task.wall_seconds + self.grace for r in self.running.values())
        ready, _ = ray.wait(list(self.running), num_returns=1, timeout=max(0.05, min(0.5, deadline - now)))
        for ref in ready:
            running = self.running.pop(ref)
            try:
                outcome = ray.get(ref)
            except Exception as error:  # noqa: BLE001 - every failure of Ray becomes the task's result
                outcome = ray_failure(error, time.monotonic() - running.started)
            self.finish(running.task, outcome)

    def cancel_overdue(self) -> None:
        now = time.monotonic()
        for ref, running in list(self.running.items()):
            limit = running.task.wall_seconds
            if now - running.started > limit + self.grace:
                ray.cancel(ref, force=True)
                del self.running[ref]
                message = f"cancelled: still running {self.grace:g} s after its wall time limit ({limit:g} s)"
                self.finish(running.task, failure("timeout", now - running.started, message))

    def run(self) -> Counter[str]:
        while self.pending or self.running:
            self.submit()
            if self.running:
                self.collect()
                self.cancel_overdue()
        return self.counts


#: The signals that stopped the run (SIGTERM).
_RECEIVED: list[int] = []


def _stop(signum: int, frame: FrameType | None) -> None:
    del frame
    _RECEIVED.append(signum)
    raise SystemExit(128 + signum)


def run_job(
    tasks: list[JobTask], out_dir: Path, lines: Lines, options: Options, function: TaskFunction = run_task
) -> None:
    """Runs `tasks` on Ray (local, or the cluster of RAY_ADDRESS), printing the lines of the contract."""
    begin = time.monotonic()
    out_dir.mkdir(parents=True, exist_ok=True)
    connection = connect(options)
    if threading.current_thread() is threading.main_thread():
        # after ray.init, which sets a handler of its own: SIGTERM ends the run through `finally`
        signal.signal(signal.SIGTERM, _stop)
    try:
        alive = [node for node in RAY.nodes() if node.get("Alive")]
        lines.emit(
            {
                "event": "started",
                "tasks": len(tasks),
                "mode": connection.mode,
                "address": connection.address,
                "nodes": len(alive),
                "cpus": float(RAY.cluster_resources().get("CPU", 0)),
            }
        )
        counts = Run(tasks, out_dir, lines, options.grace, function).run()
        lines.emit({"event": "finished", "wallSeconds": round(time.monotonic() - begin, 3), "counts": dict(counts)})
    except SystemExit:
        if _RECEIVED:  # inside ray.wait, Ray turns the handler's exit into SystemExit(1)
            raise SystemExit(128 + _RECEIVED[-1]) from None
        raise
    finally:
        disconnect(connection)
