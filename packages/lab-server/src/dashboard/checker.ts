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

/** Checks a folder of model files: by default the language family's checker, loaded on first use. */
export type FolderChecker = (root: string) => Promise<FileDiagnostic[]>;

/** The language server's checker on one model root (its nested `maa.json` folders are roots of their own). */
export const familyChecker: FolderChecker = async (root) => {
    const { checkModelRoots } = await import('@maa/language-server');
    const found = await checkModelRoots([{ root }]);
    return found.map((d) => ({
        file: path.relative(root, d.file).split(path.sep).join('/'),
        line: d.line,
        column: d.column,
        severity: d.severity,
        code: d.code,
        message: d.message,
    }));
};

export class WorkspaceChecker {
    private readonly cache = new Map<number, WorkspaceCheck>();
    /** the check in progress per workspace and fingerprint (a second request waits for it) */
    private readonly running = new Map<string, Promise<WorkspaceCheck>>();
    private queue: Promise<unknown> = Promise.resolve();
    /** how many checks really ran (not answered from the cache): for tests and the log */
    checksRun = 0;

    constructor(
        private readonly store: LabStore,
        private readonly checkFolder: FolderChecker = familyChecker,
    ) {}

    /** The diagnostics of the workspace's current files (from the cache while they are unchanged). */
    async check(workspaceId: number): Promise<WorkspaceCheck> {
        const files = await this.store.listFiles(workspaceId);
        const fingerprint = files
            .map((f) => `${f.path}@${f.revision}`)
            .sort()
            .join(' ');
        const cached = this.cache.get(workspaceId);
        if (cached?.fingerprint === fingerprint) return cached;
        const key = `${workspaceId} ${fingerprint}`;
        let run = this.running.get(key);
        if (!run) {
            run = this.queue.then(() =>
                this.run(
                    workspaceId,
                    fingerprint,
                    files.map((f) => f.path),
                ),
            );
            this.queue = run.catch(() => undefined);
            this.running.set(key, run);
            void run.finally(() => this.running.delete(key)).catch(() => undefined);
        }
        return run;
    }

    private async run(workspaceId: number, fingerprint: string, paths: string[]): Promise<WorkspaceCheck> {
        const root = await mkdtemp(path.join(tmpdir(), 'maa-lab-check-'));
        try {
            for (const p of paths) {
                const file = await this.store.readFile(workspaceId, p);
                if (!file || file.content === null) continue;
                const target = path.join(root, ...p.split('/'));
                await mkdir(path.dirname(target), { recursive: true });
                await writeFile(target, file.content);
            }
            this.checksRun++;
            const diagnostics = await this.checkFolder(root);
            const result: WorkspaceCheck = {
                fingerprint,
                errors: diagnostics.filter((d) => d.severity === 'error').length,
                warnings: diagnostics.filter((d) => d.severity === 'warning').length,
                diagnostics,
            };
            this.cache.set(workspaceId, result);
            return result;
        } finally {
            await rm(root, { recursive: true, force: true });
        }
    }
}
