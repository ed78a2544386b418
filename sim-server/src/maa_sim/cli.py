"""`maa-sim`: the command line of the simulation sidecar."""

from __future__ import annotations

import argparse
import json
import signal
import sys
import threading
import time
from collections.abc import Callable, Sequence
from pathlib import Path
from types import FrameType

from . import __version__
from .app import RunOptions, SimApp
from .deployment import DeploymentError
from .messages import MessageError
from .protocol import ScenarioReport, ScenarioWorld, SimulatorFinished, SimulatorProgress
from .scenario import (
    WorldFileError,
    failed_report,
    load_world,
    world_config,
    world_summary,
    write_report,
)
from .world import WorldConfig


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
    _add_run_options(commands)
    _add_world_options(commands.choices["run"])
    _add_output_options(commands.choices["run"])
    _add_inspect_command(commands)
    _add_replay_command(commands)
    return parser


def _add_run_options(commands: argparse._SubParsersAction[argparse.ArgumentParser]) -> None:
    """`maa-sim run`: the package, the scene and mode, the endpoints, when the run ends, node supervision."""
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
        "--viser-controls",
        choices=("on", "off"),
        default="on",
        help="the viser panel's run controls: pause, resume, step, reset, speed (default: %(default)s; "
        "the IDE turns them off, its simulate view has its own)",
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
    run.add_argument("--log-dir", type=Path, default=None, help="where node logs go (default: a temporary directory)")


def _add_world_options(run: argparse.ArgumentParser) -> None:
    """`maa-sim run`: the initial world (a scenario's world file, or single values)."""
    run.add_argument(
        "--seed", type=int, default=None, help="random seed of the scene (default: the world file's, else 0)"
    )
    run.add_argument(
        "--world",
        type=Path,
        default=None,
        metavar="FILE.json",
        help='the initial world of a scenario: {"goldenSeconds": 6, "breadJitter": 0, "seed": 0}, every field '
        "optional (--seed and --golden-seconds win over the file)",
    )
    run.add_argument(
        "--golden-seconds",
        type=_positive_float,
        default=None,
        help="seconds of toasting to reach golden toast (default: the world file's, else 6)",
    )


def _add_output_options(run: argparse.ArgumentParser) -> None:
    """`maa-sim run`: what it prints for the program that started it, and the recording."""
    run.add_argument(
        "--status-json",
        action="store_true",
        help="print one JSON line with ports and node pids once running, and one when finished",
    )
    run.add_argument(
        "--progress-json",
        action="store_true",
        help="print a JSON progress line (simulated time, real-time factor, goal) about once a second",
    )
    run.add_argument(
        "--record",
        type=Path,
        default=None,
        metavar="FILE.mcap",
        help="record every topic and the scene state into an MCAP file (ROS 2 schemas, CDR)",
    )
    run.add_argument(
        "--report",
        type=Path,
        default=None,
        metavar="FILE.json",
        help="write the scenario report (goal, events, automaton states; maa-scenario-report/1) at the end of the "
        "run, also when it fails or is interrupted",
    )


def _add_inspect_command(commands: argparse._SubParsersAction[argparse.ArgumentParser]) -> None:
    inspect = commands.add_parser(
        "inspect",
        help="what a recording holds (decodes every message)",
        description="Reads an MCAP file written by `maa-sim run --record`, decodes every message with its ROS 2 "
        "schema and prints one JSON object: the profile, the message count and per channel the topic, schema and "
        "message count. Exit 2 when the file cannot be read.",
    )
    inspect.add_argument("file", type=Path, metavar="FILE.mcap")


def _add_replay_command(commands: argparse._SubParsersAction[argparse.ArgumentParser]) -> None:
    replay = commands.add_parser(
        "replay",
        help="play a recording back (3D scene and seek service)",
        description="Serves a recording of `maa-sim run --record`: the viser 3D scene placed from the recorded "
        "scene states and a rosbridge endpoint with /sim/seek, /sim/get_status and /sim/replay_messages "
        "(docs/simulation.md). Runs until interrupted. Exit 2 when the file is no readable recording.",
    )
    replay.add_argument("file", type=Path, metavar="FILE.mcap")
    replay.add_argument("--host", default="127.0.0.1", help="address to serve on (default: %(default)s)")
    replay.add_argument(
        "--rosbridge-port", type=_port, default=9090, metavar="PORT", help="rosbridge port (default: %(default)s)"
    )
    replay.add_argument(
        "--viser-port", type=_port, default=8080, metavar="PORT|off", help="viser port (default: %(default)s)"
    )
    replay.add_argument("--status-json", action="store_true", help="print one JSON line with the endpoints once ready")


