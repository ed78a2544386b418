"""Benchmark of record and replay (issue 19), one run, one table (no timed assertions).

    sim-server/.venv/bin/python sim-server/bench/bench_replay.py [--seconds 60]

Records a lock-step run of the example's generated timesync build (`maa-gen generate ... --platform
timesync` into a temporary folder; the fixture application when node is missing) for 60 simulated
seconds with `--record`, as the IDE's Record toggle does, then measures on that file:

- the recording's size per simulated minute (the MCAP file as the recorder writes it: CDR in zstd-compressed chunks);
- loading it for a replay (`maa_sim.replay.load_recording`: every message decoded, the scene states
  when first sought) and the size of
  the `/sim/replay_messages` answer the simulate view loads into its timeline store;
- the replay frame rate: seeks per second, each moving the viser scene to the recorded poses of
  another time (a 30 fps walk through the whole recording), called directly and over rosbridge the
  way the simulate view calls `/sim/seek` (one call at a time, each waiting for its answer).

The goals: a replay follows the time slider at >= 30 frames per second (the viser panel's own rate,
viewer.FPS) over rosbridge; a recording takes <= 20 MB per simulated minute; loading a 60 s
recording takes <= 5 s.
"""

from __future__ import annotations

import argparse
import json
import shutil
import subprocess
import sys
import tempfile
import time
from pathlib import Path

from websockets.sync.client import connect

HERE = Path(__file__).resolve().parent
REPO = HERE.parents[1]
FIXTURE_APP = HERE.parent / "tests" / "fixtures" / "toast_app"
sys.path.insert(0, str(FIXTURE_APP))

from maa_sim.app import RunOptions, SimApp  # noqa: E402
from maa_sim.replay import ReplayServer, load_recording  # noqa: E402

Row = tuple[str, str, str, str]
GOAL_FPS = 30.0
GOAL_MB_PER_MINUTE = 20.0
GOAL_LOAD_SECONDS = 5.0


def generated_timesync(out: Path) -> Path | None:
    """The example generated for the timesync platform (None without node or maa-gen)."""
    maa_gen = REPO / "packages" / "cli" / "bin" / "maa-gen.js"
    app = REPO / "examples" / "toast-service" / "TR.arcapp"
    if shutil.which("node") is None or not maa_gen.exists():
        return None
    result = subprocess.run(
        ["node", str(maa_gen), "generate", str(app), "--platform", "timesync", "--out", str(out)],
        capture_output=True,
        text=True,
        check=False,
    )
    return out / "timesync" if result.returncode == 0 else None


def record(package: Path, target: Path, seconds: float) -> float:
    """A lock-step run of `package` for `seconds` of simulated time, recorded; returns the simulated time."""
    app = SimApp(
        RunOptions(
            package=package, mode="lockstep", rosbridge_port=None, viser_port=None, max_sim_time=seconds, record=target
        )
    )
    app.start()
    try:
        app.wait(600)
        return float(app.status()["time"])
    finally:
        app.stop()


def seek_walk(recording_start: float, recording_end: float, fps: float = 30.0) -> list[float]:
    """The times a 30 fps playback of the recording visits."""
    times: list[float] = []
    t = recording_start
    while t <= recording_end:
        times.append(t)
        t += 1.0 / fps
    return times


def bench_direct(server: ReplayServer, times: list[float]) -> float:
    """Seeks per second, each moving the viser scene (ReplayScene.seek)."""
    scene = server.scene
    assert scene is not None
    started = time.perf_counter()
    for t in times:
        scene.seek(t)
    return len(times) / (time.perf_counter() - started)


