import { existsSync, readdirSync, renameSync, rmSync, rmdirSync } from 'node:fs';
import path from 'node:path';
import { STATE_DIR, isLegacyStaging, ownEntry, rootState } from './layout.js';
import { processAlive } from './lock.js';
import type { Checkpoints, WritePhase } from './pause.js';

/**
 * Brings an output root back to a clean state; the caller holds its lock. Runs before a
 * generation reads anything (phase `recover`: the leftovers of killed runs) and after a commit
 * (phase `cleanup`: the versions it replaced):
 *
 * - a plain platform folder moved aside by an interrupted conversion goes back to its place when
 *   that place is empty (the conversion is rolled back), and is deleted once `<out>/P` is our
 *   link (the conversion had completed; its files live on in the new version);
 * - version folders no platform link points at (staged by a killed run, or replaced), temporary
 *   links and temporary lock files of dead processes are deleted;
 * - staging folders of the earlier writer (`.maa-staging-*` in `<out>`) are deleted: they only
 *   ever held copies. Its `.maa-backup-*` folders are left alone: a run killed while committing
 *   may have left the only copy of a file there.
 *
 * Names that are not ours are never touched.
 */
export function cleanOutputRoot(outRoot: string, phase: WritePhase, checkpoints: Checkpoints): void {
    const stateDir = path.join(outRoot, STATE_DIR);
    if (existsSync(stateDir)) {
        const entries = readdirSync(stateDir).sort();
        for (const name of entries) {
            const own = ownEntry(name);
            if (own?.kind === 'old-folder') restoreOrDrop(outRoot, name, own.platform, phase, checkpoints);
        }
        const current = currentVersions(outRoot);
        for (const name of entries) {
            const own = ownEntry(name);
            const full = path.join(stateDir, name);
            if (own?.kind === 'version' && !current.has(name)) removeTree(full, phase, checkpoints);
            else if (own?.kind === 'temp-link') rmSync(full, { force: true });
            else if (own?.kind === 'temp-lock' && !processAlive(own.pid)) rmSync(full, { force: true });
        }
    }
    for (const name of readdirSync(outRoot)) {
        if (isLegacyStaging(name)) removeTree(path.join(outRoot, name), phase, checkpoints);
    }
    checkpoints.ended(phase);
}

function restoreOrDrop(outRoot: string, name: string, platform: string, phase: WritePhase, checkpoints: Checkpoints): void {
    const old = path.join(outRoot, STATE_DIR, name);
    const state = rootState(outRoot, platform);
    if (state.kind === 'missing') {
        renameSync(old, path.join(outRoot, platform));
        checkpoints.reached(phase);
    } else if (state.kind === 'version' && state.exists) {
        removeTree(old, phase, checkpoints);
    }
    // Anything else (someone created a new folder there meanwhile): keep both, delete nothing.
}

/** The version folders the platform links of `<out>` point at. */
function currentVersions(outRoot: string): Set<string> {
    const current = new Set<string>();
    for (const name of readdirSync(outRoot)) {
        if (name.startsWith('.')) continue;
        const state = rootState(outRoot, name);
        if (state.kind === 'version') current.add(state.version);
    }
    return current;
}

/** Deletes one of our folders entry by entry (a checkpoint each), so a kill can land in between. */
function removeTree(dir: string, phase: WritePhase, checkpoints: Checkpoints): void {
    let entries: string[];
    try {
        entries = readdirSync(dir);
    } catch {
        rmSync(dir, { recursive: true, force: true });
        return;
    }
    for (const e of entries) {
        rmSync(path.join(dir, e), { recursive: true, force: true });
        checkpoints.reached(phase);
    }
    rmdirSync(dir);
}
