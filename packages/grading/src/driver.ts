/**
 * Running a grade job on the Python grading driver (`python -m maa_sim.grading run --job JOB.json
 * --out OUTDIR`, Ray): its JSON lines are read as they come and forwarded; an AbortSignal stops it
 * (SIGTERM, then SIGKILL to its process group after a grace period).
 */
import { type ChildProcess, spawn } from 'node:child_process';
import { writeFile } from 'node:fs/promises';
import { createInterface } from 'node:readline';
import { type DriverLine, type DriverTask, driverLineContract, GRADE_JOB_FORMAT, type GradeJobTask } from '@maa/protocol/grading';

export interface DriverOptions {
    readonly python: string;
    readonly jobFile: string;
    readonly outDir: string;
    readonly tasks: readonly GradeJobTask[];
    /** A Ray cluster's address (RAY_ADDRESS); local Ray when absent. */
    readonly rayAddress?: string;
    readonly onLine?: (line: DriverLine) => void;
    readonly signal?: AbortSignal;
    /** Environment of the driver (default: this process's). */
    readonly env?: NodeJS.ProcessEnv;
}

export interface DriverRun {
    /** The task lines by task id. */
    readonly tasks: ReadonlyMap<string, DriverTask>;
    readonly exitCode: number | null;
    /** The end of the driver's stderr (for errors). */
    readonly stderr: string;
}

/** Raised when the driver refuses the job or dies before finishing; names the exit and the end of its stderr. */
export class DriverError extends Error {
    constructor(message: string) {
        super(message);
        this.name = 'DriverError';
    }
}

const STDERR_TAIL = 8192;
/** How long the driver may take to cancel its tasks and shut Ray down (a SIGKILL leaves Ray's processes behind). */
const KILL_GRACE_MS = 30_000;

export async function runDriver(options: DriverOptions): Promise<DriverRun> {
    await writeFile(options.jobFile, `${JSON.stringify({ format: GRADE_JOB_FORMAT, tasks: options.tasks }, null, 2)}\n`);
    options.signal?.throwIfAborted();
    const env: NodeJS.ProcessEnv = { ...(options.env ?? process.env), PYTHONUNBUFFERED: '1' };
    if (options.rayAddress) env['RAY_ADDRESS'] = options.rayAddress;
    const child = spawn(options.python, ['-m', 'maa_sim.grading', 'run', '--job', options.jobFile, '--out', options.outDir], {
        env,
        stdio: ['ignore', 'pipe', 'pipe'],
        detached: true,
    });
    const tasks = new Map<string, DriverTask>();
    let stderr = '';
    child.stderr.setEncoding('utf8');
    child.stderr.on('data', (chunk: string) => {
        stderr = (stderr + chunk).slice(-STDERR_TAIL);
    });
    const lines = createInterface({ input: child.stdout });
    lines.on('line', (text) => {
        const line = parseLine(text);
        if (!line) return;
        if (line.event === 'task') tasks.set(line.id, line);
        options.onLine?.(line);
    });
    const stop = stopper(child);
    options.signal?.addEventListener('abort', stop, { once: true });
    try {
        // 'exit', not 'close': processes Ray started may keep stderr open after the driver ended;
        // stdout (the JSON lines) is the driver's own and ends with it.
        const stdoutDone = new Promise<void>((resolve) => lines.once('close', resolve));
        const exitCode = await new Promise<number | null>((resolve, reject) => {
            child.on('error', (e) => reject(new DriverError(`could not start the grading driver ${options.python}: ${e.message}`)));
            child.on('exit', (code) => resolve(code));
        });
        await stdoutDone;
        child.stderr.destroy();
        options.signal?.throwIfAborted();
        if (exitCode !== 0)
            throw new DriverError(`the grading driver exited with ${exitCode}: ${stderr.trim().split('\n').slice(-10).join('\n')}`);
        return { tasks, exitCode, stderr };
    } finally {
        options.signal?.removeEventListener('abort', stop);
        lines.close();
    }
}

/** A JSON line of the driver, or undefined for other output (a warning Ray prints). */
function parseLine(text: string): DriverLine | undefined {
    if (!text.startsWith('{')) return undefined;
    try {
        const value: unknown = JSON.parse(text);
        return driverLineContract.check(value) ? value : undefined;
    } catch {
        return undefined;
    }
}

/**
 * Stops the driver: SIGTERM to it (it cancels its tasks and shuts Ray down), then, if it has not
 * ended after a grace period, SIGKILL to its whole process group (the driver and what it started).
 */
function stopper(child: ChildProcess): () => void {
    return () => {
        const pid = child.pid;
        if (pid === undefined || child.exitCode !== null || child.signalCode !== null) return;
        child.kill('SIGTERM');
        const timer = setTimeout(() => {
            try {
                process.kill(-pid, 'SIGKILL');
            } catch {
                // already gone
            }
        }, KILL_GRACE_MS);
        child.once('exit', () => clearTimeout(timer));
    };
}
