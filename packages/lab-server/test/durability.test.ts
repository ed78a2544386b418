// Security requirement of the lab (issue 15): no acknowledged save is lost when the server is
// killed with kill -9. A child process (durability-child.ts) acknowledges saves one by one and is
// killed with SIGKILL right after the 100th acknowledgement, in the middle of the 101st save; a
// new store on the same data then has all 100 revisions. PGlite: the data directory is reopened
// by another PGlite (crash recovery from the WAL). PostgreSQL: the client is killed, then the
// server too is stopped in immediate mode (no shutdown checkpoint: crash recovery on restart).
import { type ChildProcess, spawn } from 'node:child_process';
import { mkdtempSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import path from 'node:path';
import { createInterface } from 'node:readline';
import { fileURLToPath } from 'node:url';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { durableFsyncCount } from '../src/storage/durable-nodefs.js';
import { type LabStore, openLabStore, type StorageOptions } from '../src/storage/index.js';
import { BACKENDS, copyPgliteTemplate, startBackend } from './backends.js';
import { DURABLE_LOGIN, DURABLE_PATH, durableContent } from './durability-shared.js';

const here = path.dirname(fileURLToPath(import.meta.url));
const repo = path.resolve(here, '..', '..', '..');
const ACKED = 100;
/** Children still running (a test that failed before the kill), killed after the tests. */
const running = new Set<ChildProcess>();

/** Starts the child on the store and resolves once it has acknowledged ACKED saves and been killed with SIGKILL. */
function saveThenKill(storage: StorageOptions): Promise<{ acked: number; signal: NodeJS.Signals | null; stderr: string }> {
    // vite-node (Vitest's own runner) runs the TypeScript child as it is, like the tests.
    const child: ChildProcess = spawn(
        process.execPath,
        [path.join(repo, 'node_modules', 'vite-node', 'vite-node.mjs'), path.join(here, 'durability-child.ts'), JSON.stringify(storage)],
        {
            cwd: path.join(repo, 'packages', 'lab-server'),
            stdio: ['pipe', 'pipe', 'pipe'],
        },
    );
    running.add(child);
    child.on('exit', () => running.delete(child));
    let acked = 0;
    let stderr = '';
    child.stderr!.on('data', (chunk: Buffer) => {
        stderr += chunk.toString();
    });
    createInterface({ input: child.stdout! }).on('line', (line) => {
        const ack = /^ack (\d+)$/.exec(line);
        // Lines still in the pipe after the kill are not counted: the kill came after ACKED.
        if (!ack || child.killed) return;
        acked = Number(ack[1]);
        if (acked === ACKED) child.kill('SIGKILL');
    });
    return new Promise((resolve, reject) => {
        child.on('error', reject);
        child.on('exit', (_code, signal) => resolve({ acked, signal, stderr }));
    });
}

async function expectAllAcknowledgedSaves(store: LabStore): Promise<void> {
    const student = await store.findUserByLogin(DURABLE_LOGIN);
    expect(student).toBeDefined();
    const course = await store.findCourse('durability');
    const exercise = await store.findExercise(course!.id, 'saves');
    const workspace = await store.workspace(student!.id, exercise!.id);
    const history = await store.history(workspace.id, DURABLE_PATH);
    // The 101st save may or may not have committed before the kill; the first 100 must all be there.
    expect(history.length).toBeGreaterThanOrEqual(ACKED);
    for (let i = 1; i <= ACKED; i++) {
        expect((await store.readFile(workspace.id, DURABLE_PATH, i))?.content, `revision ${i}`).toBe(durableContent(i));
    }
}

describe.each(BACKENDS)('durability on %s', (backendName) => {
    let backend: Awaited<ReturnType<typeof startBackend>>;
    beforeAll(async () => {
        backend = await startBackend(backendName);
    });
    afterAll(async () => {
        for (const child of running) child.kill('SIGKILL');
        await backend?.dispose();
    });

    it(`keeps all ${ACKED} acknowledged saves of a process killed with SIGKILL`, async () => {
        const storage = await backend.freshStorage();
        const run = await saveThenKill(storage);
        expect(run.stderr).not.toMatch(/durability-child:/);
        expect(run).toMatchObject({ acked: ACKED, signal: 'SIGKILL' });
        if (backend.server) await backend.server.restart({ immediate: true });
        const store = await openLabStore(storage);
        try {
            await expectAllAcknowledgedSaves(store);
        } finally {
            await store.close();
        }
    });
});

describe('PGlite durability settings', () => {
    let dataRoot: string;
    beforeAll(() => {
        dataRoot = mkdtempSync(path.join(tmpdir(), 'maa-lab-fsync-'));
    });
    afterAll(() => rmSync(dataRoot, { recursive: true, force: true }));

    it('syncs every commit to the disk (PostgreSQL fsync on, reaching the host file)', async () => {
        await copyPgliteTemplate(path.join(dataRoot, 'fsync'));
        const store = await openLabStore({ dataDir: path.join(dataRoot, 'fsync') });
        try {
            const student = await store.createUser({ login: 'fsync', name: 'F', role: 'student' });
            const before = durableFsyncCount();
            await store.setPasswordHash(student.id, 'h');
            expect(durableFsyncCount()).toBeGreaterThan(before);
        } finally {
            await store.close();
        }
    });
});
