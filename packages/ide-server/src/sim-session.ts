import { spawn, type ChildProcess } from 'node:child_process';
import { randomBytes, randomUUID } from 'node:crypto';
import { existsSync } from 'node:fs';
import { connect } from 'node:net';
import path from 'node:path';
import { createInterface } from 'node:readline';
import type { SimMode, SimStatusAnswer } from '@maa/protocol';
import { findPackageDir, SIM_PACKAGE_FILE } from '@maa/protocol/sim-package';
import { HttpError } from './http-util.js';
import { descendantGroups, groupAlive, signalGroup } from './process-group.js';
import type { Ros2Environment } from './ros2-environment.js';

export type { SimMode } from '@maa/protocol';

export { findPackageDir } from '@maa/protocol/sim-package';
const LOG_LINES = 200;
const STATUS_LOG_LINES = 60;
/**
 * maa-sim's node supervision in ros2 mode: how long a node may take to come up, and to answer a
 * liveness probe. maa-sim's defaults (30 s, 5 s) are tight for seven rclpy processes on a loaded
 * 2-core machine; a crash is still reported at once.
 */
const ROS2_SUPERVISION = ['--startup-timeout', '60', '--hang-timeout', '15'];

/** What a session starts (the validated request of `POST /api/sim/start` with the generated folder). */
export interface SimStartRequest {
    app: string;
    platform: string;
    mode: SimMode;
    /** Simulated seconds per wall second; undefined leaves maa-sim's default. */
    speed?: number;
    /** The generated platform folder. */
    platformDir: string;
    /** Record the run into this MCAP file (maa-sim's `--record`; recordings.ts). */
    record?: string;
    /** Replay this MCAP file instead of running the platform (`maa-sim replay`; recording-routes.ts). */
    replay?: string;
}

export interface SimEndpoints {
    rosbridge: URL;
    viser: URL | undefined;
}

/** Where the proxy sends a session's traffic, with the secret maa-sim requires (`MAA_SIM_TOKEN`). */
export interface SimTarget extends SimEndpoints {
    token: string;
}

export interface SimSessionOptions {
    /** How long a simulation may take to become ready (default 90 s). */
    readyTimeoutMs?: number;
    /** A session ends when it had no client for this long (default 60 s; docs/ide.md "Simulation sessions"). */
    idleMs?: number;
    /** How long a stop waits after SIGTERM before SIGKILL (default 8 s). */
    stopGraceMs?: number;
    /**
     * Wraps maa-sim's command line, e.g. in a sandbox (the lab: `python -m maa_sim.sandbox ... --
     * maa-sim run ...`). Default none: maa-sim runs as it is (maa-ide). The wrapper gets the
     * session's signals (SIGTERM to its group on a stop) and must pass them on.
     */
    wrap?: SimCommandWrapper;
}

/** What a session would run: maa-sim, its arguments, its working folder (the package folder). */
export interface SimLaunch {
    command: string;
    args: string[];
    cwd: string;
    request: SimStartRequest;
}

/** The command line that runs a launch instead (its first word is the program). */
export type SimCommandWrapper = (launch: SimLaunch) => { command: string; args: string[] };

interface Session {
    id: string;
    request: SimStartRequest;
    /** Set while the environment is prepared (ros2: venv setup, interface build), before maa-sim runs. */
    preparing?: AbortController;
    /** maa-sim, once spawned (the leader of its own process group). */
    child?: ChildProcess;
    /** The bearer token maa-sim's endpoints require (passed as MAA_SIM_TOKEN). */
    token: string;
    /** Open proxied WebSockets of this session. */
    clients: number;
    idleTimer?: NodeJS.Timeout;
    log: string[];
    endpoints?: SimEndpoints;
    exitCode?: number | null;
    exited?: Promise<void>;
}

/** `GET /api/sim/status` (@maa/protocol). */
export type SimStatus = SimStatusAnswer;

