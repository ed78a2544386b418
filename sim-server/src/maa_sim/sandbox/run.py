"""Runs one command in a bubblewrap sandbox: a separate uid per run (when root), rlimits, a wall-clock
kill of the whole sandbox (its pid namespace), output tails and the reason it ended in plain words."""

from __future__ import annotations

import contextlib
import ctypes
import fcntl
import os
import random
import signal
import stat
import subprocess
import threading
import time
from collections.abc import Iterator, Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import IO

from .spec import Limits, SandboxError, SandboxResult, SandboxSpec
from .view import build_command, interpreter_of, python_view

#: Host uids the runs use, one per run at a time (MAA_SANDBOX_UIDS="first-last" changes the range).
DEFAULT_UIDS = (61000, 61999)
TAIL_BYTES = 64 * 1024


def uid_range() -> tuple[int, int]:
    text = os.environ.get("MAA_SANDBOX_UIDS", "")
    if not text:
        return DEFAULT_UIDS
    try:
        first, last = (int(x) for x in text.split("-"))
    except ValueError as e:
        raise SandboxError(f"MAA_SANDBOX_UIDS must look like 61000-61999, not {text!r}") from e
    if not 1000 <= first <= last:
        raise SandboxError(f"MAA_SANDBOX_UIDS {text!r} is not a range of unprivileged uids")
    return first, last


@contextlib.contextmanager
def run_user() -> Iterator[int | None]:
    """A uid of its own for one run (held by a lock file until the run ends); None when not root."""
    if os.geteuid() != 0:
        yield None
        return
    lock_dir = Path(os.environ.get("MAA_SANDBOX_LOCKS", "/run/maa-sandbox"))
    lock_dir.mkdir(mode=0o700, parents=True, exist_ok=True)
    first, last = uid_range()
    uids = list(range(first, last + 1))
    start = random.randrange(len(uids))
    for uid in uids[start:] + uids[:start]:
        fd = os.open(lock_dir / f"{uid}.lock", os.O_CREAT | os.O_RDWR, 0o600)
        try:
            fcntl.flock(fd, fcntl.LOCK_EX | fcntl.LOCK_NB)
        except BlockingIOError:
            os.close(fd)
            continue
        try:
            if _pids_of(uid):
                continue  # a process of this uid is alive (left over from an earlier run)
            yield uid
            return
        finally:
            os.close(fd)
    raise SandboxError(f"every sandbox uid {first}-{last} is in use")


@dataclass
class _Owner:
    path: Path
    uid: int
    gid: int


def _chown_tree(root: Path, uid: int, gid: int, strip_setid: bool) -> None:
    """lchown of the tree (never follows a symlink the run made); optionally clears set-id bits."""
    os.lchown(root, uid, gid)
    for dirpath, dirnames, filenames in os.walk(root, followlinks=False):
        for name in [*dirnames, *filenames]:
            p = os.path.join(dirpath, name)
            with contextlib.suppress(FileNotFoundError):
                os.lchown(p, uid, gid)
                st = os.lstat(p)
                if strip_setid and stat.S_ISREG(st.st_mode) and st.st_mode & (stat.S_ISUID | stat.S_ISGID):
                    os.chmod(p, stat.S_IMODE(st.st_mode) & ~(stat.S_ISUID | stat.S_ISGID))


@contextlib.contextmanager
def handed_over(writable: Sequence[Path], uid: int | None) -> Iterator[None]:
    """The writable folders belong to the run's uid while it runs, and to their owner again afterwards."""
    if uid is None:
        yield
        return
    owners = []
    for w in writable:
        st = os.stat(w)
        owners.append(_Owner(Path(w), st.st_uid, st.st_gid))
        _chown_tree(Path(w), uid, uid, strip_setid=False)
    try:
        yield
    finally:
        for o in owners:
            with contextlib.suppress(FileNotFoundError):
                _chown_tree(o.path, o.uid, o.gid, strip_setid=True)


class _Tail:
    """The last TAIL_BYTES of a stream, read by a thread of its own."""

    def __init__(self, stream: IO[bytes]) -> None:
        self.data = bytearray()
        self.thread = threading.Thread(target=self._read, args=(stream,), daemon=True)
        self.thread.start()

    def _read(self, stream: IO[bytes]) -> None:
        with stream:
            while chunk := stream.read1(65536) if hasattr(stream, "read1") else stream.read(65536):
                self.data += chunk
                if len(self.data) > 2 * TAIL_BYTES:
                    del self.data[: len(self.data) - TAIL_BYTES]

    def text(self) -> str:
        self.thread.join(timeout=10)
        return bytes(self.data[-TAIL_BYTES:]).decode(errors="replace")


def _extra_readonly(argv: Sequence[str]) -> list[Path]:
    python = interpreter_of(argv[0])
    return list(python_view(python)) if python else []


