"""ROS 2 mode: a real rclpy node as the simulator's transport, and the supervisor of the app's nodes.

Isolation: every session gets a ROS domain id of its own (reserved with a lock file, so that
parallel sessions on one machine never share one) and `ROS_AUTOMATIC_DISCOVERY_RANGE=LOCALHOST`
(the variable rcl of ROS 2 Kilted honours; `ROS_LOCALHOST_ONLY` is gone from it), for the
simulator and for every node it starts.
"""

from __future__ import annotations

import contextlib
import fcntl
import json
import os
import queue
import signal
import subprocess
import sys
import tempfile
import threading
import time
from collections import deque
from collections.abc import Callable
from concurrent.futures import Future
from dataclasses import dataclass, field
from pathlib import Path
from typing import IO, Any

from .deployment import Deployment, NodeSpec
from .messages import JsonMessage, MessageError, from_json, message_class, normalize_type, to_json
from .transport import MessageCallback, Subscription

DISCOVERY_ENV = {"ROS_AUTOMATIC_DISCOVERY_RANGE": "LOCALHOST"}
#: Topics whose publishers keep their last message for late subscribers (transient local): the
#: generated nodes' automaton states. The simulator subscribes to them with the same durability.
TRANSIENT_LOCAL_TOPICS = frozenset({"/maa/automaton_states"})

#: Runs a node's command so that the kernel kills it when the simulator dies without cleaning up
#: (SIGKILL, a crash): prctl(PR_SET_PDEATHSIG) survives the exec. argv: parent pid, command...
_LAUNCHER = (
    "import ctypes, os, signal, sys\n"
    "ctypes.CDLL(None, use_errno=True).prctl(1, signal.SIGKILL)\n"
    "os.getppid() == int(sys.argv[1]) or sys.exit(1)\n"
    "os.execvp(sys.argv[2], sys.argv[2:])\n"
)
#: Domain ids handed out (0 is left to whatever else runs on the machine).
DOMAIN_RANGE = range(1, 101)
_LOCK_DIR = Path(tempfile.gettempdir()) / "maa-sim-domains"
#: A domain id given from outside, used as it is: the lab's sandbox (maa_sim.sandbox, ros_domain)
#: gives each workspace its own; a sandbox's /tmp is private, so the lock files would not see others.
DOMAIN_ENV = "MAA_SIM_ROS_DOMAIN"


class DomainLease:
    """A ROS domain id reserved for this process until `release()` (or its exit)."""

    def __init__(self) -> None:
        given = os.environ.get(DOMAIN_ENV, "")
        if given:
            if not given.isdigit() or not 0 <= int(given) <= 232:
                raise RuntimeError(f"{DOMAIN_ENV}={given!r} is not a ROS domain id (0..232)")
            self.domain_id = int(given)
            self._handle: IO[str] | None = None
            return
        _LOCK_DIR.mkdir(parents=True, exist_ok=True)
        start = (os.getpid() * 7919 + time.monotonic_ns()) % len(DOMAIN_RANGE)
        for i in range(len(DOMAIN_RANGE)):
            domain = DOMAIN_RANGE[(start + i) % len(DOMAIN_RANGE)]
            handle = (_LOCK_DIR / f"{domain}.lock").open("a")
            try:
                fcntl.flock(handle, fcntl.LOCK_EX | fcntl.LOCK_NB)
            except OSError:
                handle.close()
                continue
            self.domain_id = domain
            self._handle = handle
            return
        raise RuntimeError("no free ROS domain id (every one of 1..100 is in use on this machine)")

    def release(self) -> None:
        if self._handle is not None:
            fcntl.flock(self._handle, fcntl.LOCK_UN)
            self._handle.close()
            self._handle = None