def _replay(args: argparse.Namespace) -> int:
    """`maa-sim replay`: serves the recording until SIGINT/SIGTERM."""
    from .replay import RecordingError, ReplayServer, load_recording

    if args.rosbridge_port is None:
        print("maa-sim: replay needs a rosbridge port (its seek service)", file=sys.stderr)
        return 2
    interrupted = threading.Event()
    _install_signal_handlers(interrupted, [])
    try:
        recording = load_recording(args.file)
        server = ReplayServer(recording, host=args.host, rosbridge_port=args.rosbridge_port, viser_port=args.viser_port)
        server.start()
    except (RecordingError, RuntimeError, ValueError, OSError) as exc:
        print(f"maa-sim: {exc}", file=sys.stderr)
        return 2
    try:
        line = server.ready_line()
        if args.status_json:
            print(json.dumps(line), flush=True)
        else:
            print(f"maa-sim: replaying {args.file} ({line['start']:.2f} s to {line['end']:.2f} s)", flush=True)
            print(f"  rosbridge  {server.rosbridge.url_with_token}", flush=True)
            if server.scene is not None:
                print(f"  viser      {server.scene.view.url_with_token}", flush=True)
        interrupted.wait()
    finally:
        server.stop()
    return 0


def _inspect(path: Path) -> int:
    from mcap.exceptions import McapError

    from .recorder import inspect_recording

    try:
        print(json.dumps(inspect_recording(path), indent=2))
    except (OSError, McapError, ValueError) as exc:
        print(f"maa-sim: cannot read {path}: {exc}", file=sys.stderr)
        return 2
    return 0


def _options(args: argparse.Namespace, config: WorldConfig) -> RunOptions:
    return RunOptions(
        package=args.package.resolve(),
        mode=args.mode,
        scene=args.scene,
        speed=args.speed,
        period=args.period,
        seed=config.seed,
        host=args.host,
        rosbridge_port=args.rosbridge_port,
        viser_port=args.viser_port,
        viser_controls=args.viser_controls == "on",
        max_sim_time=args.max_time,
        until_goal=args.until_goal,
        paused=args.paused,
        on_node_failure=args.on_node_failure,
        startup_timeout=args.startup_timeout,
        hang_timeout=args.hang_timeout,
        log_dir=args.log_dir,
        golden_seconds=config.golden_seconds,
        bread_jitter=config.bread_jitter,
        record=args.record.resolve() if args.record is not None else None,
        scenario=args.report is not None,
    )


def _print_ready(app: SimApp, status_json: bool) -> None:
    status = app.status()
    if status_json:
        # the token for the program that started maa-sim (the IDE backend), which presents it
        print(json.dumps({"event": "ready", **status, "token": app.token}), flush=True)
        return
    # the URLs a person opens carry the token (viser keeps it in a cookie for its page)
    print(f"maa-sim: {app.options.mode} mode, scene {app.options.scene}", flush=True)
    if app.rosbridge is not None:
        print(f"  rosbridge  {app.rosbridge.url_with_token}", flush=True)
    if app.viewer is not None:
        print(f"  viser      {app.viewer.url_with_token}", flush=True)
    for node in status["nodes"]:
        print(f"  node       {node['name']} (pid {node['pid']}, {node['state']})", flush=True)
    if app.recorder is not None:
        print(f"  recording  {app.recorder.part} (renamed to {app.recorder.path.name} at the end)", flush=True)


def progress_line(app: SimApp, wall_seconds: float) -> SimulatorProgress:
    """The `--progress-json` line (@maa/protocol SimulatorProgress)."""
    status = app.status()
    return {
        "event": "progress",
        "time": status["time"],
        "wall_seconds": wall_seconds,
        "real_time_factor": status["real_time_factor"],
        "periods": status["periods"],
        "paused": status["paused"],
        "toast_level": status["toast_level"],
        "goal_reached": status["toast_on_plate"],
        "recorded_messages": app.recorder.messages if app.recorder is not None else None,
    }


def _wait(app: SimApp, interrupted: threading.Event, progress: bool) -> None:
    """Waits for the end of the run (or a signal), printing a progress line about once a second."""
    start = time.monotonic()
    last = start
    while not app.wait(0.2) and not interrupted.is_set():
        now = time.monotonic()
        if progress and now - last >= 1.0:
            last = now
            print(json.dumps(progress_line(app, now - start)), flush=True)