/**
 * One `maa-sim run` child at a time, in a process group of its own: a stop signals the group
 * (SIGTERM, SIGKILL after a grace time), so whatever maa-sim started ends with it, and the
 * backend's exit kills it synchronously. Ports are chosen by maa-sim (`0`) and read from its
 * `--status-json` ready line, so there is no window in which another process could take a port
 * we picked. Start and stop are serialized; a crashed child stays visible in the status.
 */
export class SimSessions {
    private current: Session | undefined;
    private lock: Promise<unknown> = Promise.resolve();
    private readonly readyTimeoutMs: number;
    private readonly idleMs: number;
    private readonly stopGraceMs: number;
    private readonly wrap: SimCommandWrapper | undefined;
    /** Kills the running session's processes when the backend exits, however it exits. */
    private readonly onExit = (): void => this.killNow();

    /**
     * @param maaSim the maa-sim of lockstep sessions (and of ros2 ones when there is no `ros2` environment)
     * @param ros2 the environment ros2 sessions run in (its maa-sim, the interface packages installed into it)
     */
    constructor(
        private readonly maaSim: string,
        options: SimSessionOptions = {},
        private readonly ros2?: Ros2Environment,
    ) {
        this.readyTimeoutMs = options.readyTimeoutMs ?? 90_000;
        this.idleMs = options.idleMs ?? 60_000;
        this.stopGraceMs = options.stopGraceMs ?? 8_000;
        this.wrap = options.wrap;
        process.on('exit', this.onExit);
    }

    /** The endpoints and token of the running session (undefined when none runs). */
    target(): SimTarget | undefined {
        const s = this.current;
        return s?.child && s.exitCode === undefined && s.endpoints ? { ...s.endpoints, token: s.token } : undefined;
    }

    /** The running session's process group (maa-sim's pid), for tests and diagnostics. */
    processGroup(): number | undefined {
        const s = this.current;
        return s?.child && s.exitCode === undefined ? s.child.pid : undefined;
    }

    /**
     * A client (a proxied WebSocket) of the running session opened; call the returned function
     * when it closes. The session does not idle out while it has clients.
     */
    clientOpened(): () => void {
        const s = this.current;
        if (!s) return () => undefined;
        s.clients++;
        clearTimeout(s.idleTimer);
        let released = false;
        return () => {
            if (released) return;
            released = true;
            s.clients--;
            if (s.clients === 0) this.armIdle(s);
        };
    }

    /** A request about the simulation (`/api/sim/*`, proxied HTTP): the idle time starts again. */
    signOfLife(): void {
        const s = this.current;
        if (s?.endpoints && s.exitCode === undefined && s.clients === 0) this.armIdle(s);
    }

    /** Stops listening for the backend's exit (the server closed; stop() ran before). */
    dispose(): void {
        process.off('exit', this.onExit);
        this.killNow();
    }

    private armIdle(s: Session): void {
        clearTimeout(s.idleTimer);
        s.idleTimer = setTimeout(() => {
            if (this.current !== s || s.clients > 0 || s.exitCode !== undefined) return;
            s.log.push(`maa-ide: no client for ${this.idleMs / 1000} s, stopping the simulation`);
            this.serialized(() => (this.current === s ? this.stopCurrent() : Promise.resolve())).catch(() => undefined);
        }, this.idleMs);
        s.idleTimer.unref();
    }

    /** SIGKILL for the running session's groups, synchronously (process exit). */
    private killNow(): void {
        const pid = this.processGroup();
        if (pid === undefined) return;
        for (const group of [pid, ...descendantGroups(pid)]) signalGroup(group, 'SIGKILL');
    }

    start(request: SimStartRequest): Promise<{ session: string }> {
        return this.serialized(async () => {
            await this.stopCurrent();
            return this.spawnSession(request);
        });
    }

    /** Stops the session; a start still preparing its environment is cancelled at once (its answer is 409). */
    stop(): Promise<void> {
        this.current?.preparing?.abort();
        return this.serialized(() => this.stopCurrent());
    }

