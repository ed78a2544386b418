// The two backends every storage test runs on: PGlite on a temporary data directory, and a real
// PostgreSQL server in a temporary cluster (postgres-cluster.ts) with a database per store.
import { createHash } from 'node:crypto';
import { cpSync, existsSync, mkdirSync, mkdtempSync, readdirSync, readFileSync, renameSync, rmSync } from 'node:fs';
import { createRequire } from 'node:module';
import { tmpdir } from 'node:os';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { PGLITE_SUBDIR } from '../src/storage/connect.js';
import { openLabStore, type StorageOptions } from '../src/storage/index.js';
import { startTemporaryPostgres, type TemporaryPostgres } from './postgres-cluster.js';
import './liftoff.js';

export interface Backend {
    /** Options for a store of its own (a fresh data directory or database each call). */
    freshStorage(): Promise<StorageOptions>;
    /** Stops the server and removes what freshStorage made. */
    dispose(): Promise<void>;
}

export type BackendName = 'pglite' | 'postgresql';
export const BACKENDS: BackendName[] = ['pglite', 'postgresql'];

export async function startBackend(name: BackendName): Promise<Backend & { server?: TemporaryPostgres }> {
    if (name === 'pglite') {
        const root = mkdtempSync(path.join(tmpdir(), 'maa-lab-pglite-'));
        let count = 0;
        return {
            freshStorage: async () => {
                const dataDir = path.join(root, `db${++count}`);
                await copyPgliteTemplate(dataDir);
                return { dataDir };
            },
            dispose: async () => rmSync(root, { recursive: true, force: true }),
        };
    }
    const server = await startTemporaryPostgres();
    let count = 0;
    return {
        server,
        freshStorage: async () => ({ databaseUrl: await server.createDatabase(`lab_test_${++count}`) }),
        dispose: () => server.stop(),
    };
}

/**
 * Makes `dataDir` a PGlite store as a new one is after openLabStore: a copy of a template made
 * once (per PGlite version and migrations) in the temporary folder. PGlite's initdb runs in
 * WebAssembly and costs about 4 s of CPU with Liftoff (test/liftoff.ts); opening a copy costs
 * under one. A missing or stale template is made again; two test files making it at once both
 * make one and the first rename wins. The tests of what opening a new folder does (data-dir-lock,
 * durability, cli-bin) open their own folders.
 */
export async function copyPgliteTemplate(dataDir: string): Promise<void> {
    const template = await pgliteTemplate();
    mkdirSync(dataDir, { recursive: true });
    cpSync(path.join(template, PGLITE_SUBDIR), path.join(dataDir, PGLITE_SUBDIR), { recursive: true });
}

async function pgliteTemplate(): Promise<string> {
    const template = path.join(tmpdir(), `maa-lab-pglite-template-${templateKey()}`);
    if (existsSync(template)) return template; // only ever made by the rename below: complete
    const making = mkdtempSync(path.join(tmpdir(), 'maa-lab-pglite-making-'));
    const store = await openLabStore({ dataDir: making });
    await store.close();
    try {
        renameSync(making, template);
    } catch (error) {
        rmSync(making, { recursive: true, force: true });
        // another test file made it meanwhile
        if (!existsSync(template)) throw error;
    }
    return template;
}

/** PGlite's version and the text of the storage's migrations and connection settings. */
function templateKey(): string {
    const hash = createHash('sha256');
    const pglite = path.dirname(path.dirname(createRequire(import.meta.url).resolve('@electric-sql/pglite')));
    hash.update(readFileSync(path.join(pglite, 'package.json')));
    const storage = fileURLToPath(new URL('../src/storage/', import.meta.url));
    for (const folder of [storage, path.join(storage, 'migrations')])
        for (const name of readdirSync(folder).sort())
            if (name.endsWith('.ts')) hash.update(name).update(readFileSync(path.join(folder, name)));
    return hash.digest('hex').slice(0, 16);
}
