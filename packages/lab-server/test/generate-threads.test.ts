// Generation off the lab server's event loop (docs/lab.md "Load benchmark"): the generator
// threads' pool (jobs beyond the threads wait in order, a crashed thread rejects its job and is
// replaced, the stop rejects what waits), and a student's save answered while a generation runs
// (the generator thread is held blocked until the save, the file list and another student's login
// were answered; a generation on the event loop could never let them through); the worker threads
// run at a lower priority than the main thread.
import { readdirSync, readFileSync } from 'node:fs';
import { getPriority } from 'node:os';
import { Worker } from 'node:worker_threads';
import { afterAll, beforeAll, describe, expect, it, vi } from 'vitest';
import type { GenerateJob } from '@maa/ide-server';
import { CheckThread } from '../src/dashboard/index.js';
import { WORKER_NICE } from '../src/thread-priority.js';
import { defaultGenerateThreads, GeneratePool, generateWorkerScript } from '../src/workspaces/generate-pool.js';
import { type Backend, startBackend } from './backends.js';
import { type Lab, PYTHON, put, startLab } from './workspace-setup.js';

/** A generator thread (eval'd CommonJS) that answers each job with its platform and app file, or exits 9 for the platform `crash`. */
const ECHO = `const { parentPort } = require('node:worker_threads');
parentPort.on('message', (job) => {
    if (job.platform === 'crash') process.exit(9);
    parentPort.postMessage({ result: { kind: 'done', ok: true, diagnostics: [], files: [job.platform, job.appFile] } });
});`;

/**
 * A generator thread that, on a job, sets flag 1 (the job started) and then blocks its thread
 * (Atomics.wait) until the test sets flag 0, then answers an empty generation.
 */
const BLOCKING = `const { parentPort, workerData } = require('node:worker_threads');
const flags = new Int32Array(workerData);
parentPort.on('message', () => {
    Atomics.store(flags, 1, 1);
    Atomics.notify(flags, 1);
    Atomics.wait(flags, 0, 0);
    parentPort.postMessage({ result: { kind: 'done', ok: true, diagnostics: [], files: [] } });
});`;

const job = (platform: string, appFile = 'A.arcapp'): GenerateJob => ({
    appFile,
    modelRoot: '/m',
    platform,
    outDir: '/out',
    discoveryRoots: [],
});

describe('the generator threads', () => {
    it('take the cores but one, at least 1 and at most 4', () => {
        expect([1, 2, 3, 8, 64].map((cores) => defaultGenerateThreads(cores))).toEqual([1, 1, 2, 4, 4]);
        expect(() => new GeneratePool(0)).toThrow(/at least 1/);
    });

    it('run jobs in threads up to the size, the rest in order; a crash rejects its job and a new thread takes the next', async () => {
        const pool = new GeneratePool(2, () => new Worker(ECHO, { eval: true }));
        try {
            const runs = ['a', 'b', 'c', 'd', 'e'].map((p) => pool.run(job(p, `${p}.arcapp`)));
            expect(pool.started).toBe(2);
            expect(pool.queued).toBe(3);
            const results = await Promise.all(runs);
            expect(results.map((r) => (r.kind === 'done' ? r.files : r))).toEqual([
                ['a', 'a.arcapp'],
                ['b', 'b.arcapp'],
                ['c', 'c.arcapp'],
                ['d', 'd.arcapp'],
                ['e', 'e.arcapp'],
            ]);
            expect(pool.started).toBe(2);
            await expect(pool.run(job('crash'))).rejects.toThrow(/exit code 9/);
            // one thread is left: two jobs at once need a new one
            const after = await Promise.all([pool.run(job('x')), pool.run(job('y'))]);
            expect(after).toMatchObject([
                { kind: 'done', files: ['x', 'A.arcapp'] },
                { kind: 'done', files: ['y', 'A.arcapp'] },
            ]);
            expect(pool.started).toBe(3);
        } finally {
            await pool.close();
        }
        await expect(pool.run(job('late'))).rejects.toThrow(/stopping/);
    });

    it('rejects the running and waiting jobs when it is closed', async () => {
        const flags = new Int32Array(new SharedArrayBuffer(8));
        const pool = new GeneratePool(1, () => new Worker(BLOCKING, { eval: true, workerData: flags.buffer }));
        const outcome = (run: Promise<unknown>) =>
            run.then(
                () => 'resolved',
                (e: Error) => e.message,
            );
        const running = outcome(pool.run(job('a')));
        const waiting = outcome(pool.run(job('b')));
        const started = Atomics.waitAsync(flags, 1, 0);
        if (started.async) await started.value;
        const closing = pool.close(); // rejects both at once, then ends the thread
        Atomics.store(flags, 0, 1); // lets the blocked thread go, so that it can end
        Atomics.notify(flags, 0);
        await closing;
        expect(await running).toMatch(/stopped during the generation/);
        expect(await waiting).toMatch(/stopped during the generation/);
    });
});

