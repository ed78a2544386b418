"""A local Ray cluster on 127.0.0.1: a head node and worker node processes, for tests and the benchmark.

Each node is a `ray start --block` process in a session of its own; stopping the cluster ends
exactly those processes and what they started (never `ray stop`, which would end every Ray
process of the machine). The nodes share a random token (RAY_AUTH_MODE=token), so only drivers
given `env()` can use the cluster.
"""

from __future__ import annotations

import contextlib
import json
import os
import secrets
import shutil
import signal
import socket
import subprocess
import sys
import time
from dataclasses import dataclass
from pathlib import Path

#: The file in the cluster's directory that says how to reach it and which processes are its nodes.
CLUSTER_FILE = "cluster.json"


class ClusterError(Exception):
    """The cluster did not start (a node process ended, or not every node registered in time)."""


@dataclass(frozen=True)
class LocalCluster:
    directory: Path
    address: str
    token: str
    pids: tuple[int, ...]

    def env(self) -> dict[str, str]:
        """What a driver's environment needs to use this cluster."""
        return {"RAY_ADDRESS": self.address, "RAY_AUTH_MODE": "token", "RAY_AUTH_TOKEN": self.token}


def _free_port() -> int:
    with socket.socket() as probe:
        probe.bind(("127.0.0.1", 0))
        return int(probe.getsockname()[1])


def _ray() -> str:
    return str(Path(sys.executable).with_name("ray"))


def _node(args: list[str], log: Path, env: dict[str, str]) -> subprocess.Popen[bytes]:
    with log.open("wb") as out:
        return subprocess.Popen(
            [_ray(), "start", "--block", "--node-ip-address", "127.0.0.1", *args],
            stdin=subprocess.DEVNULL,
            stdout=out,
            stderr=subprocess.STDOUT,
            env=env,
            start_new_session=True,
        )


def _ports() -> list[str]:
    """Ports of a node's agents: free ones, so that several nodes fit on one machine."""
    return [
        "--dashboard-agent-listen-port",
        str(_free_port()),
        "--metrics-export-port",
        str(_free_port()),
        "--runtime-env-agent-port",
        str(_free_port()),
    ]


_PROBE = """
import sys, time, ray
ray.init(address=sys.argv[1], logging_level="ERROR", log_to_driver=False)
deadline = time.monotonic() + float(sys.argv[3])
while True:
    alive = [n for n in ray.nodes() if n.get("Alive")]
    if len(alive) >= int(sys.argv[2]) or time.monotonic() > deadline:
        break
    time.sleep(0.3)
print(len(alive))
ray.shutdown()
"""


def _wait_for_port(port: int, nodes: list[subprocess.Popen[bytes]], log: Path, timeout: float) -> None:
    deadline = time.monotonic() + timeout
    while True:
        if nodes[0].poll() is not None:
            raise ClusterError(f"the head node ended with {nodes[0].returncode}: see {log}")
        with contextlib.suppress(OSError), socket.create_connection(("127.0.0.1", port), timeout=1):
            return
        if time.monotonic() > deadline:
            raise ClusterError(f"the head node does not listen on 127.0.0.1:{port} after {timeout:g} s: see {log}")
        time.sleep(0.2)


