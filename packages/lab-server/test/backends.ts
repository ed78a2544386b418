// The two backends every storage test runs on: PGlite on a temporary data directory, and a real
// PostgreSQL server in a temporary cluster (postgres-cluster.ts) with a database per store.
import { mkdtempSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import path from 'node:path';
import type { StorageOptions } from '../src/storage/index.js';
import { startTemporaryPostgres, type TemporaryPostgres } from './postgres-cluster.js';

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
            freshStorage: async () => ({ dataDir: path.join(root, `db${++count}`) }),
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
