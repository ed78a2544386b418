// The diagnostics of a workspace's current files (docs/lab.md "The instructor's dashboard"): the
// language family's checker (`maa-gen check`'s checkModelRoots) runs in a worker thread
// (check-thread.ts), one workspace at a time, so the lab server's event loop stays free for the
// students between and during the checks. Results are cached per workspace by its files'
// revisions, so refreshing a dashboard of 30 students re-checks only the workspaces that changed.
// A dashboard request takes what is ready (states()) and leaves the rest checking; the next poll
// brings it. The polls re-check a workspace at most every `recheckMs` (10 s) after its last
// check: saves in between are coalesced into one check of the files as they are when it runs, so
// the checks take a bounded share of the machine while students save often. What waits for a
// check (check(): one workspace's view, the CSV export) checks at once.
import type { LabStore } from '../storage/index.js';
import { CheckThread } from './check-thread.js';

export interface FileDiagnostic {
    /** the workspace path of the file (`/`-separated) */
    file: string;
    line: number;
    column: number;
    severity: 'error' | 'warning' | 'info' | 'hint';
    code: string;
    message: string;
}

export interface WorkspaceCheck {
    /** the files' revisions the check ran on (`path@revision`, sorted, joined by spaces) */
    fingerprint: string;
    errors: number;
    warnings: number;
    diagnostics: FileDiagnostic[];
}

/** One file of a workspace: its path (`/`-separated) and text. */
export interface WorkspaceFile {
    path: string;
    content: string;
}

/** What the lab server sends the checker thread, and its answer. */
export interface CheckRequest {
    id: number;
    files: readonly WorkspaceFile[];
}
export type CheckResponse = { id: number; diagnostics: FileDiagnostic[] } | { id: number; error: string };

/** Checks one workspace's files and gives their diagnostics (by default in the checker thread). */
export type FilesChecker = (files: readonly WorkspaceFile[]) => Promise<FileDiagnostic[]>;

/** Where a workspace's check stands. */
export interface CheckState {
    /** the latest finished check: of the current files, or of earlier ones while `checking` */
    check: WorkspaceCheck | undefined;
    /** the current files are being checked or wait for their turn */
    checking: boolean;
    /** the check of the current files failed (e.g. the checker crashed); the next request checks again */
    error: string | undefined;
}

/** How often the dashboard's polls re-check one workspace at most (after its last check ended). */
export const RECHECK_MS = 10_000;

export interface CheckerOptions {
    /** a workspace is re-checked by states() at most this long after its last check ended (default RECHECK_MS) */
    recheckMs?: number;
}

/** A check that waits for its workspace's re-check interval (it reads the files when it runs). */
interface DelayedCheck {
    /** the newest fingerprint asked for (names the queued check; run() reads the files as they are then) */
    fingerprint: string;
    promise: Promise<WorkspaceCheck>;
    /** queues it now */
    fire(): void;
    /** drops it (the checker closes) */
    cancel(error: Error): void;
}

export class WorkspaceChecker {
    private readonly cache = new Map<number, WorkspaceCheck>();
    /** the last failed check per workspace (reported once, then checked again) */
    private readonly failed = new Map<number, { fingerprint: string; message: string }>();
    /** the check in progress per workspace and fingerprint (a second request waits for it) */
    private readonly running = new Map<string, Promise<WorkspaceCheck>>();
    /** per workspace: the check waiting for the re-check interval (coalesces the saves meanwhile) */
    private readonly delayed = new Map<number, DelayedCheck>();
    /** per workspace: when its last successful check ended (Date.now()) */
    private readonly lastChecked = new Map<number, number>();
    private queue: Promise<unknown> = Promise.resolve();
    private readonly thread: CheckThread | undefined;
    private readonly checkFiles: FilesChecker;
    private readonly recheckMs: number;
    /** how many workspaces were really checked (not answered from the cache): for tests and the log */
    checksRun = 0;

    /** @param checkFiles the checker (default: the language family's in one worker thread, started on first use) */
    constructor(
        private readonly store: LabStore,
        checkFiles?: FilesChecker,
        options: CheckerOptions = {},
    ) {
        this.recheckMs = options.recheckMs ?? RECHECK_MS;
        if (checkFiles) this.checkFiles = checkFiles;
        else {
            const thread = new CheckThread();
            this.thread = thread;
            this.checkFiles = (files) => thread.check(files);
        }
    }

    /** The diagnostics of the workspace's current files (from the cache while they are unchanged; waits for a check). */
    async check(workspaceId: number): Promise<WorkspaceCheck> {
        const fingerprint = await this.fingerprint(workspaceId);
        const cached = this.cache.get(workspaceId);
        if (cached?.fingerprint === fingerprint) return cached;
        return this.start(workspaceId, fingerprint, true);
    }

    /** The diagnostics of each workspace, waiting for every check (one workspace after the other). */
    async checkAll(workspaceIds: readonly number[]): Promise<Map<number, WorkspaceCheck>> {
        const checks = new Map<number, WorkspaceCheck>();
        for (const id of workspaceIds) checks.set(id, await this.check(id));
        return checks;
    }

