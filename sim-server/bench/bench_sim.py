"""Benchmark of the simulation sidecar, one run, one table (no timed assertions).

    sim-server/.venv/bin/python sim-server/bench/bench_sim.py [--quick]

Measures: raw MuJoCo steps per second for the toast kitchen (bare mj_step, and the world's
step with its joint references and toasting), lock-step steps per second with the fixture
application (ratio to raw), the real-time factor ROS 2 mode achieves with real rclpy nodes (as
fast as possible) and its pacing jitter at speed 1, and rosbridge message latency (median, p95).
Until the generated ToastServiceRobot exists, the application is the hand-written fixture in
tests/fixtures/toast_app (the same behaviour, as lock-step controller and as rclpy nodes).
"""

from __future__ import annotations

import argparse
import json
import statistics
import sys
import time
from pathlib import Path

import mujoco
import numpy as np

HERE = Path(__file__).resolve().parent
TOAST_APP = HERE.parent / "tests" / "fixtures" / "toast_app"
sys.path.insert(0, str(TOAST_APP))

from toast_app.lockstep import create_controller  # noqa: E402
from websockets.sync.client import connect  # noqa: E402

from maa_sim.app import RunOptions, SimApp  # noqa: E402
from maa_sim.rosbridge import RosbridgeServer  # noqa: E402
from maa_sim.runs import run_lockstep  # noqa: E402
from maa_sim.transport import LocalBus  # noqa: E402
from maa_sim.world import ToastKitchen  # noqa: E402

Row = tuple[str, str, str]


def bench_raw(steps: int) -> tuple[float, float]:
    world = ToastKitchen()
    m, d = world.model, world.data
    start = time.perf_counter()
    for _ in range(steps):
        mujoco.mj_step(m, d)
    bare = steps / (time.perf_counter() - start)
    world.reset()
    start = time.perf_counter()
    world.step(steps)
    stepped = steps / (time.perf_counter() - start)
    return bare, stepped


def bench_lockstep(runs: int) -> tuple[float, float, bool]:
    rates, sim_times, reached = [], [], True
    for _ in range(runs):
        result = run_lockstep(create_controller({}), max_sim_time=40.0)
        steps = result.periods * round(0.02 / 0.002)
        rates.append(steps / result.wall_seconds)
        sim_times.append(result.sim_time)
        reached = reached and result.goal_reached
    return statistics.median(rates), statistics.median(sim_times), reached


def bench_ros2(seconds: float) -> dict[str, float]:
    results: dict[str, float] = {}
    for label, speed in (("max", 0.0), ("1x", 1.0)):
        app = SimApp(RunOptions(package=TOAST_APP, mode="ros2", speed=speed, rosbridge_port=None, viser_port=None))
        app.start()
        try:
            assert app.runner is not None and app.session is not None
            start_wall, start_sim = time.perf_counter(), app.session.clock
            app.runner.lateness.clear()
            time.sleep(seconds)
            wall, sim = time.perf_counter() - start_wall, app.session.clock - start_sim
            results[f"rtf_{label}"] = sim / wall
            goal_sim = app.session.world.toast_level
            results[f"toast_level_{label}"] = goal_sim
            if speed > 0:
                late = np.array(app.runner.lateness) * 1000.0
                results["late_p50_ms"] = float(np.percentile(late, 50))
                results["late_p95_ms"] = float(np.percentile(late, 95))
                results["late_max_ms"] = float(np.max(late))
        finally:
            app.stop()
    return results


def bench_rosbridge(messages: int) -> tuple[float, float, float, float]:
    bus = LocalBus()
    bus.declare("/sensors/distance", "std_msgs/msg/Int32")
    server = RosbridgeServer(bus, port=0)
    server.start()
    try:
        with connect(server.url) as ws:
            # client -> server -> client: publish on a topic the same client subscribes to
            ws.send(json.dumps({"op": "subscribe", "topic": "/bench", "type": "std_msgs/msg/Int32"}))
            ws.send(json.dumps({"op": "advertise", "topic": "/bench", "type": "std_msgs/msg/Int32"}))
            ws.send(json.dumps({"op": "subscribe", "topic": "/sensors/distance"}))
            time.sleep(0.2)
            round_trip = []
            for i in range(messages):
                start = time.perf_counter()
                ws.send(json.dumps({"op": "publish", "topic": "/bench", "msg": {"data": i}}))
                while json.loads(ws.recv(timeout=5)).get("topic") != "/bench":
                    pass
                round_trip.append((time.perf_counter() - start) * 1000)
            # simulator -> client: a sensor message delivered on the bus until the client has it
            one_way = []
            for i in range(messages):
                start = time.perf_counter()
                bus.deliver("/sensors/distance", {"data": i})
                while json.loads(ws.recv(timeout=5)).get("topic") != "/sensors/distance":
                    pass
                one_way.append((time.perf_counter() - start) * 1000)
    finally:
        server.stop()
    rt, ow = np.array(round_trip), np.array(one_way)
    return (
        float(np.median(rt)),
        float(np.percentile(rt, 95)),
        float(np.median(ow)),
        float(np.percentile(ow, 95)),
    )


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--quick", action="store_true", help="fewer steps and shorter runs")
    args = parser.parse_args()
    steps = 5_000 if args.quick else 30_000
    rows: list[Row] = []

    bare, stepped = bench_raw(steps)
    rows.append(("raw MuJoCo (mj_step)", f"{bare:,.0f} steps/s", f"{bare * 0.002:,.0f}x real time (dt 2 ms)"))
    rows.append(("world.step (refs, toasting)", f"{stepped:,.0f} steps/s", f"{stepped / bare:.2f} of raw"))

    rate, sim_time, reached = bench_lockstep(1 if args.quick else 3)
    rows.append(
        (
            "lock-step, fixture app",
            f"{rate:,.0f} steps/s",
            f"{rate / bare:.2f} of raw; {rate * 0.002:,.0f}x real time; goal at {sim_time:.2f} s sim: {reached}",
        )
    )

    ros = bench_ros2(3.0 if args.quick else 8.0)
    rows.append(("ROS 2 mode, as fast as possible", f"RTF {ros['rtf_max']:.2f}", "2 rclpy nodes, /clock every 20 ms"))
    rows.append(("ROS 2 mode, speed 1", f"RTF {ros['rtf_1x']:.3f}", "achieved real-time factor"))
    rows.append(
        (
            "ROS 2 mode, speed 1, jitter",
            f"p50 {ros['late_p50_ms']:.2f} ms",
            f"p95 {ros['late_p95_ms']:.2f} ms, max {ros['late_max_ms']:.2f} ms (lateness of period ends)",
        )
    )

    rt50, rt95, ow50, ow95 = bench_rosbridge(200 if args.quick else 1000)
    rows.append(("rosbridge round trip", f"median {rt50:.3f} ms", f"p95 {rt95:.3f} ms (client publish -> client)"))
    rows.append(("rosbridge sim -> client", f"median {ow50:.3f} ms", f"p95 {ow95:.3f} ms (bus message -> client)"))

    widths = [max(len(r[i]) for r in rows) for i in range(3)]
    print(f"{'measure':<{widths[0]}}  {'value':<{widths[1]}}  notes")
    print(f"{'-' * widths[0]}  {'-' * widths[1]}  {'-' * widths[2]}")
    for name, value, note in rows:
        print(f"{name:<{widths[0]}}  {value:<{widths[1]}}  {note}")


if __name__ == "__main__":
    main()
