import { existsSync, mkdirSync, readdirSync, renameSync, rmSync, rmdirSync, statSync, symlinkSync } from 'node:fs';
import path from 'node:path';
import { cleanOutputRoot } from './cleanup.js';
import { OutputWriteError, STATE_DIR, names, newId, rootState, toWriteError, type RootState } from './layout.js';
import { acquireLock } from './lock.js';
import { Checkpoints } from './pause.js';
import { buildVersion } from './version-builder.js';
import type { WritePlan } from './writer.js';

interface Staged {
    readonly platform: string;
    readonly outDir: string;
    readonly before: RootState;
    readonly version: string;
    readonly tempLink: string;
    readonly id: string;
}

/**
 * Writes planned outputs into one output root `<out>` (platform P in `<out>/P`), atomically per
 * platform as a reader sees it (the layout is described in layout.ts):
 *
 * 1. `open` takes the root's lock and cleans up after killed runs (phase `recover`);
 * 2. `stage` builds each platform's new tree in a new version folder (phase `staging`): the old
 *    tree is not touched, so a kill leaves it as it was;
 * 3. `commit` switches each `<out>/P` with one rename of a new link over it (phase `commit`);
 *    a failure switches the platforms already switched back;
 * 4. the replaced versions are deleted (phase `cleanup`); a kill here leaves only hidden
 *    leftovers, which the next `open` deletes.
 *
 * A plain folder at `<out>/P` (written before this layout, or by hand) is converted by its first
 * commit: it is moved into `.maa-gen` and the link takes its place. Between these two renames
 * `<out>/P` is missing; a run killed there is rolled back by the next `open`. Every error is an
 * OutputWriteError naming the path as the user knows it. `close` must always be called.
 */
export class OutputTransaction {
    private readonly stateDir: string;
    private readonly staged: Staged[] = [];
    private readonly checkpoints = new Checkpoints();
    private releaseLock: (() => void) | undefined;
    private createdRoot = false;
    private committed = false;

    private constructor(readonly outRoot: string) {
        this.stateDir = path.join(outRoot, STATE_DIR);
    }

    /** Locks `outRoot` (creating it) and cleans up leftovers of earlier runs. */
    static open(outRoot: string): OutputTransaction {
        const tx = new OutputTransaction(path.resolve(outRoot));
        try {
            tx.createdRoot = !existsSync(tx.outRoot);
            if (!tx.createdRoot && !statSync(tx.outRoot).isDirectory())
                throw new OutputWriteError(tx.outRoot, 'is a file where the output folder is needed');
            mkdirSync(tx.stateDir, { recursive: true });
            tx.releaseLock = acquireLock(tx.stateDir);
            cleanOutputRoot(tx.outRoot, 'recover', tx.checkpoints);
        } catch (e) {
            tx.close();
            // The user knows the output folder, not its hidden state folder.
            throw toWriteError(e, tx.outRoot, (p) => (p.startsWith(tx.stateDir) ? tx.outRoot : p));
        }
        return tx;
    }

    /** Builds the plan's new tree beside the current one; nothing visible changes. */
    stage(plan: WritePlan): void {
        const outDir = path.resolve(plan.outDir);
        const platform = path.basename(outDir);
        if (path.dirname(outDir) !== this.outRoot || platform.startsWith('.')) {
            throw new Error(`internal: ${outDir} is not a platform folder of ${this.outRoot}`);
        }
        const shown = (rel: string): string => (rel ? path.join(outDir, ...rel.split('/')) : outDir);
        const before = rootState(this.outRoot, platform);
        if (before.kind === 'other') throw new OutputWriteError(outDir, 'is a file where the platform folder is needed');
        if (before.kind === 'foreign-link') {
            throw new OutputWriteError(
                outDir,
                `is a symbolic link maa-gen did not create (to ${before.target}); remove it or choose another output folder`,
            );
        }
        const current =
            before.kind === 'version' && before.exists
                ? path.join(this.stateDir, before.version)
                : before.kind === 'folder'
                  ? outDir
                  : undefined;
        // Nothing to change: no new version (an unchanged output keeps its files and times).
        if (current !== undefined && plan.write.length === 0 && plan.remove.length === 0) return;
        const id = newId();
        const version = path.join(this.stateDir, names.version(platform, id));
        const staged: Staged = { platform, outDir, before, version, tempLink: path.join(this.stateDir, names.tempLink(id)), id };
        this.staged.push(staged);
        // Errors name the folder the user knows, not the hidden version folder.
        const display = (p: string): string => (p === version || p.startsWith(version + path.sep) ? outDir + p.slice(version.length) : p);
        try {
            mkdirSync(version);
            buildVersion(plan, current, version, this.checkpoints, shown);
            symlinkSync(names.linkTarget(path.basename(version)), staged.tempLink);
        } catch (e) {
            throw toWriteError(e, outDir, display);
        }
    }