def _finished_line(app: SimApp, reason: str, reached: bool, sim_time: float, wall: float) -> SimulatorFinished:
    """The `--status-json` finished line (@maa/protocol SimulatorFinished), after the recording is complete."""
    return {
        "event": "finished",
        "reason": reason,
        "time": sim_time,
        "goal_reached": reached,
        "wall_seconds": wall,
        "real_time_factor": sim_time / wall if wall > 0 else 0.0,
        "record": app.recorder.summary() if app.recorder is not None else None,
    }


def _print_finished(app: SimApp, line: SimulatorFinished, status_json: bool) -> None:
    if status_json:
        print(json.dumps(line), flush=True)
        return
    print(
        f"maa-sim: finished ({line['reason']}) at {line['time']:.2f} s; toast on the plate: {line['goal_reached']}",
        flush=True,
    )
    record = line["record"]
    if record is not None:
        print(f"maa-sim: recorded {record['messages']} messages into {record['path']}", flush=True)


def _install_signal_handlers(interrupted: threading.Event, received: list[str]) -> None:
    def on_signal(signum: int, _frame: FrameType | None) -> None:
        # Only flag it: the handler runs between two bytecodes of the main thread, which may
        # hold a lock that finishing the run needs.
        received.append(signal.Signals(signum).name)
        interrupted.set()

    signal.signal(signal.SIGINT, on_signal)
    signal.signal(signal.SIGTERM, on_signal)


def _write_report(path: Path | None, make: Callable[[], ScenarioReport]) -> None:
    """Writes the scenario report of `--report`; a report that cannot be written is said on stderr."""
    if path is None:
        return
    try:
        write_report(path, make())
    except OSError as exc:
        print(f"maa-sim: cannot write the report {path}: {exc}", file=sys.stderr)


def _scenario_report(app: SimApp, reason: str, sim_time: float) -> ScenarioReport:
    assert app.scenario is not None and app.session is not None
    error = reason if reason.startswith("error") else None
    return app.scenario.report(app.session.world, app.world_config(), reason, sim_time, error)


def _start(args: argparse.Namespace) -> SimApp | int:
    """The app, started; an exit code (2) when the world file, the package or the options are bad."""
    world: ScenarioWorld = {}
    try:
        if args.world is not None:
            world = load_world(args.world)
    except WorldFileError as exc:
        problem = str(exc)
        print(f"maa-sim: {problem}", file=sys.stderr)
        _write_report(args.report, lambda: failed_report(world, "error: bad world file", problem))
        return 2
    config = world_config(world, args.seed, args.golden_seconds)
    try:
        app = SimApp(_options(args, config))
        app.start()
    except (DeploymentError, MessageError, ValueError, FileNotFoundError, ImportError, TypeError, OSError) as exc:
        # ValueError: e.g. an MAA_SIM_TOKEN a URL cannot carry, a bad lockstep.json
        problem = str(exc)
        print(f"maa-sim: {problem}", file=sys.stderr)
        _write_report(args.report, lambda: failed_report(world_summary(config), "error: did not start", problem))
        return 2
    return app


def main(argv: Sequence[str] | None = None) -> int:
    args = build_parser().parse_args(argv)
    if args.command == "inspect":
        return _inspect(args.file)
    if args.command == "replay":
        return _replay(args)
    interrupted = threading.Event()
    received: list[str] = []
    _install_signal_handlers(interrupted, received)
    app = _start(args)
    if isinstance(app, int):
        return app
    options = app.options
    start = time.monotonic()
    reason, sim_time = "error: the run did not finish", 0.0
    try:
        _print_ready(app, args.status_json)
        _wait(app, interrupted, args.progress_json)
        assert app.runner is not None
        if interrupted.is_set():
            app.runner.finish(f"signal {received[0]}")
        reason = app.runner.finish_reason
        reached = app.session is not None and app.session.world.toast_on_plate()
        sim_time = float(app.status()["time"])
        wall = time.monotonic() - start
    finally:
        app.stop()  # completes the recording
        _write_report(args.report, lambda: _scenario_report(app, reason, sim_time))
    _print_finished(app, _finished_line(app, reason, reached, sim_time, wall), args.status_json)
    if args.until_goal:
        return 0 if reached else 1
    if interrupted.is_set():
        return 0  # a clean shutdown on request
    failed = reason.startswith("error") or (app.failed.is_set() and options.on_node_failure == "stop")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
