"""`python -m maa_sim.sandbox [options] -- CMD...`: runs CMD in the sandbox (see maa_sim.sandbox)."""

from __future__ import annotations

import argparse
import os
import sys
from pathlib import Path

from .run import run_attached
from .spec import Limits, SandboxError, SandboxSpec

DESCRIPTION = """Runs a command in a bubblewrap sandbox: a read-only view of the system folders, the
Python interpreter's folders (when CMD is a Python program) and the --ro folders; writable only
the --rw folders (and a small /tmp); new pid/ipc/uts namespaces, no network unless --network host;
a separate unprivileged uid per run when started as root; rlimits. The command's output is this
program's output; SIGTERM/SIGINT/SIGHUP are passed on to it. Exit code: the command's, 128+N when
it died of signal N, 125 when the sandbox could not be set up. Why it ended is printed to stderr
("maa-sandbox: ...") unless it exited with 0."""


def parser() -> argparse.ArgumentParser:
    p = argparse.ArgumentParser(prog="python -m maa_sim.sandbox", description=DESCRIPTION)
    p.add_argument("--ro", action="append", default=[], metavar="PATH", help="a folder or file to see read-only")
    p.add_argument("--rw", action="append", default=[], metavar="DIR", help="a folder the command may write")
    p.add_argument("--cwd", metavar="DIR", help="the working folder (default: the first --rw, else /tmp)")
    p.add_argument(
        "--network", choices=["none", "host"], default="none", help="host: the host's network (default none)"
    )
    p.add_argument("--ros-domain", type=int, metavar="N", help="ROS_DOMAIN_ID of the run (0..232)")
    p.add_argument("--env", action="append", default=[], metavar="NAME=VALUE", help="an environment variable")
    p.add_argument(
        "--pass-env",
        action="append",
        default=[],
        metavar="NAME",
        help="pass this variable of our own environment on (for secrets: a command line is visible to every user)",
    )
    p.add_argument("--wall-seconds", type=float, default=0, help="wall-clock limit (default 0: none)")
    p.add_argument("--cpu-seconds", type=int, default=3600, help="CPU time limit per process (default 3600)")
    p.add_argument("--memory-mb", type=int, default=4096, help="address space per process (default 4096)")
    p.add_argument("--processes", type=int, default=256, help="processes and threads of the run (default 256)")
    p.add_argument("--file-size-mb", type=int, default=256, help="largest file written; size of /tmp (default 256)")
    p.add_argument("--open-files", type=int, default=256, help="open files per process (default 256)")
    p.add_argument("command", nargs=argparse.REMAINDER, help="-- then the command and its arguments")
    return p


def spec_of(args: argparse.Namespace) -> SandboxSpec:
    env = {}
    for item in args.env:
        name, eq, value = item.partition("=")
        if not eq or not name:
            raise SandboxError(f"--env needs NAME=VALUE, not {item!r}")
        env[name] = value
    for name in args.pass_env:
        if name in os.environ:
            env[name] = os.environ[name]
    limits = Limits(
        args.wall_seconds, args.cpu_seconds, args.memory_mb, args.processes, args.file_size_mb, args.open_files
    )
    cwd = Path(args.cwd) if args.cwd else Path(args.rw[0]) if args.rw else Path("/tmp")
    return SandboxSpec(
        readonly=[Path(p) for p in args.ro],
        writable=[Path(p) for p in args.rw],
        cwd=cwd,
        limits=limits,
        network=args.network,
        env=env,
        ros_domain=args.ros_domain,
    )


def main(argv: list[str] | None = None) -> int:
    p = parser()
    args = p.parse_args(argv)
    command = args.command[1:] if args.command[:1] == ["--"] else args.command
    if not command:
        p.error("no command given (put it after --)")
    try:
        result = run_attached(command, spec_of(args))
    except SandboxError as e:
        print(f"maa-sandbox: {e}", file=sys.stderr)
        return 125
    if result.exit_code != 0:
        print(f"maa-sandbox: {result.reason}", file=sys.stderr, flush=True)
    if result.exit_code is not None:
        return result.exit_code
    return 128 + (result.signal or 9)


if __name__ == "__main__":
    sys.exit(main())
