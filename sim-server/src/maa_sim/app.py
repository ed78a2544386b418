"""One simulation session with everything around it: what `maa-sim run` starts.

`SimApp.start()` builds the world, the transport (a real rclpy node in ROS 2 mode, the local
bus in lock-step mode), starts the application (node processes or the in-process controller),
the rosbridge endpoint and the viser panel, then the loop. `stop()` takes it all down again,
every child process included.
"""

from __future__ import annotations

import contextlib
import json
import shutil
import sys
import tempfile
import threading
from dataclasses import dataclass
from pathlib import Path
from typing import Any, Literal

from . import interface
from .access import AccessPolicy, resolve_token
from .breakpoints import TRANSITIONS_TOPIC, Breakpoints, check_request, unresolved
from .deployment import Deployment
from .lockstep import LockstepPackage
from .messages import JsonMessage, MessageError
from .rosbridge import BlockingService, RosbridgeServer, ServiceError, ServiceHandler
from .runs import lockstep_session
from .scenario import STATES_TOPIC, ScenarioObserver
from .session import DEFAULT_PERIOD, Runner, SimEvent, SimSession
from .transport import LocalBus
from .world import ToastKitchen, WorldConfig

Mode = Literal["ros2", "lockstep"]


@dataclass
class RunOptions:
    package: Path
    mode: Mode = "ros2"
    scene: str = "toast_kitchen"
    speed: float | None = None  # None: 1.0 in ROS 2 mode, 0 (as fast as possible) in lock-step mode
    period: float | None = None
    seed: int = 0
    host: str = "127.0.0.1"
    rosbridge_port: int | None = 9090  # None: no rosbridge endpoint
    viser_port: int | None = 8080  # None: no viser panel
    #: the viser panel's own run controls (pause, resume, step, reset, speed); off when the IDE drives the run
    viser_controls: bool = True
    max_sim_time: float | None = None
    until_goal: bool = False
    paused: bool = False
    on_node_failure: Literal["continue", "stop"] = "continue"
    startup_timeout: float = 30.0
    hang_timeout: float = 5.0
    log_dir: Path | None = None
    golden_seconds: float = WorldConfig.golden_seconds
    #: standard deviation of the bread's start position (m), drawn from the seed (maa_sim.scenario)
    bread_jitter: float = WorldConfig.bread_jitter
    #: observe the run for a scenario report (maa_sim.scenario.ScenarioObserver, `maa-sim run --report`)
    scenario: bool = False
    #: the secret of the rosbridge and viser endpoints (None: MAA_SIM_TOKEN, else a random one)
    token: str | None = None
    #: an MCAP file of every topic and the scene state (maa_sim.recorder), None: no recording
    record: Path | None = None


