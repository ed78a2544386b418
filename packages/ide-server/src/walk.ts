import type { Dirent } from 'node:fs';
import { readdir } from 'node:fs/promises';
import path from 'node:path';

/** An entry met by `walkTree`: its directory entry, absolute path and path relative to the root (POSIX). */
export interface WalkEntry {
    dirent: Dirent;
    abs: string;
    rel: string;
}

/**
 * Every entry below `root`, depth first, without following symlinks. Folders for which
 * `enter` answers false are yielded but not entered; unreadable folders (vanished meanwhile,
 * no permission) are passed over, so a walk lists what can be listed.
 */
export async function* walkTree(root: string, enter: (entry: WalkEntry) => boolean = () => true): AsyncGenerator<WalkEntry> {
    const pending: Array<{ dir: string; rel: string }> = [{ dir: root, rel: '' }];
    while (pending.length > 0) {
        const { dir, rel } = pending.pop()!;
        let dirents: Dirent[];
        try {
            dirents = await readdir(dir, { withFileTypes: true });
        } catch {
            continue;
        }
        // Pushed in reverse so that folders are entered in the order readdir gave them.
        const folders: Array<{ dir: string; rel: string }> = [];
        for (const dirent of dirents) {
            const entry = { dirent, abs: path.join(dir, dirent.name), rel: rel ? `${rel}/${dirent.name}` : dirent.name };
            yield entry;
            if (dirent.isDirectory() && enter(entry)) folders.push({ dir: entry.abs, rel: entry.rel });
        }
        pending.push(...folders.reverse());
    }
}
