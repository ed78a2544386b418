"""The bubblewrap command line of a run: its file system view, namespaces, user, limits and environment."""

from __future__ import annotations

import functools
import json
import os
import shutil
import subprocess
from collections.abc import Iterable, Sequence
from pathlib import Path

from .spec import SandboxError, SandboxSpec

#: System directories every run sees read-only (those that exist; symlinks such as /lib -> usr/lib are recreated).
SYSTEM_DIRS = ("/usr", "/lib", "/lib64", "/lib32", "/bin", "/sbin")
#: Single files of /etc that programs need (dynamic loader cache, time zone, name service config); no secrets.
ETC_FILES = (
    "/etc/ld.so.cache",
    "/etc/ld.so.conf",
    "/etc/localtime",
    "/etc/hosts",
    "/etc/host.conf",
    "/etc/nsswitch.conf",
    "/etc/alternatives",
)
#: Paths of the view that the sandbox makes itself; no spec path may be (or contain) one of them.
RESERVED = ("/", "/proc", "/dev", "/etc", "/usr", "/tmp")
MB = 1024 * 1024


def bwrap_path() -> str:
    """The bubblewrap binary (MAA_BWRAP, else `bwrap` on PATH, else /usr/bin/bwrap); SandboxError when missing."""
    found = os.environ.get("MAA_BWRAP") or shutil.which("bwrap") or "/usr/bin/bwrap"
    if not os.access(found, os.X_OK):
        raise SandboxError(
            "bubblewrap (bwrap) is not installed; install Debian's package: apt-get install -y bubblewrap"
        )
    return found


@functools.lru_cache(maxsize=16)
def python_view(python: str) -> tuple[Path, ...]:
    """The directories a Python interpreter needs: its base prefix, its venv and the folders on its
    sys.path (editable installs point into the repository). Asked from the interpreter itself in
    isolated mode (-I: no current folder, no PYTHONPATH), so nothing of a student's folder runs."""
    code = "import json, sys; print(json.dumps([sys.base_prefix, sys.base_exec_prefix, sys.prefix, *sys.path]))"
    try:
        out = subprocess.run(
            [python, "-I", "-c", code],
            cwd="/",
            env={"PATH": "/usr/bin:/bin"},
            capture_output=True,
            check=True,
            timeout=60,
        ).stdout
    except (OSError, subprocess.SubprocessError) as e:
        raise SandboxError(f"cannot ask the interpreter {python} for its folders: {e}") from e
    base_prefix, _, prefix, *_ = found = json.loads(out)
    dirs = [Path(p) for p in found if p and Path(p).is_dir()]
    for d in dirs:
        # a sys.path entry above the venv (a repository root) would show the whole repository
        if d != Path(prefix) and d in Path(prefix).parents and d != Path(base_prefix):
            raise SandboxError(f"{python} has {d} on sys.path, which holds its whole venv {prefix}; not bound")
    return tuple(outermost(dirs))


def interpreter_of(program: str) -> str | None:
    """The Python interpreter a command runs: the program itself (python3.11) or its `#!` line
    (a console script such as maa-sim); None when it is not a Python program."""
    path = os.path.abspath(shutil.which(program) or program)
    if not os.path.isfile(path):
        return None
    if Path(path).name.startswith("python"):
        return path
    try:
        with open(path, "rb") as f:
            first = f.readline(512)
    except OSError:
        return None
    if not first.startswith(b"#!"):
        return None
    words = first[2:].decode(errors="replace").split()
    if words and Path(words[0]).name == "env" and len(words) > 1:
        words = words[1:]
    if words and Path(words[0]).name.startswith("python"):
        return shutil.which(words[0]) or words[0]
    return None


def outermost(paths: Iterable[Path]) -> list[Path]:
    """The paths without those that lie inside another one, sorted."""
    result: list[Path] = []
    for p in sorted({Path(os.path.abspath(p)) for p in paths}, key=lambda p: (len(p.parts), str(p))):
        if not any(p == q or q in p.parents for q in result):
            result.append(p)
    return sorted(result)


def checked_dirs(paths: Sequence[Path], kind: str) -> list[Path]:
    """Absolute paths of existing directories or files; SandboxError for a missing or reserved one."""
    result = []
    for p in paths:
        a = Path(os.path.abspath(p))
        if not a.exists():
            raise SandboxError(f"the {kind} path {p} does not exist")
        if any(a == Path(r) for r in RESERVED):
            raise SandboxError(f"the {kind} path {p} is a system path of the sandbox and cannot be bound")
        result.append(a)
    return result