class SimApp:
    def __init__(self, options: RunOptions) -> None:
        self.options = options
        self.session: SimSession | None = None
        self.runner: Runner | None = None
        self.rosbridge: RosbridgeServer | None = None
        self.viewer: Any = None
        self.supervisor: Any = None
        self.transport: Any = None
        self.lease: Any = None
        self.deployment: Deployment | None = None
        self.recorder: Any = None  # a maa_sim.recorder.McapRecorder with --record
        #: the events and state changes of the run, with RunOptions.scenario
        self.scenario: ScenarioObserver | None = None
        self._controller: Any = None
        self.domain_id: int | None = None
        self.log_dir: Path | None = None
        self._own_log_dir = False
        self._stopped = threading.Event()
        self._reset_lock = threading.Lock()
        self._port_topics: set[str] = set()
        #: the latest state of every automaton by node name (from /maa/automaton_states)
        self.automaton_states: dict[str, str] = {}
        self._states_lock = threading.Lock()
        self.failed = threading.Event()
        #: the token both endpoints require (maa_sim.access)
        self.token = resolve_token(options.token)
        #: the breakpoints of a lock-step run (maa_sim.breakpoints); None in ROS 2 mode
        self.breakpoints: Breakpoints | None = None

    # ----------------------------------------------------------------------------- start

    def start(self) -> None:
        try:
            if self.options.mode == "lockstep":
                self._start_lockstep()
            else:
                self._start_ros2()
            assert self.session is not None and self.runner is not None
            self.session.event_listeners.append(self._on_event)
            self._watch_states()
            self._watch_breakpoints()
            if self.options.scenario:
                self._observe_scenario()
            if self.options.record is not None:
                self._start_recording(self.options.record)
            if self.options.rosbridge_port is not None:
                self.rosbridge = RosbridgeServer(
                    self.session.transport,
                    host=self.options.host,
                    port=self.options.rosbridge_port,
                    services=self.control_services(),
                    on_publish=self._on_client_publish if self.options.mode == "lockstep" else None,
                    latched=self._latched,
                    access=self._access(),
                    check_publish=interface.check_client_message,
                )
                self.rosbridge.start()
            if self.options.viser_port is not None:
                from .viewer import SceneView

                self.viewer = SceneView(
                    self.runner,
                    host=self.options.host,
                    port=self.options.viser_port,
                    access=self._access(),
                    controls=self.options.viser_controls,
                    actions=self.control_services(),
                )
                self.viewer.start()
            if self.options.paused:
                self.runner.pause()
            self.runner.start()
        except BaseException:
            self.stop()
            raise

    def _access(self) -> AccessPolicy:
        """One policy per endpoint (each knows its own port, for its cookie), one token for both."""
        return AccessPolicy(self.token, bind_host=self.options.host)

    def world_config(self) -> WorldConfig:
        """The initial world of the run (seed, toasting speed, bread jitter)."""
        options = self.options
        return WorldConfig(golden_seconds=options.golden_seconds, bread_jitter=options.bread_jitter, seed=options.seed)

    def _world(self) -> ToastKitchen:
        return ToastKitchen(self.options.scene, self.world_config())

    def _observe_scenario(self) -> None:
        """Watches the run for `maa-sim run --report`; a lock-step controller tells its initial states."""
        assert self.session is not None
        self.scenario = ScenarioObserver()
        states = getattr(self._controller, "states", None)
        initial = states() if callable(states) else None
        self.scenario.attach(self.session, initial if isinstance(initial, dict) else None)

    def _start_lockstep(self) -> None:
        package = LockstepPackage.load(self.options.package)
        controller = self._controller = package.create()
        topics = getattr(controller, "topics", None)
        if callable(topics) and callable(getattr(controller, "validate_input", None)):
            # a generated timesync build: it shows the inputs it is fed in the slice that reads them
            self._port_topics = set(dict(topics()).keys())
        period = self.options.period or package.period or DEFAULT_PERIOD
        session, _ = lockstep_session(controller, period=period, scene=self.options.scene, config=self.world_config())
        self.session = session
        self.transport = session.transport
        speed = 0.0 if self.options.speed is None else self.options.speed
        self.runner = Runner(
            session,
            speed=speed,
            controller=controller,
            stop_when=self._goal if self.options.until_goal else None,
            max_sim_time=self.options.max_sim_time,
        )

    def _start_ros2(self) -> None:
        from .ros2 import DomainLease, NodeSupervisor, RosTransport

        deployment = self.deployment = Deployment.load(self.options.package)
        for entry in reversed(deployment.python_path):
            if str(entry) not in sys.path:
                sys.path.insert(0, str(entry))  # custom message packages of the application
        self.lease = DomainLease()
        self.domain_id = self.lease.domain_id
        self.transport = RosTransport(self.domain_id)
        period = self.options.period or DEFAULT_PERIOD
        self.session = SimSession(self._world(), self.transport, period)
        speed = 1.0 if self.options.speed is None else self.options.speed
        self.runner = Runner(
            self.session,
            speed=speed,
            stop_when=self._goal if self.options.until_goal else None,
            max_sim_time=self.options.max_sim_time,
        )
        if self.options.log_dir is not None:
            self.log_dir = self.options.log_dir
        else:
            self.log_dir = Path(tempfile.mkdtemp(prefix="maa-sim-"))
            self._own_log_dir = True
        self.supervisor = NodeSupervisor(
            deployment,
            self.domain_id,
            self.transport,
            report=self._report_node,
            log_dir=self.log_dir,
            startup_timeout=self.options.startup_timeout,
            hang_timeout=self.options.hang_timeout,
            on_failure=self._on_node_failure,
        )
        self._keep_last_values(deployment)
        # The clock starts once every node answers (so no node misses the first commands).
        self.session.publish(self.session.observe())
        self.supervisor.start()
        if not self.supervisor.wait_ready(self.options.startup_timeout):
            self.session.report("warning", "supervisor", "not every node came up; starting the simulation anyway")

    def _keep_last_values(self, deployment: Deployment) -> None:
        """ROS 2 mode: the last message of every port topic, for rosbridge clients that subscribe
        later (Runner.last_values; lock-step mode keeps the controller's outputs). Subscribed
        before the nodes start, so their first messages are kept too."""
        assert self.runner is not None and self.transport is not None
        note = self.runner.last_values.note
        for topic, type_name in sorted(deployment.topics().items()):
            if topic == STATES_TOPIC or topic in interface.ALL_TOPICS:
                continue  # latched on their own / the simulator's topics
            with contextlib.suppress(MessageError):  # a type the simulator cannot import: not kept
                self.transport.subscribe(topic, type_name, note)

    def _recorded_topics(self) -> list[tuple[str, str]]:
        """Every topic of the run: the simulator's, the application's port topics, its event topics
        (automaton states, transitions, program steps)."""
        assert self.session is not None
        transport = self.session.transport
        if isinstance(transport, LocalBus):
            return transport.topics()  # lock-step: the controller declared its port topics
        topics = {spec.name: spec.type for spec in interface.ALL_TOPICS.values()}
        if self.deployment is not None:
            topics.update(self.deployment.topics())
        from .recorder import EVENT_TOPICS

        for topic in EVENT_TOPICS:  # automaton states, transitions, program steps
            topics[topic] = "std_msgs/msg/String"
        return sorted(topics.items())

    def _start_recording(self, path: Path) -> None:
        """Subscribes an MCAP recorder to every topic and the scene state after every period."""
        assert self.session is not None
        session = self.session
        try:
            # imported here: a Python with maa-sim but without the mcap packages runs everything else
            from .recorder import McapRecorder, record_scene, record_topics
        except ImportError as exc:
            raise ImportError(f"--record needs the packages mcap and mcap-ros2-support ({exc})") from None
        self.recorder = McapRecorder(path)

        def warn(text: str) -> None:
            session.report("warning", "recorder", text)

        # stamped with the elapsed time, which a reset does not turn back (session.py)
        record_topics(
            self.recorder, self._recorded_topics(), session.transport.subscribe, lambda: session.elapsed, warn
        )
        session.period_listeners.append(record_scene(self.recorder))

    def _watch_states(self) -> None:
        """Keeps the latest automaton state of every node (`/maa/automaton_states`, docs/ide.md):
        for `/sim/get_status`, and for a client that subscribes to the topic later."""
        assert self.session is not None
        transport = self.session.transport
        if isinstance(transport, LocalBus) and transport.topic_type(STATES_TOPIC) is None:
            return  # a lock-step controller without automaton states
        transport.subscribe(STATES_TOPIC, "std_msgs/msg/String", self._on_states)

    def _watch_breakpoints(self) -> None:
        """Lock-step mode: the transitions of every period are checked against the breakpoints."""
        assert self.session is not None and self.runner is not None
        transport = self.session.transport
        if not isinstance(transport, LocalBus) or transport.topic_type(TRANSITIONS_TOPIC) is None:
            return  # ROS 2 mode, or a controller that reports no transitions
        self.breakpoints = Breakpoints(self.runner.pause)
        transport.subscribe(TRANSITIONS_TOPIC, "std_msgs/msg/String", self.breakpoints.on_transition)

    def _on_states(self, _topic: str, msg: JsonMessage) -> None:
        try:
            states = json.loads(str(msg.get("data", "")))
        except ValueError:
            return
        if isinstance(states, dict):
            with self._states_lock:
                self.automaton_states.update({str(k): str(v) for k, v in states.items()})

    def _clear_states(self) -> None:
        with self._states_lock:
            self.automaton_states.clear()

    def _latched(self, topic: str) -> JsonMessage | None:
        """What a client that subscribes gets at once: the automata's states, or the last message
        of a topic the application sent (a port written before the client subscribed)."""
        if topic != STATES_TOPIC:
            return self.runner.last_values.get(topic) if self.runner is not None else None
        with self._states_lock:
            return {"data": json.dumps(self.automaton_states)} if self.automaton_states else None

    @staticmethod
    def _goal(session: SimSession) -> bool:
        return session.world.toast_on_plate()

    # ----------------------------------------------------------------------------- events

    def _report_node(self, level: str, source: str, message: str, details: dict[str, Any]) -> None:
        assert self.session is not None
        self.session.report(level, source, message, **details)

    def _on_node_failure(self, _node: Any) -> None:
        self.failed.set()
        if self.options.on_node_failure == "stop" and self.runner is not None:
            self.runner.finish("a node failed")

    def _on_event(self, event: SimEvent) -> None:
        text = f"[maa-sim] {event.level}: {event.source}: {event.message}"
        tail = event.details.get("stderr_tail")
        if tail:
            text += "\n  stderr (last lines):\n" + "\n".join("    " + line for line in str(tail).splitlines())
        print(text, file=sys.stderr, flush=True)
        if self.rosbridge is not None and event.level in ("error", "warning"):
            self.rosbridge.broadcast_status(event.level, f"{event.source}: {event.message}")

    def _on_client_publish(self, topic: str, msg: JsonMessage) -> bool:
        """Lock-step mode: a client's message on a port topic goes to the controller's next slice."""
        assert self.runner is not None and self.session is not None
        transport = self.session.transport
        if isinstance(transport, LocalBus):
            type_name = transport.topic_type(topic)
            if type_name is not None:
                from .messages import validate

                msg = validate(type_name, msg)
        check = getattr(self.runner.controller, "validate_input", None)
        if callable(check):
            try:
                check(topic, msg)  # e.g. an enum constant's name on a root in-port topic
            except ValueError as exc:
                raise MessageError(f"{topic}: {exc}") from None
        self.runner.inject(topic, msg)
        if isinstance(transport, LocalBus) and topic not in self._port_topics:
            # actuator topics reach the session this way, other topics their subscribers; a port
            # topic of the controller is shown by the controller in the slice that reads it
            transport.deliver(topic, msg)
        return True

    # ----------------------------------------------------------------------------- services

    def control_services(self) -> dict[str, ServiceHandler]:
        def runner() -> Runner:
            assert self.runner is not None
            return self.runner

        def ok(message: str = "") -> JsonMessage:
            return {"success": True, "message": message, "status": runner().status()}

        def pause(_args: JsonMessage) -> JsonMessage:
            runner().pause()
            return ok("paused")

        def going_on() -> None:
            if self.breakpoints is not None:
                self.breakpoints.clear_hit()

        def resume(_args: JsonMessage) -> JsonMessage:
            going_on()
            runner().resume()
            return ok("running")

        def step(args: JsonMessage) -> JsonMessage:
            steps = args.get("steps", 1)
            if isinstance(steps, bool) or not isinstance(steps, int):
                raise ServiceError("steps must be an integer")
            going_on()
            done, interrupted = runner().step(steps)
            if interrupted:
                return ok(f"stepped {done} of {steps} period(s); stopped by {interrupted}")
            return ok(f"stepped {steps} period(s)")

        def reset(args: JsonMessage) -> JsonMessage:
            seed = args.get("seed")
            if seed is not None and (isinstance(seed, bool) or not isinstance(seed, int)):
                raise ServiceError("seed must be an integer")
            if self.supervisor is not None:
                restarted = self.reset_ros2(seed)
                return ok(
                    f"reset; {len(self.supervisor.processes)} node(s) restarted"
                    + ("" if restarted else " (not every node came up again)")
                )
            self._clear_states()  # the controller emits its states again in its next first slice
            going_on()
            runner().reset(seed)
            return ok("reset")

        def set_speed(args: JsonMessage) -> JsonMessage:
            speed = args.get("speed")
            if isinstance(speed, bool) or not isinstance(speed, int | float):
                raise ServiceError("speed must be a number")
            runner().set_speed(float(speed))
            return ok(f"speed {speed}")

        def get_status(_args: JsonMessage) -> JsonMessage:
            return self.status()

        def set_breakpoints(args: JsonMessage) -> JsonMessage:
            if self.breakpoints is None:
                raise ServiceError("breakpoints need a lock-step run of a generated application (--mode lockstep)")
            try:
                breakpoints = check_request(args)
            except ValueError as exc:
                raise ServiceError(str(exc)) from None
            states = getattr(self._controller, "states", None)
            known = set(states()) if callable(states) else None
            unknown = sorted({bp["node"] for bp in breakpoints} - known) if known is not None else []
            if unknown:
                raise ServiceError(f"/sim/set_breakpoints: no automaton runs on {', '.join(unknown)}")
            automata = getattr(self._controller, "automata", None)  # the build's automata table
            problems = unresolved(breakpoints, automata()) if callable(automata) else []
            if problems:
                raise ServiceError(f"/sim/set_breakpoints: {'; '.join(problems)}")
            self.breakpoints.set(breakpoints)
            return ok(f"{len(breakpoints)} breakpoint(s)")

        return {
            "sim/pause": pause,
            "sim/resume": resume,
            # up to 100000 periods (minutes on a slow machine): on a worker thread, so the endpoint
            # serves every client meanwhile; the reply comes when the step is done or interrupted
            "sim/step": BlockingService(step),
            "sim/reset": BlockingService(reset),  # restarting nodes takes seconds
            "sim/set_speed": set_speed,
            "sim/get_status": get_status,
            "sim/set_breakpoints": set_breakpoints,
        }

    def reset_ros2(self, seed: int | None = None) -> bool:
        """ROS 2 mode's reset: every node restarts (a fresh run), the scene goes back to its start.

        The loop is paused meanwhile and the clock held until every new node answers its liveness
        probe (as at the start); then the loop continues unless it was paused before. The clock
        keeps running forward across the reset. True when every node came up again.
        """
        assert self.runner is not None and self.session is not None and self.supervisor is not None
        with self._reset_lock:
            runner, session = self.runner, self.session
            was_paused = runner.paused
            runner.pause()
            session.report("info", "supervisor", "reset: restarting every node")
            self.supervisor.restart()
            self._clear_states()
            runner.reset(seed)
            session.publish(session.observe())
            ready: bool = self.supervisor.wait_ready(self.options.startup_timeout)
            if not ready:
                session.report("warning", "supervisor", "reset: not every node came up again")
            if not was_paused and not self._stopped.is_set():
                runner.resume()
            return ready

    def _latched_states(self) -> dict[str, str]:
        with self._states_lock:
            return dict(self.automaton_states)

    def status(self) -> JsonMessage:
        assert self.runner is not None and self.session is not None
        return {
            "mode": self.options.mode,
            **self.runner.status(),
            "domain_id": self.domain_id,
            "nodes": self.supervisor.statuses() if self.supervisor is not None else [],
            "automaton_states": self._latched_states(),
            "breakpoint": self.breakpoints.hit if self.breakpoints is not None else None,
            "events": [e.as_json() for e in list(self.session.events)[-20:]],
            "rosbridge": self.rosbridge.url if self.rosbridge is not None else None,
            "viser": self.viewer.url if self.viewer is not None else None,
        }

    # ----------------------------------------------------------------------------- stop

    def wait(self, timeout: float | None = None) -> bool:
        """Waits until the run finishes (goal, time limit, failure policy); True when it did."""
        assert self.runner is not None
        return self.runner.finished.wait(timeout)

    def stop(self) -> None:
        if self._stopped.is_set():
            return
        self._stopped.set()
        if self.runner is not None:
            self.runner.stop()
        if self.supervisor is not None:
            self.supervisor.closing.set()  # a reset waiting for its nodes gives up
            with self._reset_lock:  # a reset in progress finishes first (it holds node processes)
                self.supervisor.close()
        if self.viewer is not None:
            self.viewer.stop()
        if self.rosbridge is not None:
            self.rosbridge.stop()
        if self.transport is not None and hasattr(self.transport, "close"):
            self.transport.close()
        if self.lease is not None:
            self.lease.release()
        if self.recorder is not None:
            try:
                self.recorder.close()
            except OSError as exc:
                print(f"maa-sim: the recording {self.recorder.part} could not be completed: {exc}", file=sys.stderr)
        if self._own_log_dir and self.log_dir is not None and not self.failed.is_set():
            with contextlib.suppress(OSError):
                shutil.rmtree(self.log_dir)
