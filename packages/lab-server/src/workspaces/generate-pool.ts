// Generation off the lab server's event loop (docs/lab.md "Load benchmark"): the students'
// generator runs (generate, a stream test's generation, a simulation's start) go to a small pool
// of worker threads (generate-worker.ts), so saves, file lists and logins are answered while
// generators work. Each thread runs one job at a time (the IDE backend's runGenerateJob: fresh
// language services per run, as in maa-ide); jobs beyond the threads wait in order. A thread that
// crashes rejects its job and is replaced for the next one.
import { availableParallelism } from 'node:os';
import { Worker } from 'node:worker_threads';
import type { GenerateJob, GenerateJobResult, GenerateRunner } from '@maa/ide-server';

/** What the generator thread answers for one job. */
export type GenerateThreadAnswer = { result: GenerateJobResult } | { error: string };

/** The compiled generate-worker.js beside this module (from the sources under test: the one in dist/). */
export function generateWorkerScript(): URL {
    const here = import.meta.url;
    return here.endsWith('.ts') ? new URL('../../dist/workspaces/generate-worker.js', here) : new URL('./generate-worker.js', here);
}

/** The default number of generator threads: one core left for the event loop, at most 4 (each holds its own language services). */
export function defaultGenerateThreads(cores = availableParallelism()): number {
    return Math.max(1, Math.min(4, cores - 1));
}

interface Pending {
    job: GenerateJob;
    resolve(result: GenerateJobResult): void;
    reject(error: Error): void;
}

interface Thread {
    worker: Worker;
    /** the job it runs now */
    current: Pending | undefined;
}

export class GeneratePool {
    private readonly threads: Thread[] = [];
    private readonly waiting: Pending[] = [];
    private closed = false;
    /** how many threads were started (for tests and the log) */
    started = 0;

    /**
     * @param size how many threads at most (default: defaultGenerateThreads())
     * @param spawn starts a thread that answers GenerateJobs with GenerateThreadAnswers (default: generate-worker.js)
     */
    constructor(
        readonly size: number = defaultGenerateThreads(),
        private readonly spawn: () => Worker = () => new Worker(generateWorkerScript()),
    ) {
        if (!Number.isInteger(size) || size < 1) throw new Error(`the generator threads must be a whole number of at least 1, not ${size}`);
    }

    /** Runs one job in a thread (the GenerationService's runner). */
    readonly run: GenerateRunner = (job) => {
        if (this.closed) return Promise.reject(new Error('the lab server is stopping: no more generation'));
        return new Promise<GenerateJobResult>((resolve, reject) => {
            this.waiting.push({ job, resolve, reject });
            this.pump();
        });
    };

    /** Jobs waiting for a free thread (not those running). */
    get queued(): number {
        return this.waiting.length;
    }

    /** Ends the threads (the server's stop); waiting and running jobs are rejected. */
    async close(): Promise<void> {
        this.closed = true;
        const error = new Error('the lab server stopped during the generation');
        for (const pending of this.waiting.splice(0)) pending.reject(error);
        const threads = this.threads.splice(0);
        for (const thread of threads) {
            thread.current?.reject(error);
            thread.current = undefined;
        }
        await Promise.all(threads.map((t) => t.worker.terminate()));
    }

    /** Hands waiting jobs to idle threads, starting threads up to the size. */
    private pump(): void {
        while (this.waiting.length > 0 && !this.closed) {
            const thread = this.threads.find((t) => t.current === undefined) ?? this.startThread();
            if (!thread) return;
            const next = this.waiting.shift() as Pending;
            thread.current = next;
            thread.worker.postMessage(next.job);
        }
    }

    private startThread(): Thread | undefined {
        if (this.threads.length >= this.size) return undefined;
        const thread: Thread = { worker: this.spawn(), current: undefined };
        this.started++;
        thread.worker.on('message', (answer: GenerateThreadAnswer) => {
            const pending = thread.current;
            thread.current = undefined;
            if (pending) {
                if ('error' in answer) pending.reject(new Error(answer.error));
                else pending.resolve(answer.result);
            }
            this.pump();
        });
        const lost = (error: Error): void => {
            const index = this.threads.indexOf(thread);
            if (index < 0) return;
            this.threads.splice(index, 1);
            const pending = thread.current;
            thread.current = undefined;
            pending?.reject(error);
            void thread.worker.terminate();
            this.pump();
        };
        thread.worker.on('error', (e) => lost(new Error(`the generator thread crashed: ${e.message}`)));
        thread.worker.on('exit', (code) => lost(new Error(`the generator thread stopped (exit code ${code})`)));
        this.threads.push(thread);
        return thread;
    }
}