def build_command(
    argv: Sequence[str],
    spec: SandboxSpec,
    extra_readonly: Sequence[Path],
    uid: int | None,
    status_fd: int | None,
    nproc_base: int = 0,
) -> list[str]:
    """The full command line: bwrap [view, namespaces] -- [setpriv to the run's uid] -- prlimit [limits] -- argv.

    ``uid`` None: the caller is not root; bubblewrap then makes a user namespace instead of the
    separate uid (setpriv needs root), and the process limit counts the caller's other processes
    too, so ``nproc_base`` (their number) is added to it."""
    if not argv:
        raise SandboxError("no command to run")
    if "/" in argv[0] and not os.path.isabs(argv[0]):
        argv = [os.path.abspath(argv[0]), *argv[1:]]
    readonly = checked_dirs([*extra_readonly, *spec.readonly], "read-only")
    writable = checked_dirs(spec.writable, "writable")
    for w in writable:
        if not w.is_dir():
            raise SandboxError(f"the writable path {w} is not a directory")
    cwd = Path(os.path.abspath(spec.cwd))
    if cwd != Path("/tmp") and not any(cwd == d or d in cwd.parents for d in [*readonly, *writable]):
        raise SandboxError(f"the working directory {cwd} is not inside the sandbox's view")
    cmd = [bwrap_path(), *_namespaces(spec, uid), *_system_view(spec), *_binds(readonly, writable)]
    cmd += ["--chdir", str(cwd), "--clearenv"]
    for key, value in environment(spec).items():
        cmd += ["--setenv", key, value]
    if status_fd is not None:
        cmd += ["--json-status-fd", str(status_fd)]
    cmd.append("--")
    if uid is not None:
        cmd += ["setpriv", f"--reuid={uid}", f"--regid={uid}", "--clear-groups", "--no-new-privs"]
        cmd += ["--inh-caps=-all", "--bounding-set=-all", "--"]
    cmd += ["prlimit", *_rlimits(spec, nproc_base), "--", *argv]
    return cmd


def _namespaces(spec: SandboxSpec, uid: int | None) -> list[str]:
    args = ["--unshare-pid", "--unshare-ipc", "--unshare-uts", "--unshare-cgroup-try", "--die-with-parent"]
    args += ["--hostname", "sandbox"]
    if spec.network == "none":
        args.append("--unshare-net")
    elif spec.network != "host":
        raise SandboxError(f"network must be 'none' or 'host', not {spec.network!r}")
    if uid is None:
        # not root: a user namespace maps the caller's uid; no nested user namespaces inside
        args += ["--unshare-user", "--disable-userns"]
    else:
        # root: bubblewrap mounts as root; setpriv then drops to the run's uid with these two
        args += ["--cap-add", "CAP_SETUID", "--cap-add", "CAP_SETGID"]
    return args


def _system_view(spec: SandboxSpec) -> list[str]:
    args: list[str] = []
    for d in SYSTEM_DIRS:
        if os.path.islink(d):
            args += ["--symlink", os.readlink(d), d]
        elif os.path.isdir(d):
            args += ["--ro-bind", d, d]
    for f in ETC_FILES:
        args += ["--ro-bind-try", f, f]
    size = str(max(16, spec.limits.file_size_mb) * MB)
    args += ["--dev", "/dev", "--proc", "/proc", "--perms", "1777", "--size", size, "--tmpfs", "/tmp"]
    args += ["--perms", "1777", "--size", size, "--tmpfs", "/dev/shm"]
    return args


def _binds(readonly: list[Path], writable: list[Path]) -> list[str]:
    """Folders leading to the binds (0755, bubblewrap would make them 0700), then the binds, outer ones first."""
    targets = [*readonly, *writable]
    made: set[Path] = {Path("/"), Path("/tmp")}
    args: list[str] = []
    for t in sorted(targets, key=lambda p: len(p.parts)):
        for parent in reversed(t.parents):
            if parent in made or any(parent == d or d in parent.parents for d in targets):
                continue
            if parent.parts[1:2] and f"/{parent.parts[1]}" in (*SYSTEM_DIRS, "/proc", "/dev", "/etc"):
                continue  # these exist (read-only) in the view
            made.add(parent)
            args += ["--perms", "0755", "--dir", str(parent)]
    both = [(p, "--ro-bind") for p in readonly] + [(p, "--bind") for p in writable]
    for p, how in sorted(both, key=lambda b: (len(b[0].parts), b[1] == "--bind")):
        args += [how, str(p.resolve()), str(p)]
    return args


def environment(spec: SandboxSpec) -> dict[str, str]:
    """The run's whole environment: PATH, HOME=/tmp, LANG, the ROS 2 domain, then the spec's own variables."""
    env = {"PATH": "/usr/local/bin:/usr/bin:/bin", "HOME": "/tmp", "LANG": "C.UTF-8", "PYTHONUNBUFFERED": "1"}
    env["ROS_LOCALHOST_ONLY"] = "1"
    env["ROS_AUTOMATIC_DISCOVERY_RANGE"] = "LOCALHOST"
    if spec.ros_domain is not None:
        if not 0 <= spec.ros_domain <= 232:
            raise SandboxError(f"the ROS 2 domain must be 0..232, not {spec.ros_domain}")
        env["ROS_DOMAIN_ID"] = str(spec.ros_domain)
        env["MAA_SIM_ROS_DOMAIN"] = str(spec.ros_domain)  # maa-sim's own nodes use it (maa_sim.ros2.DomainLease)
    env.update(spec.env)
    return env


def _rlimits(spec: SandboxSpec, nproc_base: int) -> list[str]:
    lim = spec.limits
    lim.check()
    return [
        # the soft CPU limit sends SIGXCPU, the hard one (a second later) SIGKILL
        f"--cpu={lim.cpu_seconds}:{lim.cpu_seconds + 1}",
        f"--as={lim.memory_mb * MB}",
        f"--nproc={lim.processes + nproc_base}",
        f"--fsize={lim.file_size_mb * MB}",
        f"--nofile={lim.open_files}",
        "--core=0",
    ]