@dataclass
class _Ended:
    returncode: int
    timed_out: bool
    wall: float
    cpu: float


def _pids_of(uid: int) -> list[int]:
    pids = []
    for entry in os.scandir("/proc"):
        if entry.name.isdigit():
            with contextlib.suppress(OSError):
                if entry.stat().st_uid == uid:
                    pids.append(int(entry.name))
    return pids


def _living_members(group: int, uid: int | None) -> list[int]:
    """Processes (not zombies) of the process group or of the uid."""
    found = []
    for entry in os.scandir("/proc"):
        if not entry.name.isdigit():
            continue
        try:
            fields = Path(entry.path, "stat").read_text().rpartition(")")[2].split()
            owner = entry.stat().st_uid
        except OSError:
            continue
        state, pgrp = fields[0], int(fields[2])
        if state not in ("Z", "X") and (pgrp == group or (uid is not None and owner == uid)):
            found.append(int(entry.name))
    return found


def _end_leftovers(group: int, uid: int | None, patience: float = 30.0) -> None:
    """Kills what is left of a sandbox and waits until it is gone. bwrap returns as soon as the
    command ended, while the pid namespace (the command's children) is torn down after it; the
    run's processes are its process group and, as root, every process of the run's uid."""
    deadline = time.monotonic() + patience
    while (alive := _living_members(group, uid)) and time.monotonic() < deadline:
        for pid in alive:
            with contextlib.suppress(ProcessLookupError):
                os.kill(pid, signal.SIGKILL)
        time.sleep(0.01)


def _wait(proc: subprocess.Popen[bytes], wall_seconds: float, uid: int | None) -> _Ended:
    """Waits for the sandbox (killing its whole process group and pid namespace at the wall limit);
    reaps it with wait4 for the CPU time of everything that ran in it; ends what is left of it."""
    started = time.monotonic()
    done = threading.Event()
    box: list[tuple[int, float]] = []

    def reap() -> None:
        _, status, usage = os.wait4(proc.pid, 0)
        box.append((os.waitstatus_to_exitcode(status), usage.ru_utime + usage.ru_stime))
        done.set()

    threading.Thread(target=reap, daemon=True).start()
    timed_out = False
    if not done.wait(wall_seconds if wall_seconds > 0 else None):
        timed_out = True
        # bwrap leads its own process group; the sandbox's pid 1 dies with it (--die-with-parent),
        # and with pid 1 every process of the pid namespace.
        with contextlib.suppress(ProcessLookupError):
            os.killpg(proc.pid, signal.SIGKILL)
        done.wait()
    returncode, cpu = box[0]
    proc.returncode = returncode
    _end_leftovers(proc.pid, uid)
    return _Ended(returncode, timed_out, time.monotonic() - started, cpu)


def run_sandboxed(argv: Sequence[str], spec: SandboxSpec) -> SandboxResult:
    """Runs argv in a sandbox of the spec and waits for it; the output is kept as tails.

    Raises SandboxError when the sandbox cannot be set up; whatever the command does is a result."""
    spec.limits.check()
    with run_user() as uid, handed_over(spec.writable, uid):
        cmd = build_command(argv, spec, _extra_readonly(argv), uid, None, _nproc_base(uid))
        try:
            proc = subprocess.Popen(
                cmd, stdin=subprocess.DEVNULL, stdout=subprocess.PIPE, stderr=subprocess.PIPE, start_new_session=True
            )
        except OSError as e:
            raise SandboxError(f"cannot start bubblewrap: {e}") from e
        assert proc.stdout is not None and proc.stderr is not None
        out, err = _Tail(proc.stdout), _Tail(proc.stderr)
        ended = _wait(proc, spec.limits.wall_seconds, uid)
        stdout, stderr = out.text(), err.text()
    code, sig = split_status(ended.returncode, ended.timed_out)
    reason = describe(code, sig, ended.timed_out, ended.cpu, spec, stderr)
    return SandboxResult(code, sig, ended.timed_out, ended.wall, stdout, stderr, reason, ended.cpu)


def _nproc_base(uid: int | None) -> int:
    return len(_pids_of(os.getuid())) if uid is None else 0


def split_status(returncode: int, timed_out: bool) -> tuple[int | None, int | None]:
    """(exit code, signal) of the command from bwrap's status (it exits 128+N when its command died of signal N)."""
    if timed_out:
        return None, signal.SIGKILL
    if returncode < 0:
        return None, -returncode
    if 128 < returncode <= 128 + 64:
        return None, returncode - 128
    return returncode, None


def _signal_name(sig: int) -> str:
    try:
        return signal.Signals(sig).name
    except ValueError:
        return f"signal {sig}"