def start_cluster(
    directory: Path, nodes: int = 2, cpus_per_node: int = 1, port: int | None = None, timeout: float = 120.0
) -> LocalCluster:
    """Starts the head and `nodes - 1` worker nodes, each a `ray start --block` process; returns once
    all of them have registered with the head (ray.nodes()); stops them again when that fails."""
    directory = directory.resolve()
    directory.mkdir(parents=True, exist_ok=True)
    port = port or _free_port()
    token = secrets.token_hex(32)
    env = {**os.environ, "RAY_AUTH_MODE": "token", "RAY_AUTH_TOKEN": token, "RAY_USAGE_STATS_ENABLED": "0"}
    env.pop("RAY_ADDRESS", None)
    cpus = ["--num-cpus", str(cpus_per_node)]
    processes = [
        _node(
            [
                "--head",
                "--port",
                str(port),
                "--include-dashboard",
                "false",
                "--disable-usage-stats",
                "--temp-dir",
                str(directory / "head"),
                *cpus,
                *_ports(),
            ],
            directory / "head.log",
            env,
        )
    ]
    cluster = LocalCluster(directory, f"127.0.0.1:{port}", token, (processes[0].pid,))
    _write(cluster)
    try:
        _wait_for_port(port, processes, directory / "head.log", timeout)
        for index in range(1, nodes):
            args = ["--address", cluster.address, "--temp-dir", str(directory / f"node{index}"), *cpus, *_ports()]
            processes.append(_node(args, directory / f"node{index}.log", env))
        cluster = LocalCluster(directory, cluster.address, token, tuple(p.pid for p in processes))
        _write(cluster)
        probe = subprocess.run(
            [sys.executable, "-c", _PROBE, cluster.address, str(nodes), str(timeout)],
            env={**env, "RAY_ADDRESS": cluster.address},
            capture_output=True,
            text=True,
            timeout=timeout + 60,
            check=False,
        )
        registered = probe.stdout.strip().splitlines()[-1] if probe.stdout.strip() else ""
        if probe.returncode != 0 or registered != str(nodes):
            names = ["the head", *(f"node {index}" for index in range(1, nodes))]
            ended = [
                f"{name} ended with {p.returncode}"
                for name, p in zip(names, processes, strict=True)
                if p.poll() is not None
            ]
            raise ClusterError(
                f"{registered or 'no'} of {nodes} nodes registered at {cluster.address}"
                f"{'; ' + ', '.join(ended) if ended else ''}; the logs are in {directory}\n{probe.stderr[-2000:]}"
            )
    except BaseException:
        stop_cluster(directory)
        raise
    return cluster


def _write(cluster: LocalCluster) -> None:
    path = cluster.directory / CLUSTER_FILE
    data = {"address": cluster.address, "token": cluster.token, "pids": list(cluster.pids)}
    path.write_text(json.dumps(data, indent=2) + "\n", encoding="utf-8")
    path.chmod(0o600)


def _session_members(sessions: set[int]) -> list[int]:
    """The processes of the given sessions (each node's `ray start` leads one; Ray's daemons and
    workers stay in it)."""
    members = []
    for entry in Path("/proc").iterdir():
        if not entry.name.isdigit():
            continue
        with contextlib.suppress(OSError, ValueError, IndexError):
            fields = (entry / "stat").read_text().rsplit(")", 1)[1].split()
            if int(fields[3]) in sessions:
                members.append(int(entry.name))
    return members


def stop_cluster(directory: Path, timeout: float = 15.0) -> None:
    """Ends the node processes of the cluster in `directory` and all they started, then removes
    Ray's directories there (the logs head.log, node*.log and cluster.json stay)."""
    directory = directory.resolve()
    try:
        pids = json.loads((directory / CLUSTER_FILE).read_text(encoding="utf-8"))["pids"]
    except (OSError, ValueError, KeyError) as error:
        raise ClusterError(f"no cluster in {directory} ({error})") from error
    sessions = {int(pid) for pid in pids}
    for pid in sessions:
        with contextlib.suppress(ProcessLookupError):
            os.kill(pid, signal.SIGTERM)
    deadline = time.monotonic() + timeout
    while _session_members(sessions) and time.monotonic() < deadline:
        time.sleep(0.2)
    for pid in _session_members(sessions):
        with contextlib.suppress(ProcessLookupError):
            os.kill(pid, signal.SIGKILL)
    for pid in sessions:  # reap the node processes when this process started them
        with contextlib.suppress(ChildProcessError, OSError):
            os.waitpid(pid, os.WNOHANG)
    for name in ["head", *(entry.name for entry in directory.glob("node*") if entry.is_dir())]:
        shutil.rmtree(directory / name, ignore_errors=True)
