import { createHash } from 'node:crypto';
import { readFileSync, statSync } from 'node:fs';
import path from 'node:path';
import { mergeProtectedRegions, protectedRegions } from './protected-regions.js';

// The transaction that writes a plan lives in transaction.ts (re-exported here for callers of the writer).
export { OutputTransaction } from './transaction.js';
export { OutputWriteError } from './layout.js';

/** The trace file every generation writes into its output folder. */
export const TRACE_FILE = '.maa-trace.json';

export interface OutputFile {
    /** Relative to the output folder, with `/`. */
    readonly path: string;
    readonly content: string;
    /** Created once, never overwritten. */
    readonly userFile: boolean;
}

export interface WritePlan {
    readonly outDir: string;
    /** Files to write or replace (content after merging protected regions). */
    readonly write: ReadonlyArray<{ path: string; content: string }>;
    /** Generated files that are already up to date. */
    readonly unchanged: readonly string[];
    /** User files that exist and are kept as they are. */
    readonly kept: readonly string[];
    /** Files of the previous generation that this one no longer produces. */
    readonly remove: readonly string[];
    /** Protected regions with user content carried over from existing files. */
    readonly preservedRegions: number;
    /** Generated files whose user content in protected regions the new text has no region for. */
    readonly droppedRegions: ReadonlyArray<{ path: string; regions: string[] }>;
    /** Files of the previous generation no longer produced but kept: they hold user content in protected regions. */
    readonly keptStale: readonly string[];
}

/** What the previous trace file says about generated files (for stale-file removal). */
interface PreviousTrace {
    files?: Array<{ path?: unknown; userFile?: unknown }>;
}

export function sha256(text: string): string {
    return createHash('sha256').update(text, 'utf8').digest('hex');
}

/**
 * Decides what writing `files` into `outDir` means, without touching anything: generated
 * files get the user's protected regions of the existing file; existing user files are kept;
 * files the previous generation (per its trace file) produced and this one does not are
 * removed. Files that are neither (e.g. a build folder) are never touched.
 */
export function planOutput(outDir: string, files: readonly OutputFile[], traceFile: string): WritePlan {
    const write: Array<{ path: string; content: string }> = [];
    const unchanged: string[] = [];
    const kept: string[] = [];
    let preservedRegions = 0;
    const droppedRegions: Array<{ path: string; regions: string[] }> = [];
    const all = [...files, { path: TRACE_FILE, content: traceFile, userFile: false }];
    for (const f of all) {
        const target = path.join(outDir, ...f.path.split('/'));
        const existing = readIfFile(target);
        if (f.userFile) {
            if (existing !== undefined) kept.push(f.path);
            else write.push({ path: f.path, content: f.content });
            continue;
        }
        let content = f.content;
        if (existing !== undefined && f.path !== TRACE_FILE) {
            const merged = mergeProtectedRegions(content, existing);
            content = merged.text;
            preservedRegions += merged.kept;
            const lost = merged.dropped.filter((id) => hasContent(protectedRegions(existing).get(id)));
            if (lost.length > 0) droppedRegions.push({ path: f.path, regions: lost });
        }
        if (existing === content) unchanged.push(f.path);
        else write.push({ path: f.path, content });
    }
    const now = new Set(all.map((f) => f.path));
    const remove: string[] = [];
    const keptStale: string[] = [];
    const previous = readIfFile(path.join(outDir, TRACE_FILE));
    if (previous !== undefined) {
        let parsed: PreviousTrace | undefined;
        try {
            parsed = JSON.parse(previous) as PreviousTrace;
        } catch {
            parsed = undefined;
        }
        for (const f of parsed?.files ?? []) {
            if (typeof f.path !== 'string' || f.userFile === true || now.has(f.path)) continue;
            if (!isSafeRelative(f.path)) continue;
            const old = readIfFile(path.join(outDir, ...f.path.split('/')));
            if (old === undefined) continue;
            if ([...protectedRegions(old).values()].some(hasContent)) keptStale.push(f.path);
            else remove.push(f.path);
        }
    }
    return { outDir, write, unchanged, kept, remove: remove.sort(), preservedRegions, droppedRegions, keptStale: keptStale.sort() };
}

function hasContent(lines: readonly string[] | undefined): boolean {
    return (lines ?? []).some((l) => l.trim().length > 0 && !/^\s*(#|\/\/|--|;|\/?\*)\s*(your code here)?\s*$/i.test(l));
}

function isSafeRelative(p: string): boolean {
    return p.length > 0 && !p.startsWith('/') && !p.includes('\\') && !p.split('/').some((s) => s === '..' || s === '');
}

function readIfFile(file: string): string | undefined {
    try {
        if (!statSync(file).isFile()) return undefined;
        return readFileSync(file, 'utf8');
    } catch {
        return undefined;
    }
}