#: Messages in the stderr tail that name a limit (a Python program turns most limits into exceptions).
_STDERR_HINTS = (
    (("MemoryError", "Cannot allocate memory", "std::bad_alloc", "out of memory"), "memory"),
    (("File too large",), "file size"),
    (("No space left on device",), "space"),
    (("Too many open files",), "open files"),
    (("Resource temporarily unavailable", "can't start new thread", "BlockingIOError"), "processes"),
)


def limit_words(kind: str, limits: Limits) -> str:
    return {
        "memory": f"out of memory: the memory limit ({limits.memory_mb} MB) was reached",
        "file size": f"file size limit ({limits.file_size_mb} MB) reached",
        "space": f"no space left (the sandbox's /tmp holds {max(16, limits.file_size_mb)} MB; or the disk is full)",
        "open files": f"open files limit ({limits.open_files}) reached",
        "processes": f"process limit ({limits.processes} processes) reached",
    }[kind]


def describe(
    code: int | None, sig: int | None, timed_out: bool, cpu: float, spec: SandboxSpec, stderr: str = ""
) -> str:
    """Why the run ended, in plain words."""
    lim = spec.limits
    if timed_out:
        return f"killed: wall time limit ({lim.wall_seconds:g} s)"
    if sig is not None:
        if sig == signal.SIGXCPU or (sig == signal.SIGKILL and cpu >= lim.cpu_seconds):
            return f"killed: CPU time limit ({lim.cpu_seconds} s)"
        if sig == signal.SIGXFSZ:
            return f"killed: {limit_words('file size', lim)}"
        if sig == signal.SIGKILL:
            return "killed by SIGKILL (out of memory, or killed from outside)"
        return f"killed by {_signal_name(sig)}"
    lines = [line.strip() for line in stderr.splitlines() if line.strip()]
    if code != 0:
        tail = "\n".join(lines[-12:])
        for needles, kind in _STDERR_HINTS:
            if any(n in tail for n in needles):
                return limit_words(kind, lim)
    words = f"exited with {code}"
    if code != 0 and lines:
        words += f": {lines[-1][:300]}"
        if spec.network == "none" and any(
            n in lines[-1] for n in ("Connection refused", "Network is unreachable", "Name or service not known")
        ):
            words += " (the sandbox has no network)"
    return words


def _children(pid: int) -> list[int]:
    try:
        with open(f"/proc/{pid}/task/{pid}/children") as f:
            return [int(p) for p in f.read().split()]
    except (OSError, ValueError):
        return []


def run_attached(argv: Sequence[str], spec: SandboxSpec) -> SandboxResult:
    """Like run_sandboxed, but the command's stdin/stdout/stderr are this process's own (no tails), and
    SIGTERM, SIGINT and SIGHUP to this process reach the command (so it can stop gracefully): the
    form `python -m maa_sim.sandbox` runs, e.g. under the lab's simulation sessions."""
    spec.limits.check()
    _become_subreaper()
    with run_user() as uid, handed_over(spec.writable, uid):
        cmd = build_command(argv, spec, _extra_readonly(argv), uid, None, _nproc_base(uid))
        try:
            # a process group of its own: a signal to the caller's group reaches bwrap only through us
            proc = subprocess.Popen(cmd, start_new_session=True)
        except OSError as e:
            raise SandboxError(f"cannot start bubblewrap: {e}") from e

        def forward(signum: int, _frame: object) -> None:
            # bwrap -> the sandbox's pid 1 -> the command (and what was orphaned to pid 1)
            for init in _children(proc.pid):
                for pid in _children(init):
                    with contextlib.suppress(ProcessLookupError):
                        os.kill(pid, signum)

        previous = {s: signal.signal(s, forward) for s in (signal.SIGTERM, signal.SIGINT, signal.SIGHUP)}
        try:
            ended = _wait(proc, spec.limits.wall_seconds, uid)
            _reap_adopted()
        finally:
            for s, handler in previous.items():
                signal.signal(s, handler)
    code, sig = split_status(ended.returncode, ended.timed_out)
    reason = describe(code, sig, ended.timed_out, ended.cpu, spec)
    return SandboxResult(code, sig, ended.timed_out, ended.wall, "", "", reason, ended.cpu)


def _become_subreaper() -> None:
    """Orphans of our children become ours (PR_SET_CHILD_SUBREAPER): the sandbox's pid 1, which
    outlives bwrap for a moment, is then reaped here and no zombie of the run is left behind."""
    libc = ctypes.CDLL(None, use_errno=True)
    libc.prctl(36, 1, 0, 0, 0)  # PR_SET_CHILD_SUBREAPER


def _reap_adopted() -> None:
    """Waits for every child left (the sandbox's pid 1 and whatever it adopted) and reaps it."""
    while True:
        try:
            os.waitpid(-1, 0)
        except ChildProcessError:
            return