    /** Switches every staged platform to its new tree; on failure switches them all back and throws. */
    commit(): void {
        const done: Staged[] = [];
        try {
            for (const s of this.staged) {
                this.switchOne(s);
                done.push(s);
                this.checkpoints.reached('commit');
            }
        } catch (e) {
            for (const s of done.reverse()) this.switchBack(s);
            throw toWriteError(e, this.outRoot);
        }
        this.committed = true;
        this.checkpoints.ended('commit');
        try {
            cleanOutputRoot(this.outRoot, 'cleanup', this.checkpoints);
        } catch {
            // The new output is in place; what is left over is deleted by the next run.
        }
    }

    private switchOne(s: Staged): void {
        if (s.before.kind !== 'folder') {
            // rename(2) replaces a link (or nothing) in one step; it refuses to replace a folder.
            renameSync(s.tempLink, s.outDir);
            return;
        }
        const old = path.join(this.stateDir, names.oldFolder(s.platform, s.id));
        renameSync(s.outDir, old);
        this.checkpoints.reached('commit');
        try {
            renameSync(s.tempLink, s.outDir);
        } catch (e) {
            renameSync(old, s.outDir);
            throw e;
        }
    }

    /** Best effort: puts back what `switchOne` replaced. */
    private switchBack(s: Staged): void {
        try {
            if (s.before.kind === 'folder') {
                rmSync(s.outDir, { force: true });
                renameSync(path.join(this.stateDir, names.oldFolder(s.platform, s.id)), s.outDir);
            } else if (s.before.kind === 'version') {
                const back = path.join(this.stateDir, names.tempLink(newId()));
                symlinkSync(names.linkTarget(s.before.version), back);
                renameSync(back, s.outDir);
            } else {
                rmSync(s.outDir, { force: true });
            }
        } catch {
            // keep switching back the others; the next run's recovery sees what is left
        }
    }

    /** Deletes what was staged but not committed, releases the lock, and removes folders it created for nothing. */
    close(): void {
        if (!this.committed) {
            for (const s of this.staged) {
                rmSync(s.tempLink, { force: true });
                rmSync(s.version, { recursive: true, force: true });
            }
        }
        this.staged.length = 0;
        try {
            this.releaseLock?.();
        } finally {
            this.releaseLock = undefined;
            if (isEmptyDir(this.stateDir) && !this.hasPlatformLinks()) {
                tryRmdir(this.stateDir);
                if (this.createdRoot) tryRmdir(this.outRoot);
            }
        }
    }

    private hasPlatformLinks(): boolean {
        try {
            return readdirSync(this.outRoot).some((n) => !n.startsWith('.') && rootState(this.outRoot, n).kind === 'version');
        } catch {
            return false;
        }
    }
}

function isEmptyDir(dir: string): boolean {
    try {
        return statSync(dir).isDirectory() && readdirSync(dir).length === 0;
    } catch {
        return false;
    }
}

function tryRmdir(dir: string): void {
    try {
        rmdirSync(dir);
    } catch {
        // not empty or gone: leave it
    }
}