    /**
     * Where each workspace's check stands, without waiting: unchanged ones from the cache, changed
     * ones queued for the checker thread (`checking`), a failed check reported once (`error`).
     */
    async states(workspaceIds: readonly number[]): Promise<Map<number, CheckState>> {
        const states = new Map<number, CheckState>();
        for (const id of workspaceIds) {
            const fingerprint = await this.fingerprint(id);
            const cached = this.cache.get(id);
            const failed = this.failed.get(id);
            this.failed.delete(id);
            if (cached?.fingerprint === fingerprint) states.set(id, { check: cached, checking: false, error: undefined });
            else if (failed?.fingerprint === fingerprint) states.set(id, { check: cached, checking: false, error: failed.message });
            else {
                void this.start(id, fingerprint, false).catch(() => undefined);
                states.set(id, { check: cached, checking: true, error: undefined });
            }
        }
        return states;
    }

    /** Each workspace's state after its check finished (waits; a failed check is an `error`). */
    async completeStates(workspaceIds: readonly number[]): Promise<Map<number, CheckState>> {
        const states = new Map<number, CheckState>();
        for (const id of workspaceIds) {
            try {
                states.set(id, { check: await this.check(id), checking: false, error: undefined });
            } catch (e) {
                this.failed.delete(id);
                states.set(id, { check: undefined, checking: false, error: (e as Error).message });
            }
        }
        return states;
    }

    /** Resolves when no check runs or waits (failed ones included). */
    async settled(): Promise<void> {
        while (this.running.size > 0 || this.delayed.size > 0)
            await Promise.allSettled([...this.running.values(), ...[...this.delayed.values()].map((d) => d.promise)]);
    }

    /** Ends the checker thread (the server's close); checks waiting for their interval are dropped. */
    async close(): Promise<void> {
        const error = new Error('the dashboard checker was closed');
        for (const waiting of [...this.delayed.values()]) waiting.cancel(error);
        await this.thread?.close();
    }

    private async fingerprint(workspaceId: number): Promise<string> {
        return fingerprintOf(await this.store.listFiles(workspaceId));
    }

    /**
     * The workspace's check: joins one waiting for its interval (`urgent` queues it now) or one
     * queued for these files; else queues one, after the re-check interval unless `urgent`.
     */
    private start(workspaceId: number, fingerprint: string, urgent: boolean): Promise<WorkspaceCheck> {
        const waiting = this.delayed.get(workspaceId);
        if (waiting) {
            waiting.fingerprint = fingerprint;
            if (urgent) waiting.fire();
            return waiting.promise;
        }
        const wait = urgent ? 0 : (this.lastChecked.get(workspaceId) ?? Number.NEGATIVE_INFINITY) + this.recheckMs - Date.now();
        if (wait > 0 && !this.running.has(`${workspaceId} ${fingerprint}`)) return this.delay(workspaceId, fingerprint, wait);
        return this.enqueue(workspaceId, fingerprint);
    }

    /** A check of the workspace queued after `wait` ms (or when fired), of its files as they are then. */
    private delay(workspaceId: number, fingerprint: string, wait: number): Promise<WorkspaceCheck> {
        let timer: NodeJS.Timeout | undefined;
        const settle = { resolve: (_c: WorkspaceCheck) => {}, reject: (_e: Error) => {} };
        const promise = new Promise<WorkspaceCheck>((resolve, reject) => {
            settle.resolve = resolve;
            settle.reject = reject;
        });
        const leave = (): boolean => {
            clearTimeout(timer);
            if (this.delayed.get(workspaceId) !== check) return false;
            this.delayed.delete(workspaceId);
            return true;
        };
        const check: DelayedCheck = {
            fingerprint,
            promise,
            fire: () => {
                if (leave()) this.enqueue(workspaceId, check.fingerprint).then(settle.resolve, settle.reject);
            },
            cancel: (error) => {
                if (leave()) settle.reject(error);
            },
        };
        this.delayed.set(workspaceId, check);
        timer = setTimeout(check.fire, wait);
        timer.unref();
        return promise;
    }

    /** Queues the workspace's check (one at a time), or joins the one already queued for these files. */
    private enqueue(workspaceId: number, fingerprint: string): Promise<WorkspaceCheck> {
        const key = `${workspaceId} ${fingerprint}`;
        const running = this.running.get(key);
        if (running) return running;
        const one = this.queue.then(() => this.run(workspaceId, fingerprint));
        this.queue = one.catch(() => undefined);
        this.running.set(key, one);
        void one.finally(() => this.running.delete(key)).catch(() => undefined);
        return one;
    }

    private async run(workspaceId: number, queuedAs: string): Promise<WorkspaceCheck> {
        // the files as they are now (a save since queuing is checked too)
        const infos = await this.store.listFiles(workspaceId);
        const fingerprint = fingerprintOf(infos);
        const files: WorkspaceFile[] = [];
        for (const info of infos) {
            const file = await this.store.readFile(workspaceId, info.path);
            if (file && file.content !== null) files.push({ path: info.path, content: file.content });
        }
        this.checksRun++;
        let diagnostics: FileDiagnostic[];
        try {
            diagnostics = await this.checkFiles(files);
        } catch (e) {
            this.failed.set(workspaceId, { fingerprint: queuedAs, message: (e as Error).message });
            throw e;
        }
        const result: WorkspaceCheck = {
            fingerprint,
            errors: diagnostics.filter((d) => d.severity === 'error').length,
            warnings: diagnostics.filter((d) => d.severity === 'warning').length,
            diagnostics,
        };
        this.cache.set(workspaceId, result);
        this.lastChecked.set(workspaceId, Date.now());
        return result;
    }
}

function fingerprintOf(files: readonly { path: string; revision: number }[]): string {
    return files
        .map((f) => `${f.path}@${f.revision}`)
        .sort()
        .join(' ');
}
