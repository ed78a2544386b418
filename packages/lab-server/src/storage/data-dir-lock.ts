// One lab server per PGlite data directory. PGlite takes no lock of its own (two PGlite instances
// on one directory both open it and both write, which corrupts it), so the lab keeps a lock file,
// `maa-lab.lock` with the holder's process id and host, created exclusively. A lock whose process
// is gone (e.g. killed with kill -9) is stale and taken over.
import { closeSync, openSync, readFileSync, unlinkSync, writeSync } from 'node:fs';
import { hostname } from 'node:os';
import path from 'node:path';
import { StorageConflictError } from './types.js';

export const LOCK_FILE = 'maa-lab.lock';

interface LockOwner {
    pid: number;
    host: string;
}

function readOwner(file: string): LockOwner | undefined {
    try {
        const owner = JSON.parse(readFileSync(file, 'utf8')) as Partial<LockOwner>;
        return typeof owner.pid === 'number' && typeof owner.host === 'string' ? { pid: owner.pid, host: owner.host } : undefined;
    } catch {
        return undefined; // missing, or half written by a process that died while writing it
    }
}

function isAlive(pid: number): boolean {
    try {
        process.kill(pid, 0);
        return true;
    } catch (error) {
        // EPERM: the process exists but belongs to someone else
        return (error as NodeJS.ErrnoException).code === 'EPERM';
    }
}

/** Creates the lock file; false when it exists already. */
function tryCreate(file: string, owner: LockOwner): boolean {
    let fd: number;
    try {
        fd = openSync(file, 'wx');
    } catch (error) {
        if ((error as NodeJS.ErrnoException).code === 'EEXIST') return false;
        throw error;
    }
    try {
        writeSync(fd, JSON.stringify(owner));
    } finally {
        closeSync(fd);
    }
    return true;
}

/** Locks the data directory for this process; returns the release function. */
export function lockDataDir(dataDir: string): () => void {
    const file = path.join(dataDir, LOCK_FILE);
    const me: LockOwner = { pid: process.pid, host: hostname() };
    if (!tryCreate(file, me)) {
        const holder = readOwner(file);
        // On another host (a shared file system) a process id says nothing: the lock holds.
        if (holder && (holder.host !== me.host || isAlive(holder.pid))) {
            throw new StorageConflictError(
                `the lab data directory ${dataDir} is in use by process ${holder.pid} on ${holder.host}; ` +
                    `stop that lab server first (or, if it is gone, remove ${file})`,
            );
        }
        unlinkSync(file);
        // Two processes taking over one stale lock at once: only one creates the file again.
        if (!tryCreate(file, me))
            throw new StorageConflictError(`the lab data directory ${dataDir} was locked by another process just now`);
    }
    return () => {
        const holder = readOwner(file);
        if (holder?.pid === me.pid && holder.host === me.host) unlinkSync(file);
    };
}
