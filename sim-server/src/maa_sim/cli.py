"""`maa-sim`: the command line of the simulation sidecar."""

from __future__ import annotations

import argparse
import json
import signal
import sys
import threading
from collections.abc import Sequence
from pathlib import Path
from types import FrameType

from . import __version__
from .app import RunOptions, SimApp
from .deployment import DeploymentError
from .messages import MessageError


def _positive_float(text: str) -> float:
    value = float(text)
    if not value > 0:
        raise argparse.ArgumentTypeError("must be > 0")
    return value


def _speed(text: str) -> float:
    value = float(text)
    if value < 0 or value > 1000:
        raise argparse.ArgumentTypeError("must be between 0 (as fast as possible) and 1000")
    return value


def _port(text: str) -> int | None:
    if text.lower() in ("off", "none", "no"):
        return None
    value = int(text)
    if not 0 <= value <= 65535:
        raise argparse.ArgumentTypeError("must be a TCP port (0 picks a free one) or 'off'")
    return value


def build_parser() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(
        prog="maa-sim",
        description="Simulation sidecar of the MontiArcAutomaton workbench: runs a generated application "
        "against a MuJoCo scene, with a rosbridge v2 endpoint and a viser 3D panel.",
    )
    parser.add_argument("--version", action="version", version=f"maa-sim {__version__}")
    commands = parser.add_subparsers(dest="command", required=True, metavar="COMMAND")
    run = commands.add_parser(
        "run",
        help="run an application in the simulator",
        description="Runs an application in the simulator until interrupted (Ctrl-C / SIGTERM), the goal is "
        "reached (--until-goal) or the time limit (--max-time). ROS 2 mode reads DIR/deployment.json and "
        "starts every node as an rclpy process; lock-step mode reads DIR/lockstep.json and runs the "
        "application in this process, one time slice per control period.",
    )
    run.add_argument("--package", required=True, type=Path, metavar="DIR", help="the generated package directory")
    run.add_argument("--scene", default="toast_kitchen", help="the MuJoCo scene (default: %(default)s)")
    run.add_argument(
        "--mode", choices=("ros2", "lockstep"), default="ros2", help="execution mode (default: %(default)s)"
    )
    run.add_argument(
        "--speed",
        type=_speed,
        default=None,
        help="simulated seconds per wall second; 0 = as fast as possible (default: 1 in ros2 mode, 0 in lockstep)",
    )
    run.add_argument("--period", type=_positive_float, default=None, help="control period in seconds (default: 0.02)")
    run.add_argument("--seed", type=int, default=0, help="random seed of the scene (default: %(default)s)")
    run.add_argument("--host", default="127.0.0.1", help="address to serve on (default: %(default)s)")
    run.add_argument(
        "--rosbridge-port",
        type=_port,
        default=9090,
        metavar="PORT|off",
        help="rosbridge v2 WebSocket port (default: %(default)s)",
    )
    run.add_argument(
        "--viser-port",
        type=_port,
        default=8080,
        metavar="PORT|off",
        help="viser panel HTTP port (default: %(default)s)",
    )
    run.add_argument(
        "--max-time", type=_positive_float, default=None, metavar="SECONDS", help="stop after this much simulated time"
    )
    run.add_argument(
        "--until-goal", action="store_true", help="stop when the toast lies on the plate (exit 0), else exit 1"
    )
    run.add_argument("--paused", action="store_true", help="start paused (resume over rosbridge or in the panel)")
    run.add_argument(
        "--on-node-failure",
        choices=("continue", "stop"),
        default="continue",
        help="what a crashed or hung node does to the run (default: %(default)s; it is reported either way)",
    )
    run.add_argument("--startup-timeout", type=_positive_float, default=30.0, help="seconds a node may take to come up")
    run.add_argument(
        "--hang-timeout",
        type=_positive_float,
        default=5.0,
        help="seconds without an answer before a node counts as hung",
    )
    run.add_argument(
        "--golden-seconds", type=_positive_float, default=6.0, help="seconds of toasting to reach golden toast"
    )
    run.add_argument("--log-dir", type=Path, default=None, help="where node logs go (default: a temporary directory)")
    run.add_argument(
        "--status-json", action="store_true", help="print one JSON line with ports and node pids once running"
    )
    return parser


def main(argv: Sequence[str] | None = None) -> int:
    args = build_parser().parse_args(argv)
    options = RunOptions(
        package=args.package.resolve(),
        mode=args.mode,
        scene=args.scene,
        speed=args.speed,
        period=args.period,
        seed=args.seed,
        host=args.host,
        rosbridge_port=args.rosbridge_port,
        viser_port=args.viser_port,
        max_sim_time=args.max_time,
        until_goal=args.until_goal,
        paused=args.paused,
        on_node_failure=args.on_node_failure,
        startup_timeout=args.startup_timeout,
        hang_timeout=args.hang_timeout,
        log_dir=args.log_dir,
        golden_seconds=args.golden_seconds,
    )
    try:
        app = SimApp(options)
    except ValueError as exc:  # e.g. an MAA_SIM_TOKEN a URL cannot carry
        print(f"maa-sim: {exc}", file=sys.stderr)
        return 2
    interrupted = threading.Event()
    received: list[str] = []

    def on_signal(signum: int, _frame: FrameType | None) -> None:
        # Only flag it: the handler runs between two bytecodes of the main thread, which may
        # hold a lock that finishing the run needs.
        received.append(signal.Signals(signum).name)
        interrupted.set()

    signal.signal(signal.SIGINT, on_signal)
    signal.signal(signal.SIGTERM, on_signal)
    try:
        app.start()
    except (DeploymentError, MessageError, ValueError, FileNotFoundError, ImportError, TypeError) as exc:
        print(f"maa-sim: {exc}", file=sys.stderr)
        return 2
    try:
        status = app.status()
        if args.status_json:
            # the token for the program that started maa-sim (the IDE backend), which presents it
            print(json.dumps({"event": "ready", **status, "token": app.token}), flush=True)
        else:
            # the URLs a person opens carry the token (viser keeps it in a cookie for its page)
            print(f"maa-sim: {options.mode} mode, scene {options.scene}", flush=True)
            if app.rosbridge is not None:
                print(f"  rosbridge  {app.rosbridge.url_with_token}", flush=True)
            if app.viewer is not None:
                print(f"  viser      {app.viewer.url_with_token}", flush=True)
            for node in status["nodes"]:
                print(f"  node       {node['name']} (pid {node['pid']}, {node['state']})", flush=True)
        while not app.wait(0.2) and not interrupted.is_set():
            pass
        assert app.runner is not None
        if interrupted.is_set():
            app.runner.finish(f"signal {received[0]}")
        reason = app.runner.finish_reason
        reached = app.session is not None and app.session.world.toast_on_plate()
        print(
            json.dumps({"event": "finished", "reason": reason, "time": app.status()["time"], "goal_reached": reached})
            if args.status_json
            else f"maa-sim: finished ({reason}) at {app.status()['time']:.2f} s; toast on the plate: {reached}",
            flush=True,
        )
    finally:
        app.stop()
    if args.until_goal:
        return 0 if reached else 1
    if interrupted.is_set():
        return 0  # a clean shutdown on request
    failed = reason.startswith("error") or (app.failed.is_set() and options.on_node_failure == "stop")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