    status(): SimStatus {
        const s = this.current;
        if (!s) return { running: false, log: [] };
        const running = s.child !== undefined && s.exitCode === undefined;
        return {
            running,
            ...(s.preparing ? { preparing: true } : {}),
            session: s.id,
            mode: s.request.mode,
            app: s.request.app,
            platform: s.request.platform,
            ...(running || s.exitCode === undefined ? {} : { exitCode: s.exitCode }),
            ...(s.request.replay ? { replay: path.basename(s.request.replay) } : {}),
            ...(s.request.record ? { recording: path.basename(s.request.record) } : {}),
            log: s.log.slice(-STATUS_LOG_LINES),
        };
    }

    private serialized<T>(body: () => Promise<T>): Promise<T> {
        const run = this.lock.then(body);
        this.lock = run.catch(() => undefined);
        return run;
    }

    /** Starts maa-sim for the request (after preparing the ros2 environment) and waits until it is ready. */
    private async spawnSession(request: SimStartRequest): Promise<{ session: string }> {
        const ros2 = request.mode === 'ros2' && !request.replay ? this.ros2 : undefined;
        // a replay runs in its recording's folder and needs no package
        const packageDir = request.replay ? path.dirname(request.replay) : this.packageToRun(request, ros2);
        const { log, push } = boundedLog();
        const maaSim = ros2 ? await this.prepareRos2(ros2, request, log, push) : this.maaSim;
        if (request.mode === 'ros2') push(`maa-ide: starting ${maaSim} (ros2 mode)`);
        const token = randomBytes(32).toString('base64url');
        const args = maaSimArgs(request, packageDir);
        const launch = this.wrap ? this.wrap({ command: maaSim, args, cwd: packageDir, request }) : { command: maaSim, args };
        const child = spawnMaaSim(launch.command, launch.args, packageDir, token);
        let markExited!: () => void;
        const session: Session = {
            // A ros2 session keeps the id it was shown with while preparing.
            id: this.current?.request === request ? this.current.id : randomUUID(),
            request,
            child,
            log,
            token,
            clients: 0,
            exited: new Promise<void>((resolve) => (markExited = resolve)),
        };
        this.current = session;
        const ready = watchUntilReady(session, child, maaSim, push, markExited);
        return this.whenReady(session, ready);
    }

    /** The folder maa-sim runs (it holds the mode's package file); an HttpError when it or the simulator is missing. */
    private packageToRun(request: SimStartRequest, ros2: Ros2Environment | undefined): string {
        if (!ros2 && !existsSync(this.maaSim)) {
            throw new HttpError(
                500,
                `the simulator is not installed (${this.maaSim} is missing); run "bash sim-server/scripts/setup_env.sh"`,
            );
        }
        const packageDir = findPackageDir(request.platformDir, SIM_PACKAGE_FILE[request.mode]);
        if (!packageDir) {
            throw new HttpError(
                409,
                `the generated platform ${request.platform} has no ${SIM_PACKAGE_FILE[request.mode]}, so it cannot run in ${request.mode} mode`,
            );
        }
        return packageDir;
    }

    /**
     * Sets up the ros2 venv and builds the interface package; resolves with the venv's maa-sim.
     * The session is visible meanwhile (status: preparing, with the progress in its log); a stop cancels it.
     */
    private async prepareRos2(
        ros2: Ros2Environment,
        request: SimStartRequest,
        log: string[],
        push: (line: string) => void,
    ): Promise<string> {
        const preparing = new AbortController();
        const session: Session = { id: randomUUID(), request, log, preparing, token: '', clients: 0 };
        this.current = session;
        try {
            return await ros2.prepare(request.platformDir, push, preparing.signal);
        } catch (e) {
            const message = e instanceof Error ? e.message : String(e);
            push(`maa-ide: ${message.split('\n')[0]}`);
            if (e instanceof HttpError && !(e.extra && 'log' in e.extra)) throw withLog(e.status, e.message, log);
            throw e;
        } finally {
            delete session.preparing;
        }
    }

