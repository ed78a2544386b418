import { execFile } from 'node:child_process';
import { existsSync, mkdirSync, mkdtempSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { Worker } from 'node:worker_threads';

export const BIN = fileURLToPath(new URL('../bin/maa-gen.js', import.meta.url));
const BUILT_MAIN = fileURLToPath(new URL('../dist/main.js', import.meta.url));

export interface CliResult {
    code: number | null;
    stdout: string;
    stderr: string;
}

/** Fails early with a clear message when the CLI has not been built (`npm run build`). */
export function requireBuiltCli(): void {
    if (!existsSync(BUILT_MAIN)) {
        throw new Error(`${BUILT_MAIN} is missing: run "npm run build" at the repository root first`);
    }
}

/** Runs the built `maa-gen` as a child process (stdout/stderr are pipes, so not TTYs). */
export function runCli(args: string[], cwd: string): Promise<CliResult> {
    return new Promise((resolve, reject) => {
        execFile(
            process.execPath,
            [BIN, ...args],
            { cwd, env: { ...process.env, NO_COLOR: '1' }, maxBuffer: 64 * 1024 * 1024 },
            (error, stdout, stderr) => {
                if (error && typeof error.code !== 'number') {
                    reject(error);
                    return;
                }
                resolve({ code: error ? (error.code as number) : 0, stdout, stderr });
            },
        );
    });
}

let worker: Worker | undefined;
let nextId = 0;
const pending = new Map<number, { resolve: (r: CliResult) => void; reject: (e: Error) => void }>();

/** The thread of runCliInProcess, started on first use; idle, it does not keep the test process alive. */
function inProcessWorker(): Worker {
    if (worker) return worker;
    const w = new Worker(new URL('./in-process-worker.mjs', import.meta.url));
    w.unref();
    w.on('message', (m: { id: number; code?: number; stdout?: string; stderr?: string; error?: string }) => {
        const call = pending.get(m.id);
        pending.delete(m.id);
        if (pending.size === 0) w.unref();
        if (m.error !== undefined) call?.reject(new Error(`runCliInProcess: ${m.error}`));
        else call?.resolve({ code: m.code ?? null, stdout: m.stdout ?? '', stderr: m.stderr ?? '' });
    });
    const fail = (error: Error): void => {
        for (const call of pending.values()) call.reject(error);
        pending.clear();
        worker = undefined;
    };
    w.on('error', fail);
    w.on('exit', (code) => fail(new Error(`runCliInProcess: the worker thread exited with ${code}`)));
    worker = w;
    return w;
}

/**
 * Runs the built maa-gen's main() in a worker thread of this test process, with stdout and stderr
 * captured as runCli's pipes would (not TTYs) and the exit code main() returns, which the bin
 * passes to process.exit. One warm thread per test file instead of a cold process per command (a
 * cold `maa-gen check` costs about a second of CPU): for tests of what a command does, not of the
 * process boundary, which runCli tests (the bin, the flushing of stdout/stderr, the exit code).
 * `env` is added to the environment the command sees (CliIo.env; not the thread's process.env).
 */
export function runCliInProcess(args: string[], cwd: string, env: Record<string, string> = {}): Promise<CliResult> {
    const id = nextId++;
    return new Promise((resolve, reject) => {
        pending.set(id, { resolve, reject });
        const w = inProcessWorker();
        w.ref(); // while a command runs (unref'd again when none is left)
        w.postMessage({ id, args, cwd, env: { ...process.env, NO_COLOR: '1', ...env } });
    });
}

/** A temporary folder with model files; `write` creates parent folders as needed. */
export class ModelDir {
    readonly dir: string;

    constructor() {
        this.dir = mkdtempSync(path.join(tmpdir(), 'maa-cli-test-'));
    }

    write(relative: string, content: string | Buffer): string {
        const file = path.join(this.dir, relative);
        mkdirSync(path.dirname(file), { recursive: true });
        writeFileSync(file, content);
        return file;
    }

    path(relative = ''): string {
        return path.join(this.dir, relative);
    }

    dispose(): void {
        rmSync(this.dir, { recursive: true, force: true });
    }
}

/** A line of the text format: `file:line:col: severity code message`. */
export const TEXT_LINE =
    /^(?<file>[^:]+):(?<line>\d+):(?<column>\d+): (?<severity>error|warning|info|hint) (?<code>[a-z]+\/[a-z0-9-]+) (?<message>.+)$/;

export function parseTextLines(stdout: string): Array<Record<string, string>> {
    return stdout
        .split('\n')
        .filter((l) => l.length > 0)
        .map((l) => {
            const m = TEXT_LINE.exec(l);
            if (!m?.groups) throw new Error(`not a diagnostic line: ${JSON.stringify(l)}`);
            return { ...m.groups };
        });
}
