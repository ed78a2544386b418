// A workspace's files on disk, for what needs them there (generation, stream tests, the
// simulator): the database's current files written into a folder of their own under the lab's
// data directory, each confined to it; a sync rewrites what changed and removes what was deleted.
import { mkdir, rm, stat, writeFile } from 'node:fs/promises';
import path from 'node:path';
import { HttpError } from '@maa/ide-server/http';
import type { LabStore } from '../storage/index.js';

export class MaterializedFolder {
    /** path → the revision on disk */
    private readonly written = new Map<string, number>();
    private queue: Promise<unknown> = Promise.resolve();

    constructor(
        readonly root: string,
        private readonly store: LabStore,
        private readonly workspaceId: number,
    ) {}

    /** Brings the folder to the database's current files (one sync at a time). */
    sync(): Promise<void> {
        const run = this.queue.then(() => this.run());
        this.queue = run.catch(() => undefined);
        return run;
    }

    /** Removes the folder (the workspace went idle, or the server stops). */
    async remove(): Promise<void> {
        await this.queue;
        this.written.clear();
        await rm(this.root, { recursive: true, force: true });
    }

    private async run(): Promise<void> {
        await mkdir(this.root, { recursive: true, mode: 0o700 });
        const files = await this.store.listFiles(this.workspaceId);
        const current = new Set(files.map((f) => f.path));
        for (const gone of [...this.written.keys()].filter((p) => !current.has(p))) {
            await rm(this.confined(gone), { force: true });
            this.written.delete(gone);
        }
        for (const file of files) {
            if (this.written.get(file.path) === file.revision) continue;
            const saved = await this.store.readFile(this.workspaceId, file.path, file.revision);
            if (saved?.content == null) continue;
            const target = this.confined(file.path);
            // A folder where a file now is (the file a/b became a): it goes.
            if ((await stat(target).catch(() => undefined))?.isDirectory()) await rm(target, { recursive: true });
            try {
                await mkdir(path.dirname(target), { recursive: true });
            } catch {
                throw new HttpError(409, `cannot place ${file.path} on disk: a file is where its folder would be`);
            }
            await writeFile(target, saved.content);
            this.written.set(file.path, file.revision);
        }
    }

    /** The absolute path of a workspace path, which must stay inside the folder. */
    private confined(rel: string): string {
        const target = path.resolve(this.root, ...rel.split('/'));
        if (!target.startsWith(this.root + path.sep)) throw new HttpError(400, `the path ${JSON.stringify(rel)} leaves the workspace`);
        return target;
    }
}