    /**
     * Waits for maa-sim's ready line (at most readyTimeoutMs) and for its rosbridge to accept
     * connections; then the idle time starts. A session that does not get there is stopped.
     */
    private async whenReady(session: Session, ready: Promise<SimEndpoints>): Promise<{ session: string }> {
        // The race below may be decided by the timeout; a later rejection must not be unhandled.
        ready.catch(() => undefined);
        let timer: NodeJS.Timeout | undefined;
        const timeout = new Promise<never>((_, reject) => {
            timer = setTimeout(
                () => reject(withLog(504, `the simulator was not ready after ${this.readyTimeoutMs / 1000} s`, session.log)),
                this.readyTimeoutMs,
            );
        });
        try {
            const endpoints = await Promise.race([ready, timeout]);
            await waitForPort(endpoints.rosbridge, 10_000);
            session.endpoints = endpoints;
            // A session nobody connects to ends like one whose clients left.
            this.armIdle(session);
            return { session: session.id };
        } catch (e) {
            await this.stopCurrent();
            throw e;
        } finally {
            clearTimeout(timer);
        }
    }

    /**
     * SIGTERM to maa-sim's group (maa-sim then stops its nodes and exits 0); after the grace time
     * SIGKILL to its group and the groups of its descendants, and once it exited SIGKILL to
     * whatever of those groups is left.
     */
    private async stopCurrent(): Promise<void> {
        const s = this.current;
        const pid = s?.child?.pid;
        if (!s?.exited || pid === undefined || s.exitCode !== undefined) return;
        clearTimeout(s.idleTimer);
        const groups = new Set([pid, ...descendantGroups(pid)]);
        signalGroup(pid, 'SIGTERM');
        const killed = setTimeout(() => {
            for (const g of [...groups, ...descendantGroups(pid)]) signalGroup(g, 'SIGKILL');
        }, this.stopGraceMs);
        await s.exited;
        clearTimeout(killed);
        for (const g of groups) if (groupAlive(g)) signalGroup(g, 'SIGKILL');
    }
}

/** A session's log, which keeps its last LOG_LINES lines, and the function that adds one. */
function boundedLog(): { log: string[]; push: (line: string) => void } {
    const log: string[] = [];
    const push = (line: string): void => {
        log.push(line);
        if (log.length > LOG_LINES) log.splice(0, log.length - LOG_LINES);
    };
    return { log, push };
}

/** `maa-sim run` for the package: ports chosen by maa-sim, announced in its `--status-json` ready line. */
function maaSimArgs(request: SimStartRequest, packageDir: string): string[] {
    if (request.replay) {
        return ['replay', request.replay, '--rosbridge-port', '0', '--viser-port', '0', '--host', '127.0.0.1', '--status-json'];
    }
    const args = [
        'run',
        '--package',
        packageDir,
        '--mode',
        request.mode,
        '--rosbridge-port',
        '0',
        '--viser-port',
        '0',
        // the simulate view has the run controls: viser's panel keeps only its HUD and camera presets
        '--viser-controls',
        'off',
        '--host',
        '127.0.0.1',
        '--status-json',
        ...(request.mode === 'ros2' ? ROS2_SUPERVISION : []),
    ];
    if (request.speed !== undefined) args.push('--speed', String(request.speed));
    if (request.record) args.push('--record', request.record);
    return args;
}

/** Spawns maa-sim as the leader of a process group of its own, with its own token and not maa-ide's. */
function spawnMaaSim(maaSim: string, args: string[], packageDir: string, token: string): ChildProcess {
    const env: NodeJS.ProcessEnv = { ...process.env, PYTHONUNBUFFERED: '1', MAA_SIM_TOKEN: token };
    delete env['MAA_IDE_TOKEN']; // the simulation (it runs the user's components) needs only its own
    // detached: a process group of its own, so a stop reaches everything maa-sim started.
    return spawn(maaSim, args, { cwd: packageDir, stdio: ['ignore', 'pipe', 'pipe'], env, detached: true });
}

