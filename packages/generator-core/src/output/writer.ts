import { createHash, randomBytes } from 'node:crypto';
import { existsSync, mkdirSync, readFileSync, readdirSync, renameSync, rmSync, rmdirSync, statSync, writeFileSync } from 'node:fs';
import path from 'node:path';
import { mergeProtectedRegions, protectedRegions } from './protected-regions.js';

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

/**
 * Writes planned outputs as one transaction: every file is first staged next to the output
 * folder (same file system), then moved into place by renames; replaced and removed files are
 * moved aside first. If anything fails, every output folder of the transaction is restored
 * to its previous state. A new output folder appears in one rename.
 */
export class OutputTransaction {
    private readonly staged: Array<{ plan: WritePlan; stage: string; backup: string; fresh: boolean }> = [];
    private readonly undo: Array<() => void> = [];

    /** Stages a plan (writes its files to a staging folder; the output folder is not touched). */
    stage(plan: WritePlan): void {
        const parent = path.dirname(path.resolve(plan.outDir));
        mkdirSync(parent, { recursive: true });
        const tag = `${path.basename(plan.outDir)}.${process.pid}.${randomBytes(4).toString('hex')}`;
        const stage = path.join(parent, `.maa-staging-${tag}`);
        const backup = path.join(parent, `.maa-backup-${tag}`);
        const fresh = !existsSync(plan.outDir);
        try {
            mkdirSync(stage);
            for (const f of plan.write) {
                const file = path.join(stage, ...f.path.split('/'));
                mkdirSync(path.dirname(file), { recursive: true });
                writeFileSync(file, f.content);
            }
        } catch (e) {
            rmSync(stage, { recursive: true, force: true });
            this.abort();
            throw e;
        }
        this.staged.push({ plan, stage, backup, fresh });
    }

    /** Moves every staged file into place; on failure restores everything and rethrows. */
    commit(): void {
        try {
            for (const s of this.staged) this.commitOne(s);
        } catch (e) {
            this.rollback();
            throw e;
        } finally {
            for (const s of this.staged) {
                rmSync(s.stage, { recursive: true, force: true });
                rmSync(s.backup, { recursive: true, force: true });
            }
        }
    }

    /** Discards staged files (nothing was moved into place). */
    abort(): void {
        for (const s of this.staged) rmSync(s.stage, { recursive: true, force: true });
        this.staged.length = 0;
    }

    private commitOne(s: { plan: WritePlan; stage: string; backup: string; fresh: boolean }): void {
        const out = s.plan.outDir;
        if (s.fresh) {
            if (existsSync(out)) throw new Error(`output folder ${out} appeared while generating`);
            renameSync(s.stage, out);
            this.undo.push(() => renameSync(out, s.stage));
            return;
        }
        const moveAside = (rel: string): void => {
            const target = path.join(out, ...rel.split('/'));
            if (!existsSync(target)) return;
            const aside = path.join(s.backup, ...rel.split('/'));
            mkdirSync(path.dirname(aside), { recursive: true });
            renameSync(target, aside);
            this.undo.push(() => {
                mkdirSync(path.dirname(target), { recursive: true });
                renameSync(aside, target);
            });
        };
        for (const rel of s.plan.remove) moveAside(rel);
        for (const f of s.plan.write) {
            moveAside(f.path);
            const target = path.join(out, ...f.path.split('/'));
            const created = mkdirs(path.dirname(target));
            this.undo.push(() => {
                for (const d of created.reverse()) tryRmdir(d);
            });
            renameSync(path.join(s.stage, ...f.path.split('/')), target);
            this.undo.push(() => rmSync(target, { force: true }));
        }
        // Folders that removing stale files emptied.
        for (const rel of s.plan.remove) {
            let dir = path.dirname(path.join(out, ...rel.split('/')));
            while (dir.startsWith(out + path.sep) && tryRmdir(dir)) dir = path.dirname(dir);
        }
    }

    private rollback(): void {
        for (const u of this.undo.reverse()) {
            try {
                u();
            } catch {
                // best effort: keep restoring the rest
            }
        }
        this.undo.length = 0;
    }
}

/** Creates missing folders, returning those it created (outermost first). */
function mkdirs(dir: string): string[] {
    const missing: string[] = [];
    for (let d = dir; !existsSync(d); d = path.dirname(d)) missing.unshift(d);
    for (const d of missing) mkdirSync(d);
    return missing;
}

function tryRmdir(dir: string): boolean {
    try {
        if (readdirSync(dir).length > 0) return false;
        rmdirSync(dir);
        return true;
    } catch {
        return false;
    }
}
