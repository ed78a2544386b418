import { existsSync } from 'node:fs';
import { randomUUID } from 'node:crypto';
import { lstat, mkdir, readdir, readFile, realpath, rename, rm, stat, writeFile } from 'node:fs/promises';
import path from 'node:path';
import { ConfinedRoot } from './confinement.js';
import { HttpError } from './http-util.js';

export interface WorkspaceEntry {
  path: string;
  type: 'file' | 'directory';
  size?: number;
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
      let names;
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
    let s;
    try {
      s = await stat(abs);
    } catch {
      throw new HttpError(404, `not found: ${rel}`);
    }
    if (!s.isFile()) throw new HttpError(400, `not a file: ${rel}`);
    return readFile(abs);
  }

  /** Writes through a temporary file and a rename, so readers never see half a file. */
  async write(rel: string, content: Buffer): Promise<void> {
    const abs = await this.confined.resolve(rel);
    try {
      if ((await stat(abs)).isDirectory()) throw new HttpError(409, `a folder exists at ${rel}`);
    } catch (e) {
      if (e instanceof HttpError) throw e;
    }
    try {
      await mkdir(path.dirname(abs), { recursive: true });
    } catch (e) {
      throw new HttpError(409, `cannot create the folder of ${rel}: ${(e as NodeJS.ErrnoException).code ?? (e as Error).message}`);
    }
    // A symlinked target (already checked to point inside) is written through, not replaced.
    const target = (await lstat(abs).catch(() => undefined))?.isSymbolicLink() ? await realpath(abs) : abs;
    // A name of its own per write: two saves of one file in the same millisecond must not share it.
    const temp = path.join(path.dirname(target), `.${path.basename(target)}.maa-ide-${process.pid}-${randomUUID()}.tmp`);
    await writeFile(temp, content);
    try {
      await rename(temp, target);
    } catch (e) {
      await rm(temp, { force: true });
      throw e;
    }
  }

  async delete(rel: string): Promise<void> {
    const abs = await this.confined.resolve(rel);
    let s;
    try {
      s = await lstat(abs);
    } catch {
      throw new HttpError(404, `not found: ${rel}`);
    }
    // Folders too (the explorer deletes them); a symlink is removed itself, never its target.
    await rm(abs, { recursive: s.isDirectory(), force: false });
  }
}
