"""The worker's side of a grading task: unpack the input, run the argv in the sandbox, pack the outputs.

`run_task` runs inside a Ray worker (on any node of the cluster). It gets the task as plain data
and its input directory as tar bytes, and returns plain data with the outputs as tar bytes: the
driver and the workers share no files.
"""

from __future__ import annotations

import contextlib
import os
import shutil
import sys
import tempfile
import time
from pathlib import Path
from typing import Any

from maa_sim.grading.bundle import pack_outputs, unpack
from maa_sim.sandbox import Limits, SandboxResult, SandboxSpec, run_sandboxed

#: The prefix of a task's scratch directory on the worker; the worker's pid follows it.
SCRATCH_PREFIX = "maa-grade-"


def node_name() -> str:
    """This Ray node as the task lines name it: `<ip>/<first 8 hex digits of the node id>`."""
    import ray

    util: Any = ray.util
    return f"{util.get_node_ip_address()}/{ray.get_runtime_context().get_node_id()[:8]}"


def status_of(result: SandboxResult) -> str:
    """ok, failed (an exit code other than 0), killed (a signal: a limit or someone killed it), timeout."""
    if result.timed_out:
        return "timeout"
    if result.exit_code == 0:
        return "ok"
    if result.signal is not None:
        return "killed"
    return "failed"


def resolve(text: str, input_dir: Path, output_dir: Path) -> str:
    """Replaces the placeholders {python}, {input} and {output} by what they are on this worker."""
    return (
        text.replace("{python}", sys.executable).replace("{input}", str(input_dir)).replace("{output}", str(output_dir))
    )


def _remove_stale_scratch() -> None:
    """Removes scratch directories of workers that are gone (a task cancelled with its worker left them)."""
    for entry in Path(tempfile.gettempdir()).glob(f"{SCRATCH_PREFIX}*"):
        pid = entry.name[len(SCRATCH_PREFIX) :].split("-", 1)[0]
        if pid.isdigit() and not Path(f"/proc/{pid}").exists():
            shutil.rmtree(entry, ignore_errors=True)


def _readable(root: Path) -> None:
    """Lets the sandbox's unprivileged user read the unpacked input (directories a+rx, files a+r)."""
    for directory, dirs, files in os.walk(root):
        os.chmod(directory, 0o755)
        for name in files:
            path = Path(directory) / name
            if not path.is_symlink():
                path.chmod(path.stat().st_mode | 0o444)
        del dirs  # walked by os.walk


def run_task(task: dict[str, Any], bundle: bytes) -> dict[str, Any]:
    """Runs one task (`JobTask.wire()` data) on this worker; never raises for what the task does."""
    started = time.monotonic()
    node = node_name()
    with contextlib.suppress(OSError):
        _remove_stale_scratch()
    scratch = Path(tempfile.mkdtemp(prefix=f"{SCRATCH_PREFIX}{os.getpid()}-{task['id']}-"))
    try:
        input_dir, output_dir = scratch / "input", scratch / "output"
        unpack(bundle, input_dir)
        _readable(input_dir)
        output_dir.mkdir()
        output_dir.chmod(0o755)
        limits = task["limits"]
        spec = SandboxSpec(
            readonly=[input_dir],
            writable=[output_dir],
            cwd=output_dir,
            limits=Limits(
                wall_seconds=float(limits["wallSeconds"]),
                cpu_seconds=int(limits["cpuSeconds"]),
                memory_mb=int(limits["memoryMB"]),
                processes=int(limits["processes"]),
                file_size_mb=int(limits["fileSizeMB"]),
            ),
            network="none",
            env={name: resolve(value, input_dir, output_dir) for name, value in task["env"].items()},
        )
        result = run_sandboxed([resolve(arg, input_dir, output_dir) for arg in task["argv"]], spec)
        packed = pack_outputs(output_dir, budget_bytes=4 * int(limits["fileSizeMB"]) * 1024 * 1024)
        message = result.reason
        if packed.skipped:
            message += f"; outputs left out: {', '.join(packed.skipped[:5])}"
            message += f" and {len(packed.skipped) - 5} more" if len(packed.skipped) > 5 else ""
        return {
            "status": status_of(result),
            "exitCode": result.exit_code,
            "signal": result.signal,
            "seconds": round(result.wall_seconds, 3),
            "node": node,
            "message": message,
            "stdout": result.stdout,
            "stderr": result.stderr,
            "outputs": packed.data,
        }
    except Exception as error:  # noqa: BLE001 - any failure of the machinery is the task's result "error"
        return {
            "status": "error",
            "exitCode": None,
            "signal": None,
            "seconds": round(time.monotonic() - started, 3),
            "node": node,
            "message": f"the grading worker failed: {type(error).__name__}: {error}",
            "stdout": "",
            "stderr": "",
            "outputs": b"",
        }
    finally:
        shutil.rmtree(scratch, ignore_errors=True)