/**
 * Pumps maa-sim's output into the session log and watches it end. Resolves with the endpoints
 * of its ready line; rejects when it ends (or cannot be spawned) before that. Its end is
 * recorded in the session whenever it comes (`exitCode`, `exited`).
 */
function watchUntilReady(
    session: Session,
    child: ChildProcess,
    maaSim: string,
    push: (line: string) => void,
    markExited: () => void,
): Promise<SimEndpoints> {
    return new Promise<SimEndpoints>((resolve, reject) => {
        createInterface({ input: child.stdout! }).on('line', (line) => {
            const endpoints = parseReadyLine(line);
            if (endpoints) resolve(endpoints);
            push(line);
        });
        createInterface({ input: child.stderr! }).on('line', push);
        // 'close' comes after the last output line was read; 'exit' is the fallback should a
        // grandchild keep the pipes open.
        let finished = false;
        const finish = (code: number | null, signal: NodeJS.Signals | null): void => {
            if (finished) return;
            finished = true;
            const how = recordEnd(session, child, code, signal, push);
            markExited();
            reject(withLog(500, `the simulator exited before it was ready (${how})`, session.log));
        };
        child.on('close', finish);
        child.on('error', (e) => {
            // Failing to spawn, or (rarely) to signal the process.
            push(`maa-ide: maa-sim process error: ${e.message}`);
            reject(new HttpError(500, `cannot start the simulator ${maaSim}: ${e.message}`));
            if (child.pid === undefined) finish(null, null); // never started: no 'exit' will come
        });
        child.on('exit', (code, signal) => setTimeout(() => finish(code, signal), 2_000).unref());
    });
}

/** Records how maa-sim ended in its session and its log; returns that as words ("exit code 1"). */
function recordEnd(
    session: Session,
    child: ChildProcess,
    code: number | null,
    signal: NodeJS.Signals | null,
    push: (line: string) => void,
): string {
    session.exitCode = code ?? (signal ? null : -1);
    clearTimeout(session.idleTimer);
    // What maa-sim left in its group (it crashed, or was killed) goes with it.
    if (child.pid !== undefined && groupAlive(child.pid)) signalGroup(child.pid, 'SIGKILL');
    const how = signal ? `signal ${signal}` : `exit code ${code}`;
    push(`maa-ide: maa-sim ended (${how})`);
    return how;
}

/** An error whose message ends with the log tail; the answer also carries the tail as `log`. */
function withLog(status: number, message: string, log: readonly string[]): HttpError {
    const tail = log.slice(-STATUS_LOG_LINES);
    return new HttpError(status, `${message}:\n${tail.slice(-20).join('\n')}`, { log: tail });
}

/** `{"event": "ready", "rosbridge": "ws://...", "viser": "http://..."}` → its endpoints. */
export function parseReadyLine(line: string): SimEndpoints | undefined {
    if (!line.startsWith('{')) return undefined;
    try {
        const value = JSON.parse(line) as { event?: unknown; rosbridge?: unknown; viser?: unknown };
        if (value.event !== 'ready' || typeof value.rosbridge !== 'string') return undefined;
        return {
            rosbridge: new URL(value.rosbridge.replace(/^ws/, 'http')),
            viser: typeof value.viser === 'string' ? new URL(value.viser) : undefined,
        };
    } catch {
        return undefined;
    }
}

/** Resolves once a TCP connection to the URL's port succeeds ("once its rosbridge answers"). */
async function waitForPort(url: URL, timeoutMs: number): Promise<void> {
    const deadline = Date.now() + timeoutMs;
    for (;;) {
        const ok = await new Promise<boolean>((resolve) => {
            const socket = connect(Number(url.port), url.hostname);
            socket.once('connect', () => {
                socket.destroy();
                resolve(true);
            });
            socket.once('error', () => resolve(false));
        });
        if (ok) return;
        if (Date.now() > deadline) throw new HttpError(504, `the simulator's rosbridge (${url.host}) does not accept connections`);
        await new Promise((r) => setTimeout(r, 100));
    }
}
