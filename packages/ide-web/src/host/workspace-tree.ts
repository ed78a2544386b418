/**
 * The workspace as the host's file system provider sees it: the backend's listing
 * (`GET /api/files`) as a tree of paths, answering `stat` and `readdir`, and kept current by the
 * writes and deletes the workbench makes through the provider. Pure (no DOM, no fetch): the
 * provider (file-system.ts) does the requests.
 */
import type { WorkspaceEntry } from '@maa/protocol';

export type EntryType = 'file' | 'directory';

export interface EntryStat {
    readonly type: EntryType;
    readonly size: number;
    /** Bumped on every write through the provider (VS Code compares it to detect changes on disk). */
    readonly mtime: number;
}

/** `a/b/c` → `a/b`; a top-level entry's parent is the root (''). */
function parentOf(path: string): string {
    const slash = path.lastIndexOf('/');
    return slash < 0 ? '' : path.slice(0, slash);
}

function nameOf(path: string): string {
    return path.slice(path.lastIndexOf('/') + 1);
}

/** A path below the root, without leading, trailing or doubled slashes (`/a//b/` → `a/b`). */
export function normalizePath(path: string): string {
    return path
        .split('/')
        .filter((s) => s !== '' && s !== '.')
        .join('/');
}

export class WorkspaceTree {
    private readonly entries = new Map<string, EntryStat>();
    private readonly childrenOf = new Map<string, Set<string>>();
    private clock = 1;

    constructor(listing: readonly WorkspaceEntry[] = []) {
        this.entries.set('', { type: 'directory', size: 0, mtime: 0 });
        this.childrenOf.set('', new Set());
        for (const e of listing) this.add(normalizePath(e.path), e.type, e.size ?? 0, 0);
    }

    stat(path: string): EntryStat | undefined {
        return this.entries.get(normalizePath(path));
    }

    /** The names and types below a directory, sorted by name; undefined for a file or a missing path. */
    readdir(path: string): Array<[string, EntryType]> | undefined {
        const children = this.childrenOf.get(normalizePath(path));
        if (!children) return undefined;
        return [...children].sort().map((child) => [nameOf(child), this.entries.get(child)?.type ?? 'file']);
    }

    /** A file written through the provider: created with its folders, or its size and mtime updated. */
    written(path: string, size: number): EntryStat {
        return this.add(normalizePath(path), 'file', size, this.clock++);
    }

    /** A folder created through the provider (with its parents). */
    created(path: string): void {
        this.add(normalizePath(path), 'directory', 0, this.clock++);
    }

    /** An entry deleted through the provider, with everything below it. */
    removed(path: string): void {
        const p = normalizePath(path);
        for (const child of this.childrenOf.get(p) ?? []) this.removed(child);
        this.entries.delete(p);
        this.childrenOf.delete(p);
        this.childrenOf.get(parentOf(p))?.delete(p);
    }

    private add(path: string, type: EntryType, size: number, mtime: number): EntryStat {
        if (path === '') return this.entries.get('') as EntryStat;
        const parent = parentOf(path);
        if (!this.entries.has(parent)) this.add(parent, 'directory', 0, mtime);
        this.childrenOf.get(parent)?.add(path);
        const stat = { type, size, mtime };
        this.entries.set(path, stat);
        if (type === 'directory' && !this.childrenOf.has(path)) this.childrenOf.set(path, new Set());
        return stat;
    }
}

/**
 * Whether the letters of `pattern` appear in `path` in order, ignoring case and spaces (quick
 * open's relaxed reading); an empty pattern matches every path.
 */
export function matchesPattern(path: string, pattern: string): boolean {
    const wanted = pattern.toLowerCase().replace(/\s+/g, '');
    const text = path.toLowerCase();
    let at = 0;
    for (const ch of wanted) {
        at = text.indexOf(ch, at);
        if (at < 0) return false;
        at++;
    }
    return true;
}
