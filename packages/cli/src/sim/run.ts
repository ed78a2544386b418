import { type ChildProcess, spawn } from 'node:child_process';
import { createInterface } from 'node:readline';
import type { SimulatorFinished, SimulatorProgress } from '@maa/protocol';
import type { SimPackageMode } from '@maa/protocol/sim-package';

/** What `maa-sim run` is asked to do. */
export interface MaaSimRun {
    readonly maaSim: string;
    readonly packageDir: string;
    readonly mode: SimPackageMode;
    readonly untilGoal: boolean;
    /** Simulated seconds (`--max-time`). */
    readonly duration?: number;
    /** Absolute path of the MCAP file. */
    readonly record?: string;
    /** Serve the viser panel (on a free port) instead of running headless. */
    readonly viewer: boolean;
    readonly speed?: number;
}

/** How the run went: maa-sim's finished line (none when it failed before), its exit, its viewer URL. */
export interface MaaSimOutcome {
    readonly finished?: SimulatorFinished;
    readonly exitCode: number | null;
    readonly signal: NodeJS.Signals | null;
}

export interface MaaSimListener {
    /** The viser panel's URL with its token, once maa-sim is running (only with a viewer). */
    viewer?(url: string): void;
    progress(line: SimulatorProgress): void;
    /** A line maa-sim wrote to stderr (its warnings and errors). */
    log(line: string): void;
}

/** The arguments of `maa-sim run` (docs/simulation.md, "`maa-sim run` reference"). */
export function maaSimArgs(run: MaaSimRun): string[] {
    const args = ['run', '--package', run.packageDir, '--mode', run.mode, '--status-json', '--progress-json', '--rosbridge-port', 'off'];
    args.push('--viser-port', run.viewer ? '0' : 'off');
    if (run.untilGoal) args.push('--until-goal');
    if (run.duration !== undefined) args.push('--max-time', String(run.duration));
    if (run.record !== undefined) args.push('--record', run.record);
    if (run.speed !== undefined) args.push('--speed', String(run.speed));
    if (run.mode === 'ros2') args.push('--on-node-failure', 'stop');
    return args;
}

/** A JSON line of maa-sim's stdout as an object, or undefined. */
function jsonLine(line: string): Record<string, unknown> | undefined {
    if (!line.startsWith('{')) return undefined;
    try {
        const value: unknown = JSON.parse(line);
        return typeof value === 'object' && value !== null ? (value as Record<string, unknown>) : undefined;
    } catch {
        return undefined;
    }
}

/** The ready line's viser URL with the token the panel asks for. */
function viewerUrl(ready: Record<string, unknown>): string | undefined {
    if (typeof ready['viser'] !== 'string' || typeof ready['token'] !== 'string') return undefined;
    const url = new URL(ready['viser']);
    url.searchParams.set('token', ready['token']);
    return url.toString();
}

/**
 * Runs maa-sim until it exits: its progress lines and stderr go to the listener; SIGINT and
 * SIGTERM to maa-gen meanwhile stop the run (maa-sim finishes it and reports as usual).
 */
export async function runMaaSim(run: MaaSimRun, listener: MaaSimListener): Promise<MaaSimOutcome> {
    // loaded here: the contracts bring TypeBox and every schema, which other commands do not need at start
    const { simulatorFinishedContract, simulatorProgressContract } = await import('@maa/protocol');
    const child = spawn(run.maaSim, maaSimArgs(run), {
        cwd: run.packageDir,
        stdio: ['ignore', 'pipe', 'pipe'],
        env: { ...process.env, PYTHONUNBUFFERED: '1' },
    });
    let finished: SimulatorFinished | undefined;
    createInterface({ input: child.stdout! }).on('line', (line) => {
        const value = jsonLine(line);
        if (value?.['event'] === 'progress' && simulatorProgressContract.check(value)) listener.progress(value);
        else if (value?.['event'] === 'finished' && simulatorFinishedContract.check(value)) finished = value;
        else if (value?.['event'] === 'ready') {
            const url = viewerUrl(value);
            if (url) listener.viewer?.(url);
        }
    });
    createInterface({ input: child.stderr! }).on('line', (line) => listener.log(line));
    const stop = (): void => void child.kill('SIGTERM');
    process.on('SIGINT', stop);
    process.on('SIGTERM', stop);
    return new Promise<MaaSimOutcome>((resolve, reject) => {
        child.on('error', (e) => reject(e));
        child.on('close', (exitCode, signal) => resolve({ finished, exitCode, signal }));
    }).finally(() => {
        process.off('SIGINT', stop);
        process.off('SIGTERM', stop);
        stopIfRunning(child);
    });
}

function stopIfRunning(child: ChildProcess): void {
    if (child.exitCode === null && child.signalCode === null) child.kill('SIGKILL');
}