def bench_rosbridge(server: ReplayServer, times: list[float]) -> tuple[float, float, int]:
    """Seeks per second over rosbridge, one call at a time; and the time and size of /sim/replay_messages."""
    assert server.rosbridge is not None
    ws = connect(
        server.rosbridge.url,
        max_size=None,
        additional_headers={"Authorization": f"Bearer {server.rosbridge.access.token}"},
    )
    try:
        started = time.perf_counter()
        ws.send(
            json.dumps(
                {"op": "call_service", "id": "m", "service": "/sim/replay_messages", "args": {"exclude": ["/clock"]}}
            )
        )
        answer = ws.recv(timeout=120)
        load_seconds = time.perf_counter() - started
        size = len(answer)
        started = time.perf_counter()
        for i, t in enumerate(times):
            ws.send(json.dumps({"op": "call_service", "id": str(i), "service": "/sim/seek", "args": {"time": t}}))
            json.loads(ws.recv(timeout=30))
        return len(times) / (time.perf_counter() - started), load_seconds, size
    finally:
        ws.close()


def _goal(met: bool, goal: str) -> str:
    return f"{goal}: {'met' if met else 'not met'}"


def print_table(rows: list[Row]) -> None:
    header: Row = ("measure", "value", "goal (issue 19)", "notes")
    widths = [max(len(r[i]) for r in (header, *rows)) for i in range(3)]
    print("  ".join(f"{h:<{w}}" for h, w in zip(header[:3], widths, strict=True)) + "  " + header[3])
    print("  ".join("-" * w for w in widths) + "  " + "-" * max(len(r[3]) for r in rows))
    for row in rows:
        print("  ".join(f"{c:<{w}}" for c, w in zip(row[:3], widths, strict=True)) + "  " + row[3])


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--seconds", type=float, default=60.0, help="simulated seconds to record (default 60)")
    args = parser.parse_args()
    work = Path(tempfile.mkdtemp(prefix="maa-bench-replay-"))
    try:
        package = generated_timesync(work / "gen")
        what = "the example's timesync build" if package is not None else "the fixture app (node missing)"
        target = work / "run.mcap"
        started = time.perf_counter()
        sim_time = record(package or FIXTURE_APP, target, args.seconds)
        record_wall = time.perf_counter() - started
        mb_per_minute = target.stat().st_size / 1e6 / (sim_time / 60.0)

        started = time.perf_counter()
        recording = load_recording(target)
        load_seconds = time.perf_counter() - started
        messages = len(recording.messages) + len(recording.scenes)

        server = ReplayServer(recording, token="bench-replay-token-0123456789abcdef")
        server.start()
        try:
            times = seek_walk(recording.start, recording.end)
            direct = bench_direct(server, times)
            over_ws, answer_seconds, answer_size = bench_rosbridge(server, times)
        finally:
            server.stop()

        rows: list[Row] = [
            (
                "recording size",
                f"{mb_per_minute:.1f} MB per simulated minute",
                _goal(mb_per_minute <= GOAL_MB_PER_MINUTE, f"<= {GOAL_MB_PER_MINUTE:.0f} MB/min"),
                f"{target.stat().st_size / 1e6:.1f} MB for {sim_time:.1f} s of {what}, {messages:,} messages, "
                f"{len(recording.topics())} topics (recorded in {record_wall:.1f} s wall)",
            ),
            (
                "load for replay",
                f"{load_seconds:.2f} s",
                _goal(load_seconds <= GOAL_LOAD_SECONDS, f"<= {GOAL_LOAD_SECONDS:.0f} s"),
                f"scene states decoded when sought; /sim/replay_messages (no /clock): {answer_size / 1e6:.1f} MB JSON "
                f"in {answer_seconds:.2f} s",
            ),
            (
                "replay frame rate, rosbridge",
                f"{over_ws:.0f} seeks/s",
                _goal(over_ws >= GOAL_FPS, f">= {GOAL_FPS:.0f} fps"),
                f"/sim/seek + viser scene update, one call at a time, {len(times)} times at 30 fps of the recording",
            ),
            (
                "replay frame rate, direct",
                f"{direct:.0f} seeks/s",
                "-",
                "ReplayScene.seek alone (the scene's frames moved in one viser atomic update)",
            ),
        ]
        print_table(rows)
    finally:
        shutil.rmtree(work, ignore_errors=True)


if __name__ == "__main__":
    main()
