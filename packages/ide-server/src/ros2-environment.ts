import { spawn } from 'node:child_process';
import { existsSync } from 'node:fs';
import path from 'node:path';
import { createInterface } from 'node:readline';
import { findInterfacePackages, ros2EnvironmentLock } from '@maa/protocol/sim-package';
import { HttpError } from './http-util.js';

export { findInterfacePackages } from '@maa/protocol/sim-package';

/** How the backend gets a Python environment that runs generated ROS 2 nodes (docs/ide.md). */
export interface Ros2EnvironmentOptions {
    /** The venv with rclpy, the rosidl toolchain and maa-sim (packages/generators-python/.venv-ros2). */
    venv: string;
    /** Creates `venv` when it is missing (scripts/setup_ros2_venv.sh); undefined: a missing venv is an error. */
    setupScript?: string;
    /** scripts/install_ros2_interfaces.sh VENV INTERFACES_DIR. */
    installScript: string;
    /** Longest setup of the venv (default 30 min: a cold pip cache on a slow line). */
    setupTimeoutMs?: number;
    /** Longest build and install of one interface package (default 15 min). */
    buildTimeoutMs?: number;
    /** Seconds between "still ..." lines in the log while a step runs (default 15). */
    heartbeatSeconds?: number;
}

export type LogSink = (line: string) => void;

const ERROR_LOG_LINES = 60;

/**
 * The ROS 2 environment of simulation sessions: maa-sim starts every node as `<its python> -m
 * <module>`, so the generated interface package must be installed into the venv that runs maa-sim
 * (docs/generating-ros2.md). `prepare` creates the venv when missing, builds and installs every
 * interface package of a generated platform (the script skips unchanged ones) and answers the
 * venv's maa-sim. Steps are serialized in this process and, with flock(1), across processes that
 * share the venv.
 */
export class Ros2Environment {
    private queue: Promise<unknown> = Promise.resolve();

    constructor(private readonly options: Ros2EnvironmentOptions) {}

    get venv(): string {
        return this.options.venv;
    }

    /** The venv's maa-sim. */
    get maaSim(): string {
        return path.join(this.options.venv, 'bin', 'maa-sim');
    }

    prepare(platformDir: string, log: LogSink, signal: AbortSignal): Promise<string> {
        const run = this.queue.then(() => this.run(platformDir, log, signal));
        this.queue = run.catch(() => undefined);
        return run;
    }

    private async run(platformDir: string, log: LogSink, signal: AbortSignal): Promise<string> {
        const { venv, setupScript, installScript } = this.options;
        const python = path.join(venv, 'bin', 'python');
        if (!existsSync(python) || !existsSync(this.maaSim)) {
            if (!setupScript) {
                throw new HttpError(
                    500,
                    `the ROS 2 environment ${venv} is missing or has no maa-sim; create it with "bash packages/generators-python/scripts/setup_ros2_venv.sh" (for that location) or pass --ros2-venv`,
                );
            }
            log(`maa-ide: setting up the ROS 2 environment ${venv} (rclpy, the rosidl toolchain, maa-sim; minutes the first time)`);
            const seconds = await this.step(
                'setting up the ROS 2 environment',
                'bash',
                [setupScript],
                this.options.setupTimeoutMs ?? 30 * 60_000,
                log,
                signal,
            );
            log(`maa-ide: the ROS 2 environment is ready (${seconds.toFixed(1)} s)`);
            if (!existsSync(this.maaSim)) throw new HttpError(500, `setting up the ROS 2 environment did not install ${this.maaSim}`);
        }
        const interfaces = findInterfacePackages(platformDir);
        if (interfaces.length === 0) log('maa-ide: the platform has no interface package to install');
        for (const dir of interfaces) {
            const name = path.basename(dir);
            log(`maa-ide: installing the interface package ${name} into ${venv} (a build takes 15-60 s; skipped while unchanged)`);
            const seconds = await this.step(
                `building the interface package ${name}`,
                'bash',
                [installScript, venv, dir],
                this.options.buildTimeoutMs ?? 15 * 60_000,
                log,
                signal,
            );
            log(`maa-ide: ${name} is installed (${seconds.toFixed(1)} s)`);
        }
        return this.maaSim;
    }

    /** Runs one command under the venv's lock; its output goes to the log. Answers the seconds it took. */
    private step(what: string, command: string, args: string[], timeoutMs: number, log: LogSink, signal: AbortSignal): Promise<number> {
        if (signal.aborted) return Promise.reject(cancelled());
        const lockFile = ros2EnvironmentLock(this.options.venv);
        const [cmd, argv] =
            existsSync('/usr/bin/flock') || existsSync('/bin/flock') ? ['flock', [lockFile, command, ...args]] : [command, args];
        const started = Date.now();
        return new Promise<number>((resolve, reject) => {
            // A process group of its own, so that a stop also ends pip, cmake and the compilers.
            const child = spawn(cmd, argv, {
                stdio: ['ignore', 'pipe', 'pipe'],
                detached: true,
                env: { ...process.env, PIP_DISABLE_PIP_VERSION_CHECK: '1' },
            });
            const output: string[] = [];
            const push = (line: string): void => {
                output.push(line);
                if (output.length > ERROR_LOG_LINES) output.shift();
                log(line);
            };
            createInterface({ input: child.stdout! }).on('line', push);
            createInterface({ input: child.stderr! }).on('line', push);
            let failure: HttpError | undefined;
            const killGroup = (): void => {
                try {
                    if (child.pid !== undefined) process.kill(-child.pid, 'SIGTERM');
                } catch {
                    // already gone
                }
            };
            const heartbeat = setInterval(
                () => log(`maa-ide: still ${what} (${Math.round((Date.now() - started) / 1000)} s)`),
                (this.options.heartbeatSeconds ?? 15) * 1000,
            );
            const timer = setTimeout(() => {
                failure = withTail(500, `${what} took longer than ${Math.round(timeoutMs / 1000)} s`, output);
                killGroup();
            }, timeoutMs);
            const onAbort = (): void => {
                failure ??= cancelled();
                killGroup();
            };
            signal.addEventListener('abort', onAbort, { once: true });
            const done = (): void => {
                clearInterval(heartbeat);
                clearTimeout(timer);
                signal.removeEventListener('abort', onAbort);
            };
            child.on('error', (e) => {
                done();
                reject(new HttpError(500, `${what}: cannot run ${cmd}: ${e.message}`));
            });
            child.on('close', (code, sig) => {
                done();
                if (failure) reject(failure);
                else if (code === 0) resolve((Date.now() - started) / 1000);
                else reject(withTail(500, `${what} failed (${sig ? `signal ${sig}` : `exit code ${code}`})`, output));
            });
        });
    }
}

function cancelled(): HttpError {
    return new HttpError(409, 'the simulation start was cancelled (stopped)');
}

function withTail(status: number, message: string, output: readonly string[]): HttpError {
    return new HttpError(status, `${message}:\n${output.slice(-20).join('\n')}`, { log: [...output] });
}