class RosTransport:
    """The simulator's rclpy node: publishes and subscribes topics in JSON form."""

    def __init__(self, domain_id: int, node_name: str = "maa_sim") -> None:
        import rclpy
        from rclpy.executors import SingleThreadedExecutor
        from rclpy.node import Node

        for key, value in DISCOVERY_ENV.items():
            os.environ[key] = value
        self._rclpy = rclpy
        self.context = rclpy.Context()
        rclpy.init(context=self.context, domain_id=domain_id)
        self.node = Node(node_name, context=self.context)
        self.executor = SingleThreadedExecutor(context=self.context)
        self.executor.add_node(self.node)
        self._lock = threading.RLock()
        self._publishers: dict[str, tuple[str, Any]] = {}
        self._subscriptions: dict[str, tuple[str, Any, list[Subscription]]] = {}
        self._thread = threading.Thread(target=self._spin, name="maa-sim-ros", daemon=True)
        self._thread.start()

    def _spin(self) -> None:
        from rclpy.executors import ExternalShutdownException

        with contextlib.suppress(ExternalShutdownException, RuntimeError):
            while self.context.ok():
                self.executor.spin_once(timeout_sec=0.1)

    def close(self) -> None:
        with contextlib.suppress(Exception):
            self.executor.shutdown(timeout_sec=1.0)
        with contextlib.suppress(Exception):
            self.node.destroy_node()
        with contextlib.suppress(Exception):
            self._rclpy.shutdown(context=self.context)
        self._thread.join(timeout=2)

    # ----------------------------------------------------------------------------- Transport

    def topics(self) -> list[tuple[str, str]]:
        found: dict[str, str] = {}
        for name, types in self.node.get_topic_names_and_types():
            if types:
                found[name] = types[0]
        with self._lock:
            for name, (type_name, _) in self._publishers.items():
                found.setdefault(name, type_name)
            for name, (type_name, _, _) in self._subscriptions.items():
                found.setdefault(name, type_name)
        return sorted(found.items())

    def topic_type(self, topic: str) -> str | None:
        with self._lock:
            if topic in self._publishers:
                return self._publishers[topic][0]
            if topic in self._subscriptions:
                return self._subscriptions[topic][0]
        for name, types in self.node.get_topic_names_and_types():
            if name == topic and types:
                return str(types[0])
        return None

    def advertise(self, topic: str, type_name: str) -> None:
        normalized = normalize_type(type_name)
        with self._lock:
            existing = self._publishers.get(topic)
            if existing is not None:
                if existing[0] != normalized:
                    raise MessageError(f"{topic} is advertised with type {existing[0]}, not {normalized}")
                return
            known = self.topic_type(topic)
            if known is not None and known != normalized:
                raise MessageError(f"{topic} has type {known}, not {normalized}")
            cls = message_class(normalized)
            try:
                publisher = self.node.create_publisher(cls, topic, 10)
            except Exception as exc:  # noqa: BLE001 - rclpy raises several kinds for bad names
                raise MessageError(f"cannot advertise {topic}: {exc}") from None
            self._publishers[topic] = (normalized, publisher)

    def publish(self, topic: str, msg: JsonMessage) -> None:
        with self._lock:
            entry = self._publishers.get(topic)
        if entry is None:
            type_name = self.topic_type(topic)
            if type_name is None:
                raise MessageError(f"{topic} has no type: advertise it first")
            self.advertise(topic, type_name)
            with self._lock:
                entry = self._publishers[topic]
        type_name, publisher = entry
        publisher.publish(from_json(type_name, msg))

    def subscribe(self, topic: str, type_name: str | None, callback: MessageCallback) -> Subscription:
        with self._lock:
            existing = self._subscriptions.get(topic)
            normalized = normalize_type(type_name) if type_name else None
            if existing is not None:
                if normalized and normalized != existing[0]:
                    raise MessageError(f"{topic} has type {existing[0]}, not {normalized}")
                sub = Subscription(topic, callback)
                existing[2].append(sub)
                return sub
            if normalized is None:
                normalized = self.topic_type(topic)
                if normalized is None:
                    raise MessageError(f"the type of {topic} is unknown: give it in the subscribe request")
            cls = message_class(normalized)
            subs: list[Subscription] = []

            def on_message(msg: Any, topic: str = topic, subs: list[Subscription] = subs) -> None:
                if not subs:
                    return
                data = to_json(msg)
                for s in list(subs):
                    s.callback(topic, data)

            qos: Any = 10
            if topic in TRANSIENT_LOCAL_TOPICS:
                from rclpy.qos import DurabilityPolicy, QoSProfile

                qos = QoSProfile(depth=10, durability=DurabilityPolicy.TRANSIENT_LOCAL)
            try:
                ros_sub = self.node.create_subscription(cls, topic, on_message, qos)
            except Exception as exc:  # noqa: BLE001
                raise MessageError(f"cannot subscribe to {topic}: {exc}") from None
            sub = Subscription(topic, callback)
            subs.append(sub)
            self._subscriptions[topic] = (normalized, ros_sub, subs)
            return sub

    def unsubscribe(self, subscription: Subscription) -> None:
        with self._lock:
            entry = self._subscriptions.get(subscription.topic)
            if entry is None:
                return
            subs = entry[2]
            if subscription in subs:
                subs.remove(subscription)
            # The rclpy subscription stays: the simulator's own topics are subscribed for good,
            # and re-creating subscriptions per client is not worth the discovery churn.

    def nodes(self) -> list[str]:
        result = []
        for name, namespace in self.node.get_node_names_and_namespaces():
            result.append(f"{namespace.rstrip('/')}/{name}")
        return sorted(result)

    # ----------------------------------------------------------------------------- liveness

    def probe(self, fqn: str) -> Any:
        """Starts a liveness probe of a node (its list_parameters service); returns a future."""
        from rcl_interfaces.srv import ListParameters

        client = self._probe_client(fqn)
        if not client.service_is_ready():
            return None
        request = ListParameters.Request()
        request.depth = 1
        request.prefixes = ["use_sim_time"]
        return client.call_async(request)

    def forget_probe(self, fqn: str, future: Any) -> None:
        """Stops waiting for the answer to a probe (the node lost it, or a newer probe answered)."""
        self._probe_client(fqn).remove_pending_request(future)

    def _probe_client(self, fqn: str) -> Any:
        from rcl_interfaces.srv import ListParameters

        with self._lock:
            clients: dict[str, Any] = self.__dict__.setdefault("_probe_clients", {})
            client = clients.get(fqn)
            if client is None:
                client = self.node.create_client(ListParameters, f"{fqn}/list_parameters")
                clients[fqn] = client
            return client


