"""`maa-gen` commands in one warm Node process per pytest session (warm-maa-gen.mjs).

A cold ``node packages/cli/bin/maa-gen.js generate ...`` spends about two seconds of CPU loading the
language services before it generates; the suites generate a dozen builds. ``run`` answers what
``subprocess.run([... maa-gen ...], capture_output=True, text=True)`` would: the exit code main()
returns (the one the bin exits with), stdout and stderr. The ROS 2 suite of generators-python
imports this module too (from this folder).
"""

from __future__ import annotations

import atexit
import json
import shutil
import subprocess
import tempfile
import threading
from pathlib import Path

REPO = Path(__file__).resolve().parents[2]
SCRIPT = Path(__file__).resolve().parent / "warm-maa-gen.mjs"
#: wall seconds a command may take before the test fails (a loaded 2-core machine; cold: ~10 s)
TIMEOUT = 300.0

_lock = threading.Lock()
_process: subprocess.Popen[str] | None = None
#: the Node process's stderr (its own failures, e.g. an unbuilt CLI): quoted when it gives no answer
_stderr = tempfile.TemporaryFile()  # noqa: SIM115 - open for the whole session


def _stop() -> None:
    global _process
    if _process is not None:
        if _process.stdin is not None:
            _process.stdin.close()
        try:
            _process.wait(timeout=10)
        except subprocess.TimeoutExpired:
            _process.kill()
            _process.wait()
        _process = None


def _started() -> subprocess.Popen[str]:
    global _process
    if _process is None or _process.poll() is not None:
        node = shutil.which("node")
        if node is None:
            raise FileNotFoundError("node is needed to run maa-gen")
        _process = subprocess.Popen(
            [node, str(SCRIPT)], stdin=subprocess.PIPE, stdout=subprocess.PIPE, stderr=_stderr, text=True, cwd=REPO
        )
        atexit.register(_stop)
    return _process


def run(args: list[str], cwd: Path = REPO) -> subprocess.CompletedProcess[str]:
    """``maa-gen ARGS`` in ``cwd``: its exit code, stdout and stderr."""
    with _lock:
        process = _started()
        stdin, stdout = process.stdin, process.stdout
        assert stdin is not None and stdout is not None
        stdin.write(json.dumps({"args": args, "cwd": str(cwd)}) + "\n")
        stdin.flush()
        answer: list[str] = []
        # readline in a thread: a hung command fails the test after TIMEOUT instead of hanging it
        reader = threading.Thread(target=lambda: answer.append(stdout.readline()), daemon=True)
        reader.start()
        reader.join(TIMEOUT)
        if not answer or not answer[0]:
            process.kill()
            _stderr.seek(0)
            tail = _stderr.read()[-4000:].decode(errors="replace")
            raise RuntimeError(f"warm maa-gen gave no answer to {args} (exit {process.wait()}):\n{tail}")
        reply = json.loads(answer[0])
    return subprocess.CompletedProcess(["maa-gen", *args], reply["code"], reply["stdout"], reply["stderr"])
