// The dashboard's one checker thread, seen from the lab server (docs/lab.md "The instructor's
// dashboard"): started on the first check, kept alive for the next ones, ended by close(). A crash
// of the thread (it exits or throws) rejects the check it was doing; the next check starts a new one.
import { Worker } from 'node:worker_threads';
import type { CheckRequest, CheckResponse, FileDiagnostic, WorkspaceFile } from './checker.js';

/** The compiled check-worker.js beside this module (from the sources under test: the one in dist/). */
export function checkWorkerScript(): URL {
    const here = import.meta.url;
    return here.endsWith('.ts') ? new URL('../../dist/dashboard/check-worker.js', here) : new URL('./check-worker.js', here);
}

interface Job {
    resolve(diagnostics: FileDiagnostic[]): void;
    reject(error: Error): void;
}

export class CheckThread {
    private worker: Worker | undefined;
    private readonly jobs = new Map<number, Job>();
    private nextId = 1;
    private closed = false;
    /** how many threads were started (for tests and the log) */
    started = 0;

    /** @param spawn starts a thread that answers CheckRequests (default: check-worker.js) */
    constructor(private readonly spawn: () => Worker = () => new Worker(checkWorkerScript())) {}

    /** The diagnostics of one workspace's files, checked in the thread. */
    check(files: readonly WorkspaceFile[]): Promise<FileDiagnostic[]> {
        if (this.closed) return Promise.reject(new Error('the dashboard checker is closed'));
        const worker = this.thread();
        const id = this.nextId++;
        return new Promise<FileDiagnostic[]>((resolve, reject) => {
            this.jobs.set(id, { resolve, reject });
            worker.postMessage({ id, files } satisfies CheckRequest);
        });
    }

    /** Ends the thread (the server's close); checks still running are rejected. */
    async close(): Promise<void> {
        this.closed = true;
        const worker = this.worker;
        this.worker = undefined;
        this.failAll(new Error('the dashboard checker was closed'));
        await worker?.terminate();
    }

    private thread(): Worker {
        if (this.worker) return this.worker;
        const worker = this.spawn();
        this.started++;
        worker.on('message', (answer: CheckResponse) => {
            const job = this.jobs.get(answer.id);
            if (!job) return;
            this.jobs.delete(answer.id);
            if ('error' in answer) job.reject(new Error(answer.error));
            else job.resolve(answer.diagnostics);
        });
        const lost = (error: Error): void => {
            if (this.worker !== worker) return;
            this.worker = undefined;
            this.failAll(error);
        };
        worker.on('error', (e) => lost(new Error(`the checker crashed: ${e.message}`)));
        worker.on('exit', (code) => lost(new Error(`the checker stopped (exit code ${code})`)));
        this.worker = worker;
        return worker;
    }

    private failAll(error: Error): void {
        const jobs = [...this.jobs.values()];
        this.jobs.clear();
        for (const job of jobs) job.reject(error);
    }
}