@dataclass
class NodeProcess:
    spec: NodeSpec
    process: subprocess.Popen[bytes]
    log_path: Path
    state: str = "starting"
    returncode: int | None = None
    started: float = field(default_factory=time.monotonic)
    last_alive: float | None = None
    #: the probes sent since the last answer (futures), oldest first
    probes: list[Any] = field(default_factory=list)
    #: when the oldest of them was sent
    unanswered_since: float = 0.0
    #: when the newest of them was sent
    probe_sent: float = 0.0
    output: deque[str] = field(default_factory=lambda: deque(maxlen=40))
    readers: list[threading.Thread] = field(default_factory=list)

    def tail(self, lines: int = 20) -> str:
        return "\n".join(list(self.output)[-lines:])

    def as_json(self) -> JsonMessage:
        return {
            "name": self.spec.fqn,
            "component": self.spec.component,
            "instance": self.spec.instance,
            "pid": self.process.pid,
            "state": self.state,
            "returncode": self.returncode,
            "log": str(self.log_path),
        }


Reporter = Callable[[str, str, str, dict[str, Any]], None]


class NodeSupervisor:
    """Starts the deployment's nodes as processes, watches them, stops them all."""

    def __init__(
        self,
        deployment: Deployment,
        domain_id: int,
        transport: RosTransport,
        report: Reporter,
        log_dir: Path,
        startup_timeout: float = 30.0,
        hang_timeout: float = 5.0,
        probe_interval: float = 1.0,
        on_failure: Callable[[NodeProcess], None] | None = None,
    ) -> None:
        self.deployment = deployment
        self.domain_id = domain_id
        self.transport = transport
        self.report = report
        self.log_dir = log_dir
        self.startup_timeout = startup_timeout
        self.hang_timeout = hang_timeout
        self.probe_interval = probe_interval
        self.on_failure = on_failure
        self.processes: list[NodeProcess] = []
        self.generation = 0  # how often the nodes were (re)started
        self._stopping = threading.Event()
        self._monitor: threading.Thread | None = None
        self._lock = threading.Lock()
        self._spawner = _Spawner()
        #: set when the session ends: a `wait_ready` (of a reset) gives up at once
        self.closing = threading.Event()

    def environment(self) -> dict[str, str]:
        env = dict(os.environ)
        env.update(self.deployment.env)
        env["ROS_DOMAIN_ID"] = str(self.domain_id)
        env.update(DISCOVERY_ENV)
        env.pop("ROS_LOCALHOST_ONLY", None)
        env.pop("ROS_STATIC_PEERS", None)
        env["PYTHONUNBUFFERED"] = "1"
        env["RCUTILS_COLORIZED_OUTPUT"] = "0"
        paths = [str(p) for p in self.deployment.python_path]
        if env.get("PYTHONPATH"):
            paths.append(env["PYTHONPATH"])
        env["PYTHONPATH"] = os.pathsep.join(paths)
        return env

    def command(self, spec: NodeSpec, params_file: Path) -> list[str]:
        if spec.module is not None:
            cmd = [sys.executable, "-m", spec.module]
        else:
            assert spec.executable is not None
            exe = Path(spec.executable)
            if not exe.is_absolute() and (self.deployment.directory / exe).exists():
                exe = self.deployment.directory / exe
            cmd = [str(exe)]
        ros_args = ["--ros-args", "-r", f"__node:={spec.name}", "-r", f"__ns:={spec.namespace}"]
        ros_args += ["-p", "use_sim_time:=true", "--params-file", str(params_file)]
        full = [*cmd, *spec.args, *ros_args]
        if sys.platform == "linux":
            return [sys.executable, "-c", _LAUNCHER, str(os.getpid()), *full]
        return full

    def start(self) -> None:
        self.log_dir.mkdir(parents=True, exist_ok=True)
        self.generation += 1
        env = self.environment()
        for spec in self.deployment.nodes:
            safe = spec.fqn.strip("/").replace("/", "__")
            params_file = self.log_dir / f"{safe}.params.yaml"
            # JSON is YAML: rcl's parameter file parser reads this as is.
            params = {spec.fqn: {"ros__parameters": spec.parameters}}
            params_file.write_text(json.dumps(params, indent=1), encoding="utf-8")
            log_path = self.log_dir / f"{safe}.log"
            if self.generation > 1:
                with log_path.open("a", encoding="utf-8") as log:
                    log.write(f"--- restart {self.generation - 1} (simulation reset)\n")
            process = self._spawner.popen(
                self.command(spec, params_file),
                cwd=self.deployment.directory,
                env=env,
                stdin=subprocess.DEVNULL,
                stdout=subprocess.PIPE,
                stderr=subprocess.PIPE,
                start_new_session=True,
            )
            node = NodeProcess(spec, process, log_path)
            log = log_path.open("a", encoding="utf-8", errors="replace")
            for stream in (process.stdout, process.stderr):
                assert stream is not None
                reader = threading.Thread(target=self._read, args=(node, stream, log), daemon=True)
                reader.start()
                node.readers.append(reader)
            self.processes.append(node)
            self.report("info", spec.fqn, f"started (pid {process.pid})", {"pid": process.pid})
        self._monitor = threading.Thread(target=self._watch, name="maa-sim-supervisor", daemon=True)
        self._monitor.start()

    @staticmethod
    def _read(node: NodeProcess, stream: IO[bytes], log: IO[str]) -> None:
        with contextlib.suppress(ValueError, OSError):
            for raw in iter(stream.readline, b""):
                line = raw.decode("utf-8", errors="replace").rstrip("\n")
                node.output.append(line)
                log.write(line + "\n")
                log.flush()

    def ready(self) -> bool:
        """Every node has answered a liveness probe at least once."""
        return all(p.last_alive is not None for p in self.processes)

    def wait_ready(self, timeout: float) -> bool:
        deadline = time.monotonic() + timeout
        while time.monotonic() < deadline and not self.closing.is_set():
            if self.ready():
                return True
            if all(p.state not in ("starting", "running") for p in self.processes):
                return False
            time.sleep(0.05)
        return self.ready()

    def _fail(self, node: NodeProcess, state: str, message: str) -> None:
        node.state = state
        details = {"pid": node.process.pid, "returncode": node.returncode, "stderr_tail": node.tail()}
        self.report("error", node.spec.fqn, message, details)
        if self.on_failure is not None:
            self.on_failure(node)

    def _watch(self) -> None:
        while not self._stopping.wait(0.1):
            now = time.monotonic()
            for node in list(self.processes):
                if node.state not in ("starting", "running"):
                    continue
                code = node.process.poll()
                if code is not None:
                    node.returncode = code
                    for reader in node.readers:
                        reader.join(timeout=1)
                    if self._stopping.is_set():
                        break
                    if code == 0:
                        self._fail(node, "exited", f"node {node.spec.fqn} exited (code 0)")
                    else:
                        self._fail(node, "crashed", f"node {node.spec.fqn} crashed (exit code {code})")
                    continue
                self._check_alive(node, now)

    def _check_alive(self, node: NodeProcess, now: float) -> None:
        """Probes a node every ``probe_interval`` s; it hangs when no probe is answered for ``hang_timeout`` s.

        A probe unanswered after ``probe_interval`` is followed by another one rather than waited
        for: a node can lose a response for good. Fast DDS gives a service 100 ms to match a new
        client's response reader and rclpy then drops the response with a RuntimeWarning ("client
        will not receive response"); on a loaded machine that happens to the first probe of a
        healthy node. Any answer counts, also a late one to an earlier probe.
        """
        if any(probe.done() for probe in node.probes):
            for probe in node.probes:
                if not probe.done():
                    self.transport.forget_probe(node.spec.fqn, probe)
            node.probes.clear()
            node.last_alive = now
            if node.state == "starting":
                node.state = "running"
                self.report("info", node.spec.fqn, "running", {})
        elif node.probes and now - node.unanswered_since > self.hang_timeout:
            self._hung(node, f"node {node.spec.fqn} hangs: no answer to a liveness probe for {self.hang_timeout:g} s")
            return
        if node.state == "starting" and now - node.started > self.startup_timeout:
            self._hung(node, f"node {node.spec.fqn} did not come up within {self.startup_timeout:g} s")
            return
        since = node.probe_sent if node.probes else (node.last_alive or 0.0)
        if now - since >= self.probe_interval:
            future = self.transport.probe(node.spec.fqn)
            if future is not None:
                if not node.probes:
                    node.unanswered_since = now
                node.probes.append(future)
                node.probe_sent = now

    def _hung(self, node: NodeProcess, message: str) -> None:
        for probe in node.probes:
            self.transport.forget_probe(node.spec.fqn, probe)
        node.probes.clear()
        _kill_group(node.process, signal.SIGKILL)
        with contextlib.suppress(subprocess.TimeoutExpired):
            node.process.wait(timeout=2)
        node.returncode = node.process.returncode
        for reader in node.readers:
            reader.join(timeout=1)
        self._fail(node, "hung", message + " (killed)")

    def statuses(self) -> list[JsonMessage]:
        return [p.as_json() for p in self.processes]

    def restart(self, grace: float = 3.0, gone_timeout: float = 10.0) -> None:
        """Stops every node (as `stop`) and starts the deployment again: fresh processes, fresh state.

        Waits (at most ``gone_timeout`` s) until the old nodes have left the ROS graph, so that a
        liveness probe cannot reach an old node and the new ones do not share names with ghosts.
        """
        old = {p.spec.fqn for p in self.processes}
        self._stop_nodes(grace)
        deadline = time.monotonic() + gone_timeout
        while time.monotonic() < deadline and old & set(self.transport.nodes()):
            time.sleep(0.05)
        self._stopping.clear()
        self.processes = []
        self.start()

    def close(self) -> None:
        """`stop`, and ends the thread that started the nodes."""
        self.closing.set()
        self.stop()
        self._spawner.close()

    def stop(self, grace: float = 3.0) -> None:
        """SIGINT to every node's process group, SIGKILL after the grace period, then reap."""
        self._stop_nodes(grace)

    def _stop_nodes(self, grace: float) -> None:
        self._stopping.set()
        if self._monitor is not None:
            self._monitor.join(timeout=2)
        alive = [p for p in self.processes if p.process.poll() is None]
        for p in alive:
            _kill_group(p.process, signal.SIGINT)
        deadline = time.monotonic() + grace
        for p in alive:
            with contextlib.suppress(subprocess.TimeoutExpired):
                p.process.wait(timeout=max(0.0, deadline - time.monotonic()))
        for p in self.processes:
            # the group too: a node may have started children of its own
            _kill_group(p.process, signal.SIGKILL)
            with contextlib.suppress(subprocess.TimeoutExpired):
                p.process.wait(timeout=2)
            if p.state in ("starting", "running"):
                p.state = "stopped"
                p.returncode = p.process.returncode
            for stream in (p.process.stdout, p.process.stderr):
                if stream is not None:
                    with contextlib.suppress(OSError):
                        stream.close()


