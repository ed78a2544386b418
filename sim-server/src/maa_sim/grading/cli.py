"""`python -m maa_sim.grading`: run a grade job on Ray, or start/stop a local Ray cluster."""

from __future__ import annotations

import argparse
import os
import sys
from pathlib import Path

from maa_sim.grading.job import JobError, load_job

USAGE = """\
python -m maa_sim.grading run --job JOB.json --out DIR [--workers N] [--grace S]
python -m maa_sim.grading cluster start --dir DIR [--nodes N] [--cpus-per-node C] [--port P]
python -m maa_sim.grading cluster stop --dir DIR"""

DESCRIPTION = """\
run: runs every task of JOB.json (format maa-grade-job/1) as a Ray task, each in the sandbox, and
prints one JSON line per event on stdout (started, task, finished); the outputs of task T land in
DIR/T/ with stdout.txt, stderr.txt and result.json. Ray joins the cluster of $RAY_ADDRESS when it
is set (with its RAY_AUTH_MODE/RAY_AUTH_TOKEN), else it runs on this machine.
Exit code 0 when the job ran (whatever its tasks did), 2 for a bad job file, 1 when Ray failed.

cluster start: starts a local Ray cluster on 127.0.0.1 (a head node and N-1 worker node processes,
each with C CPUs), waits until every node has registered and prints the environment a driver
needs (RAY_ADDRESS, RAY_AUTH_MODE, RAY_AUTH_TOKEN; also written to DIR/cluster.json).
cluster stop: stops the processes of the cluster started in DIR and removes its Ray directories."""


def _parser() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(
        prog="python -m maa_sim.grading",
        usage=USAGE,
        description=DESCRIPTION,
        formatter_class=argparse.RawDescriptionHelpFormatter,
    )
    commands = parser.add_subparsers(dest="command", required=True, metavar="run|cluster")
    run = commands.add_parser("run", help="run a grade job")
    run.add_argument("--job", type=Path, required=True, help="the job file (maa-grade-job/1)")
    run.add_argument("--out", type=Path, required=True, help="the directory the tasks' outputs go to")
    run.add_argument("--workers", type=int, default=None, help="CPUs of a local Ray instance (default: all)")
    run.add_argument(
        "--grace", type=float, default=30.0, help="seconds past a task's wall time before it is cancelled (default 30)"
    )
    cluster = commands.add_parser("cluster", help="start or stop a local Ray cluster")
    cluster.add_argument("action", choices=["start", "stop"])
    cluster.add_argument("--dir", type=Path, required=True, help="the cluster's directory (Ray's files, cluster.json)")
    cluster.add_argument("--nodes", type=int, default=2, help="nodes: the head and N-1 workers (default 2)")
    cluster.add_argument("--cpus-per-node", type=int, default=1, help="CPUs each node offers (default 1)")
    cluster.add_argument("--port", type=int, default=None, help="the head's port (default: a free one)")
    return parser


def _run(args: argparse.Namespace) -> int:
    try:
        from maa_sim.grading.driver import Lines, Options, run_job
    except ImportError as error:
        hint = "install maa-sim with its grade extra (pip install 'maa-sim[grade]')"
        print(f"maa_sim.grading: {error}: {hint}", file=sys.stderr)
        return 1
    if args.workers is not None and args.workers < 1:
        print("maa_sim.grading: --workers must be at least 1", file=sys.stderr)
        return 2
    if args.grace < 0:
        print("maa_sim.grading: --grace must not be negative", file=sys.stderr)
        return 2
    try:
        tasks = load_job(args.job)
    except JobError as error:
        print(f"maa_sim.grading: bad job: {error}", file=sys.stderr)
        return 2
    # The JSON lines keep the original stdout; whatever else writes to fd 1 (Ray and the processes
    # it starts) goes to stderr.
    lines = Lines(os.fdopen(os.dup(1), "w", encoding="utf-8"))
    os.dup2(2, 1)
    try:
        run_job(tasks, args.out, lines, Options(workers=args.workers, grace=args.grace))
    except (ConnectionError, RuntimeError, ValueError) as error:  # Ray cannot start or reach the cluster
        print(f"maa_sim.grading: Ray failed: {error}", file=sys.stderr)
        return 1
    return 0


def _cluster(args: argparse.Namespace) -> int:
    from maa_sim.grading.cluster import ClusterError, start_cluster, stop_cluster

    try:
        if args.action == "stop":
            stop_cluster(args.dir)
            print(f"stopped the cluster of {args.dir}")
            return 0
        if args.nodes < 1 or args.cpus_per_node < 1:
            print("maa_sim.grading: --nodes and --cpus-per-node must be at least 1", file=sys.stderr)
            return 2
        cluster = start_cluster(args.dir, nodes=args.nodes, cpus_per_node=args.cpus_per_node, port=args.port)
    except ClusterError as error:
        print(f"maa_sim.grading: {error}", file=sys.stderr)
        return 1
    for name, value in cluster.env().items():
        print(f"{name}={value}")
    return 0


def main(argv: list[str] | None = None) -> int:
    args = _parser().parse_args(argv)
    return _run(args) if args.command == "run" else _cluster(args)
