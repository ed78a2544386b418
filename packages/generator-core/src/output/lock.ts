import { linkSync, readFileSync, rmSync, unlinkSync, writeFileSync } from 'node:fs';
import path from 'node:path';
import { OutputWriteError, names, newId } from './layout.js';

/** Whether a process with this id runs (EPERM: it runs as another user). */
export function processAlive(pid: number): boolean {
    if (!Number.isInteger(pid) || pid <= 0) return false;
    try {
        process.kill(pid, 0);
        return true;
    } catch (e) {
        return (e as NodeJS.ErrnoException).code === 'EPERM';
    }
}

/**
 * Takes `<stateDir>/lock` for this process, so that two generations never write into one
 * output root at once (the cleanup of one would delete the other's new version). The lock file
 * appears with its content in one step (written under a temporary name, then hard-linked), so
 * a reader never sees it empty. A lock whose process is gone (killed) is taken over. Returns
 * the release function.
 */
export function acquireLock(stateDir: string): () => void {
    const lock = path.join(stateDir, 'lock');
    const temp = path.join(stateDir, names.tempLock(newId()));
    writeFileSync(temp, `${process.pid}\n`);
    try {
        for (let attempt = 0; ; attempt++) {
            try {
                linkSync(temp, lock);
                return () => rmSync(lock, { force: true });
            } catch (e) {
                if ((e as NodeJS.ErrnoException).code !== 'EEXIST' || attempt > 0) throw e;
            }
            const owner = readOwner(lock);
            if (owner !== undefined && processAlive(owner)) {
                throw new OutputWriteError(
                    lock,
                    `another generation (process ${owner}) is writing this output; run again when it has finished`,
                );
            }
            // Left by a killed run: take it over.
            rmSync(lock, { force: true });
        }
    } finally {
        unlinkSync(temp);
    }
}

function readOwner(lock: string): number | undefined {
    try {
        const pid = Number(readFileSync(lock, 'utf8').trim());
        return Number.isInteger(pid) && pid > 0 ? pid : undefined;
    } catch {
        return undefined;
    }
}
