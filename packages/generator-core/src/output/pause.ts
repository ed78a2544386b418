import { spawn } from 'node:child_process';
import { writeSync } from 'node:fs';

/** The phases of writing an output (docs/generating.md, "Output folder"). */
export type WritePhase = 'recover' | 'staging' | 'commit' | 'cleanup';

const PHASES: readonly string[] = ['recover', 'staging', 'commit', 'cleanup'];

/** What the writer prints to stderr when it pauses, followed by `<phase> <n>`. */
const PAUSED = 'maa-gen: paused at';

/** Longest pause: a test that forgot its child does not leave it blocked forever. */
const MAX_PAUSE_MS = 10 * 60_000;

/**
 * Test-only hook, so that a test can kill the writer at a known point instead of guessing with
 * timers: with `MAA_GEN_PAUSE_AT=<phase>[:<n>]` the writer stops at the n-th checkpoint (default
 * 1) of that phase, or at the phase's last one when it has fewer, prints
 * `maa-gen: paused at <phase> <k>` to stderr and blocks its thread (about ten minutes, then it
 * goes on). Unset, a checkpoint costs one comparison.
 */
export class Checkpoints {
    private readonly phase: WritePhase | undefined;
    private readonly at: number;
    private readonly counts = new Map<WritePhase, number>();
    private paused = false;

    constructor(setting: string | undefined = process.env['MAA_GEN_PAUSE_AT']) {
        const m = /^([a-z]+)(?::(\d+))?$/.exec(setting ?? '');
        this.phase = m && PHASES.includes(m[1]!) ? (m[1] as WritePhase) : undefined;
        this.at = Math.max(1, Number(m?.[2] ?? 1));
    }

    /** A point inside `phase` where the output is in a state a kill may leave. */
    reached(phase: WritePhase): void {
        if (phase !== this.phase || this.paused) return;
        const n = (this.counts.get(phase) ?? 0) + 1;
        this.counts.set(phase, n);
        if (n >= this.at) this.pause(phase, n);
    }

    /** The end of `phase` (its last checkpoint, whatever `n` asked for). */
    ended(phase: WritePhase): void {
        if (phase !== this.phase || this.paused) return;
        this.pause(phase, (this.counts.get(phase) ?? 0) + 1);
    }

    private pause(phase: WritePhase, n: number): void {
        this.paused = true;
        // Synchronous, so the line is out before the thread blocks.
        writeSync(2, `${PAUSED} ${phase} ${n}\n`);
        Atomics.wait(new Int32Array(new SharedArrayBuffer(4)), 0, 0, MAX_PAUSE_MS);
    }
}

/**
 * The other side of the hook, for tests: runs `command` with `MAA_GEN_PAUSE_AT=<pauseAt>` until
 * the writer pauses, kills it with SIGKILL there and resolves to the checkpoint it reached
 * (`"commit 2"`); rejects, with its stderr, when it exits without pausing.
 */
export function killWhenPaused(
    command: string,
    args: readonly string[],
    pauseAt: string,
    options: { cwd?: string; env?: NodeJS.ProcessEnv } = {},
): Promise<string> {
    return new Promise((resolve, reject) => {
        const env = { ...(options.env ?? process.env), MAA_GEN_PAUSE_AT: pauseAt };
        const child = spawn(command, args, { cwd: options.cwd, env, stdio: ['ignore', 'ignore', 'pipe'] });
        let stderr = '';
        let paused = '';
        child.stderr.setEncoding('utf8');
        child.stderr.on('data', (chunk: string) => {
            stderr += chunk;
            const at = stderr.indexOf(`${PAUSED} `);
            const line = at >= 0 ? /^(\S+ \d+)\n/.exec(stderr.slice(at + PAUSED.length + 1)) : null;
            if (line && !paused) {
                paused = line[1]!;
                child.kill('SIGKILL');
            }
        });
        child.on('error', reject);
        child.on('exit', (code, signal) => {
            if (paused && signal === 'SIGKILL') resolve(paused);
            else reject(new Error(`the writer did not pause at ${pauseAt} (exit ${code}, signal ${signal}): ${stderr}`));
        });
    });
}