/** The nice value of each thread of this process (Linux: field 19 of /proc/self/task/<tid>/stat). */
function threadNices(): Map<number, number> {
    const nices = new Map<number, number>();
    for (const tid of readdirSync('/proc/self/task')) {
        try {
            const stat = readFileSync(`/proc/self/task/${tid}/stat`, 'utf8');
            const fields = stat.slice(stat.lastIndexOf(')') + 2).split(' ');
            nices.set(Number(tid), Number(fields[16]));
        } catch {
            // the thread ended meanwhile
        }
    }
    return nices;
}

describe.runIf(process.platform === 'linux')('the worker threads’ priority', () => {
    it('is lowered in the generator thread, not in the main thread', async () => {
        const mainNice = getPriority(process.pid);
        const lowered = () => [...threadNices().values()].filter((n) => n === WORKER_NICE).length;
        const before = lowered();
        const pool = new GeneratePool(1, () => new Worker(generateWorkerScript()));
        try {
            // the real generator thread answers a job for a file that does not exist (an input error)
            const answer = await pool.run(job('timesync', '/nonexistent/App.arcapp'));
            expect(answer.kind).toBe('input-error');
            expect(lowered()).toBe(before + 1);
            expect(getPriority(process.pid)).toBe(mainNice);
        } finally {
            await pool.close();
        }
    });

    it('is lowered in the dashboard’s checker thread', async () => {
        const lowered = () => [...threadNices().values()].filter((n) => n === WORKER_NICE).length;
        const before = lowered();
        const thread = new CheckThread();
        try {
            expect(await thread.check([])).toEqual([]);
            expect(lowered()).toBe(before + 1);
        } finally {
            await thread.close();
        }
    });
});

describe('a lab server while a generation runs', () => {
    let backend: Backend;
    let lab: Lab;
    const flags = new Int32Array(new SharedArrayBuffer(8));

    beforeAll(async () => {
        vi.stubEnv('MAA_PYTHON', PYTHON);
        backend = await startBackend('pglite');
        lab = await startLab(await backend.freshStorage(), {
            workspaces: { generateThreads: 1, generateThread: () => new Worker(BLOCKING, { eval: true, workerData: flags.buffer }) },
        });
    }, 120_000);
    afterAll(async () => {
        Atomics.store(flags, 0, 1); // never leave a thread blocked
        Atomics.notify(flags, 0);
        await lab?.dispose();
        await backend?.dispose();
        vi.unstubAllEnvs();
    });

    it('answers a save, the file list and a login before the generation ends', async () => {
        const ada = await lab.as('ada');
        const events: string[] = [];
        const generating = ada
            .send(`${lab.ws('ada')}/generate`, {
                method: 'POST',
                body: { app: 'TR.arcapp', platform: 'timesync' },
                headers: { 'X-CSRF-Token': ada.csrf ?? '' },
            })
            .then((answer) => {
                events.push('generate answered');
                return answer;
            });
        // the job reached the generator thread, which is blocked from now on
        const started = Atomics.waitAsync(flags, 1, 0);
        if (started.async) await started.value;
        events.push('generation running');
        const saved = await put(ada, `${lab.ws('ada')}/file?path=notes/during.txt`, 'saved while generating\n');
        expect(saved.status, saved.text).toBe(200);
        events.push('save answered');
        const files = await ada.send(`${lab.ws('ada')}/files`);
        expect(files.json.entries).toContainEqual(expect.objectContaining({ path: 'notes/during.txt' }));
        events.push('files answered');
        await lab.as('bob');
        events.push('login answered');
        Atomics.store(flags, 0, 1);
        Atomics.notify(flags, 0);
        const generated = await generating;
        expect(generated.status, generated.text).toBe(200);
        expect(generated.json).toMatchObject({ ok: true, platform: 'timesync', files: [], diagnostics: [] });
        expect(events).toEqual(['generation running', 'save answered', 'files answered', 'login answered', 'generate answered']);
        expect(lab.server.workspaces.generators.started).toBe(1);
    });
});
