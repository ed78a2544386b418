import { type Dirent, existsSync, type Stats } from 'node:fs';
import { randomUUID } from 'node:crypto';
import { chmod, lstat, mkdir, readdir, readFile, realpath, rename, rm, stat, writeFile } from 'node:fs/promises';
import path from 'node:path';
import type { WorkspaceEntry } from '@maa/protocol';
import { ConfinedRoot } from './confinement.js';
import { HttpError } from './http-util.js';
import { processAlive } from './process-group.js';
import { walkTree } from './walk.js';

export type { WorkspaceEntry } from '@maa/protocol';

/**
 * Modes of what the API creates, before the user's umask: never writable by others, whatever
 * the umask (a umask of 0 must not open the workspace to every local user).
 */
const NEW_FILE_MODE = 0o664;
const NEW_FOLDER_MODE = 0o775;
const WORLD_WRITABLE = 0o002;

/** The temporary file of a save: `.<name, cut to 64 bytes>.maa-ide-<pid>-<uuid>.tmp` in the file's folder. */
const TEMP_FILE = /^\..+\.maa-ide-(\d+)-[0-9a-f]{8}-[0-9a-f]{4}-[0-9a-f]{4}-[0-9a-f]{4}-[0-9a-f]{12}\.tmp$/;

/**
 * The start of a file name that its temporary file carries (for a person looking at the folder):
 * at most 64 bytes, so that the temporary name stays within NAME_MAX for every name that is.
 */
function tempStem(name: string): string {
    let stem = name;
    while (Buffer.byteLength(stem) > 64) stem = stem.slice(0, -1);
    return stem;
}

/** Names the listing and the app search leave out. */
export function isSkippedName(name: string): boolean {
    return name.startsWith('.') || name === 'node_modules';
}

/** The user's workspace folder: listing and file CRUD, every path confined to it. */
export class Workspace {
    readonly confined: ConfinedRoot;

    constructor(readonly root: string) {
        this.confined = new ConfinedRoot(root, 'the workspace');
    }

    get name(): string {
        return path.basename(this.root);
    }

    /**
     * Every entry, recursively, sorted by path. Hidden entries, node_modules and generated
     * platform folders (holding a `.maa-trace.json`) are left out; symlinks are followed only
     * to files inside the workspace (symlinked folders are not entered, which also rules out cycles).
     */
    async list(): Promise<WorkspaceEntry[]> {
        const realRoot = await realpath(this.root);
        const entries: WorkspaceEntry[] = [];
        const walk = async (dir: string, rel: string): Promise<void> => {
            let names: Dirent[];
            try {
                names = await readdir(dir, { withFileTypes: true });
            } catch {
                return; // vanished or unreadable meanwhile: list what can be listed
            }
            for (const d of names) {
                if (isSkippedName(d.name)) continue;
                const abs = path.join(dir, d.name);
                const relPath = rel ? `${rel}/${d.name}` : d.name;
                if (d.isDirectory()) {
                    if (existsSync(path.join(abs, '.maa-trace.json'))) continue;
                    entries.push({ path: relPath, type: 'directory' });
                    await walk(abs, relPath);
                } else if (d.isFile()) {
                    entries.push({ path: relPath, type: 'file', size: (await stat(abs)).size });
                } else if (d.isSymbolicLink()) {
                    try {
                        const real = await realpath(abs);
                        const s = await stat(real);
                        if (s.isFile() && real.startsWith(realRoot + path.sep)) entries.push({ path: relPath, type: 'file', size: s.size });
                    } catch {
                        // dangling link: not listed
                    }
                }
            }
        };
        await walk(this.root, '');
        return entries.sort((a, b) => (a.path < b.path ? -1 : a.path > b.path ? 1 : 0));
    }

    async read(rel: string): Promise<Buffer> {
        const abs = await this.confined.resolve(rel);
        let s: Stats;
        try {
            s = await stat(abs);
        } catch {
            throw new HttpError(404, `not found: ${rel}`);
        }
        if (!s.isFile()) throw new HttpError(400, `not a file: ${rel}`);
        return readFile(abs);
    }

    /**
     * Writes through a temporary file and a rename, so readers never see half a file. A new file
     * gets the user's umask (and never write access for others); an overwritten one keeps its mode
     * minus write access for others. Hidden paths are refused (403).
     */
    async write(rel: string, content: Buffer): Promise<void> {
        const abs = await this.confined.resolveWritable(rel);
        const existing = await stat(abs).catch(() => undefined);
        if (existing?.isDirectory()) throw new HttpError(409, `a folder exists at ${rel}`);
        try {
            await mkdir(path.dirname(abs), { recursive: true, mode: NEW_FOLDER_MODE });
        } catch (e) {
            throw new HttpError(409, `cannot create the folder of ${rel}: ${(e as NodeJS.ErrnoException).code ?? (e as Error).message}`);
        }
        // A symlinked target (already checked to point inside) is written through, not replaced.
        const target = (await lstat(abs).catch(() => undefined))?.isSymbolicLink() ? await realpath(abs) : abs;
        // A name of its own per write: two saves of one file in the same millisecond must not share it.
        const temp = path.join(path.dirname(target), `.${tempStem(path.basename(target))}.maa-ide-${process.pid}-${randomUUID()}.tmp`);
        try {
            // 'wx': a fresh file, never one (or a symlink) someone put there.
            await writeFile(temp, content, { flag: 'wx', mode: NEW_FILE_MODE });
            if (existing) await chmod(temp, existing.mode & 0o777 & ~WORLD_WRITABLE);
            await rename(temp, target);
        } catch (e) {
            await rm(temp, { force: true });
            throw e;
        }
    }

    async delete(rel: string): Promise<void> {
        const abs = await this.confined.resolveWritable(rel);
        let s: Stats;
        try {
            s = await lstat(abs);
        } catch {
            throw new HttpError(404, `not found: ${rel}`);
        }
        // Folders too (the explorer deletes them); a symlink is removed itself, never its target.
        await rm(abs, { recursive: s.isDirectory(), force: false });
    }

    /**
     * Removes the temporary files of saves that were killed before their rename (run once at
     * start). node_modules is skipped and symlinks are not followed; a temp file of a process that
     * is still running (another maa-ide on the same folder) is left alone. Returns the relative
     * paths removed.
     */
    async removeOrphanTemps(): Promise<string[]> {
        const removed: string[] = [];
        for await (const { dirent, abs, rel } of walkTree(this.root, ({ dirent }) => dirent.name !== 'node_modules')) {
            const pid = dirent.isFile() ? TEMP_FILE.exec(dirent.name)?.[1] : undefined;
            if (pid !== undefined && !processAlive(Number(pid))) {
                await rm(abs, { force: true });
                removed.push(rel);
            }
        }
        return removed;
    }
}
