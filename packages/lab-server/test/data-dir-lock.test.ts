// One lab server per PGlite data directory (PGlite itself takes no lock), and how the lab picks
// its storage from the environment.
import { spawn } from 'node:child_process';
import { mkdirSync, mkdtempSync, rmSync, writeFileSync } from 'node:fs';
import { hostname, tmpdir } from 'node:os';
import path from 'node:path';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { lockDataDir } from '../src/storage/data-dir-lock.js';
import { LOCK_FILE, openLabStore, StorageConflictError, storageFromEnvironment } from '../src/storage/index.js';
import './liftoff.js';

let root: string;
let count = 0;
function freshDir(): string {
    const dir = path.join(root, `d${++count}`);
    mkdirSync(dir);
    return dir;
}

/** The process id of a process that has exited. */
function deadPid(): Promise<number> {
    const child = spawn(process.execPath, ['-e', '']);
    return new Promise((resolve, reject) => {
        child.on('error', reject);
        child.on('exit', () => resolve(child.pid!));
    });
}

beforeAll(() => {
    root = mkdtempSync(path.join(tmpdir(), 'maa-lab-lock-'));
});
afterAll(() => rmSync(root, { recursive: true, force: true }));

describe('the data directory lock', () => {
    it('lets one holder in at a time and lets the next in after a release', () => {
        const dir = freshDir();
        const release = lockDataDir(dir);
        expect(() => lockDataDir(dir)).toThrow(StorageConflictError);
        expect(() => lockDataDir(dir)).toThrow(`in use by process ${process.pid}`);
        release();
        lockDataDir(dir)();
    });

    it('takes over the lock of a process that is gone (killed with kill -9) and an unreadable one', async () => {
        const dir = freshDir();
        writeFileSync(path.join(dir, LOCK_FILE), JSON.stringify({ pid: await deadPid(), host: hostname() }));
        const release = lockDataDir(dir);
        expect(() => lockDataDir(dir)).toThrow(StorageConflictError);
        release();
        writeFileSync(path.join(dir, LOCK_FILE), '{"pid": 12');
        lockDataDir(dir)();
    });

    it('respects a lock held on another host (a shared file system)', async () => {
        const dir = freshDir();
        writeFileSync(path.join(dir, LOCK_FILE), JSON.stringify({ pid: await deadPid(), host: `not-${hostname()}` }));
        expect(() => lockDataDir(dir)).toThrow(/in use by process \d+ on not-/);
    });

    it('keeps a second PGlite store off an open data directory', async () => {
        const storage = { dataDir: freshDir() };
        const store = await openLabStore(storage);
        try {
            await expect(openLabStore(storage)).rejects.toBeInstanceOf(StorageConflictError);
        } finally {
            await store.close();
        }
    });
});

describe('storageFromEnvironment', () => {
    it('takes DATABASE_URL when it is set, else the data directory', () => {
        expect(storageFromEnvironment({ DATABASE_URL: 'postgresql://lab@db/lab' }, 'data')).toEqual({
            databaseUrl: 'postgresql://lab@db/lab',
        });
        expect(storageFromEnvironment({}, 'data')).toEqual({ dataDir: 'data' });
        expect(storageFromEnvironment({ DATABASE_URL: '  ' }, 'data')).toEqual({ dataDir: 'data' });
    });
});