class _Spawner:
    """The one thread that starts every node process of a supervisor, for the supervisor's lifetime.

    The kernel's parent-death signal (``PR_SET_PDEATHSIG``, set by `_LAUNCHER`) follows the *thread*
    that forked the child: nodes started from a short-lived thread (a rosbridge service worker
    restarting them on a reset) would be killed when that thread ends. Starting them all here
    ties them to this thread, which lives until `close()`.
    """

    def __init__(self) -> None:
        self._requests: queue.Queue[tuple[Callable[[], Any], Future[Any]] | None] = queue.Queue()
        self._thread = threading.Thread(target=self._run, name="maa-sim-spawner", daemon=True)
        self._thread.start()

    def _run(self) -> None:
        while True:
            item = self._requests.get()
            if item is None:
                return
            call, future = item
            try:
                future.set_result(call())
            except BaseException as exc:  # noqa: BLE001 - handed to the caller
                future.set_exception(exc)

    def popen(self, cmd: list[str], **kwargs: Any) -> subprocess.Popen[bytes]:
        if threading.current_thread() is self._thread or not self._thread.is_alive():
            return subprocess.Popen(cmd, **kwargs)
        future: Future[subprocess.Popen[bytes]] = Future()
        self._requests.put((lambda: subprocess.Popen(cmd, **kwargs), future))
        return future.result()

    def close(self) -> None:
        self._requests.put(None)


def _kill_group(process: subprocess.Popen[bytes], sig: signal.Signals) -> None:
    with contextlib.suppress(ProcessLookupError, PermissionError):
        os.killpg(process.pid, sig)
