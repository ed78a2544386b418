// The diagnostics of a workspace's current files (docs/lab.md "The instructor's dashboard"): the
// language family's checker (`maa-gen check`'s checkModelRoots) runs in-process on a temporary
// copy of the files. Results are cached per workspace by its files' revisions, so refreshing a
// dashboard of 30 students re-checks only the workspaces that changed; checks run one at a time
// (the language services are heavy and the machine is shared with the students' simulations).
import { mkdir, mkdtemp, rm, writeFile } from 'node:fs/promises';
import { tmpdir } from 'node:os';
import path from 'node:path';
import type { LabStore } from '../storage/index.js';

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

/**
 * Checks model roots (each an independent scope) and gives each root's diagnostics, files
 * relative to their root; by default the language family's checker, loaded on first use.
 */
export type FolderChecker = (roots: readonly string[]) => Promise<FileDiagnostic[][]>;

/** The language server's checker on the roots in one run (their nested `maa.json` folders are roots of their own). */
export const familyChecker: FolderChecker = async (roots) => {
    const { checkModelRoots } = await import('@maa/language-server');
    const found = await checkModelRoots(roots.map((root) => ({ root })));
    return roots.map((root) =>
        found
            .filter((d) => d.file.startsWith(`${root}${path.sep}`))
            .map((d) => ({
                file: path.relative(root, d.file).split(path.sep).join('/'),
                line: d.line,
                column: d.column,
                severity: d.severity,
                code: d.code,
                message: d.message,
            })),
    );
};

/** A workspace whose files changed since its last check. */
interface Stale {
    workspaceId: number;
    fingerprint: string;
    paths: string[];
}

export class WorkspaceChecker {
    private readonly cache = new Map<number, WorkspaceCheck>();
    /** the check in progress per workspace and fingerprint (a second request waits for it) */
    private readonly running = new Map<string, Promise<WorkspaceCheck>>();
    private queue: Promise<unknown> = Promise.resolve();
    /** how many workspaces were really checked (not answered from the cache): for tests and the log */
    checksRun = 0;

    constructor(
        private readonly store: LabStore,
        private readonly checkRoots: FolderChecker = familyChecker,
    ) {}

    /** The diagnostics of the workspace's current files (from the cache while they are unchanged). */
    async check(workspaceId: number): Promise<WorkspaceCheck> {
        return (await this.checkAll([workspaceId])).get(workspaceId) as WorkspaceCheck;
    }

    /**
     * The diagnostics of each workspace: unchanged ones from the cache, the changed ones checked
     * together in one run of the checker (one set of language services for all of them).
     */
    async checkAll(workspaceIds: readonly number[]): Promise<Map<number, WorkspaceCheck>> {
        const pending = new Map<number, Promise<WorkspaceCheck>>();
        const stale: Stale[] = [];
        for (const workspaceId of workspaceIds) {
            const files = await this.store.listFiles(workspaceId);
            const fingerprint = files
                .map((f) => `${f.path}@${f.revision}`)
                .sort()
                .join(' ');
            const cached = this.cache.get(workspaceId);
            const running = this.running.get(`${workspaceId} ${fingerprint}`);
            if (cached?.fingerprint === fingerprint) pending.set(workspaceId, Promise.resolve(cached));
            else if (running) pending.set(workspaceId, running);
            else stale.push({ workspaceId, fingerprint, paths: files.map((f) => f.path) });
        }
        if (stale.length > 0) {
            const batch = this.queue.then(() => this.run(stale));
            this.queue = batch.catch(() => undefined);
            for (const s of stale) {
                const key = `${s.workspaceId} ${s.fingerprint}`;
                const one = batch.then((checks) => checks.get(s.workspaceId) as WorkspaceCheck);
                this.running.set(key, one);
                pending.set(s.workspaceId, one);
                void one.finally(() => this.running.delete(key)).catch(() => undefined);
            }
        }
        const checks = new Map<number, WorkspaceCheck>();
        for (const [id, check] of pending) checks.set(id, await check);
        return checks;
    }

    private async run(stale: readonly Stale[]): Promise<Map<number, WorkspaceCheck>> {
        const base = await mkdtemp(path.join(tmpdir(), 'maa-lab-check-'));
        try {
            const roots: string[] = [];
            for (const s of stale) {
                const root = path.join(base, String(s.workspaceId));
                await mkdir(root);
                for (const p of s.paths) {
                    const file = await this.store.readFile(s.workspaceId, p);
                    if (!file || file.content === null) continue;
                    const target = path.join(root, ...p.split('/'));
                    await mkdir(path.dirname(target), { recursive: true });
                    await writeFile(target, file.content);
                }
                roots.push(root);
            }
            this.checksRun += stale.length;
            const found = await this.checkRoots(roots);
            const checks = new Map<number, WorkspaceCheck>();
            for (const [i, s] of stale.entries()) {
                const diagnostics = found[i] ?? [];
                const result: WorkspaceCheck = {
                    fingerprint: s.fingerprint,
                    errors: diagnostics.filter((d) => d.severity === 'error').length,
                    warnings: diagnostics.filter((d) => d.severity === 'warning').length,
                    diagnostics,
                };
                this.cache.set(s.workspaceId, result);
                checks.set(s.workspaceId, result);
            }
            return checks;
        } finally {
            await rm(base, { recursive: true, force: true });
        }
    }
}
