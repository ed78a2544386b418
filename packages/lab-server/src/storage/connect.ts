// Opens the lab's database: PGlite (PostgreSQL in WebAssembly, in this process) on a data
// directory, or a PostgreSQL server from a DATABASE_URL. Both are reached through node-postgres
// (PGlite ships a node-postgres connection for itself), so one Kysely dialect, one set of queries
// and one migrator serve both.
import { mkdirSync } from 'node:fs';
import path from 'node:path';
import { PGlite } from '@electric-sql/pglite';
import { createPgConfig } from '@electric-sql/pglite/node-postgres';
import { Kysely, Migrator, PostgresDialect } from 'kysely';
import pg from 'pg';
import { lockDataDir } from './data-dir-lock.js';
import { DurableNodeFS } from './durable-nodefs.js';
import { labMigrations } from './migrations/index.js';
import type { Database } from './schema.js';

export type StorageOptions =
    /** PGlite on a data directory (created when missing); the default of `maa-lab serve`. */
    | { dataDir: string; databaseUrl?: undefined }
    /** A PostgreSQL server, e.g. `postgresql://lab@localhost/lab` or with `?host=/run/postgresql`. */
    | { databaseUrl: string; dataDir?: undefined };

export interface OpenDatabase {
    db: Kysely<Database>;
    backend: 'pglite' | 'postgresql';
    close(): Promise<void>;
}

/**
 * The storage a lab server uses: the PostgreSQL server of `DATABASE_URL` when it is set (and not
 * empty), else PGlite on `dataDir`.
 */
export function storageFromEnvironment(env: NodeJS.ProcessEnv, dataDir: string): StorageOptions {
    const url = env['DATABASE_URL']?.trim();
    return url ? { databaseUrl: url } : { dataDir };
}

/** Opens the database and brings its schema up to date (the migrations it has not seen). */
export async function openDatabase(options: StorageOptions): Promise<OpenDatabase> {
    const opened = options.databaseUrl !== undefined ? openPostgres(options.databaseUrl) : await openPglite(options.dataDir);
    try {
        await migrateToLatest(opened.db);
    } catch (error) {
        await opened.close();
        throw error;
    }
    return opened;
}

function openPostgres(databaseUrl: string): OpenDatabase {
    const pool = new pg.Pool({ connectionString: databaseUrl, max: 10 });
    const db = new Kysely<Database>({ dialect: new PostgresDialect({ pool }) });
    return { db, backend: 'postgresql', close: () => db.destroy() };
}

/**
 * The PostgreSQL cluster's folder in a lab's data directory: its own subfolder, since the data
 * directory also holds the lock and the lab's other folders (the students' materialized workspaces).
 */
export const PGLITE_SUBDIR = 'postgres';

async function openPglite(dataDir: string): Promise<OpenDatabase> {
    mkdirSync(dataDir, { recursive: true });
    const unlock = lockDataDir(dataDir);
    let pglite: PGlite;
    try {
        const fs = new DurableNodeFS(path.join(dataDir, PGLITE_SUBDIR));
        pglite = await PGlite.create({ fs, relaxedDurability: false, startParams: durableStartParams() });
    } catch (error) {
        unlock();
        throw error;
    }
    // PGlite is one connection: a pool of one makes Kysely's transactions take turns.
    const pool = new pg.Pool({ ...createPgConfig(pglite), max: 1 });
    const db = new Kysely<Database>({ dialect: new PostgresDialect({ pool }) });
    return {
        db,
        backend: 'pglite',
        close: async () => {
            try {
                await db.destroy();
                await pglite.close();
            } finally {
                unlock();
            }
        },
    };
}

/**
 * PGlite's start parameters without `-F` (PGlite starts PostgreSQL with fsync off) and with
 * fsync on, so a commit syncs the WAL before PGlite acknowledges it (see DurableNodeFS). The WAL
 * is synced with fsync() rather than the default fdatasync(): Emscripten's fdatasync is a stub
 * that does nothing, its fsync reaches the filesystem's stream operation.
 */
export function durableStartParams(): string[] {
    return [...PGlite.defaultStartParams.filter((p) => p !== '-F'), '-c', 'fsync=on', '-c', 'wal_sync_method=fsync'];
}

async function migrateToLatest(db: Kysely<Database>): Promise<void> {
    const { error, results } = await new Migrator({ db, provider: labMigrations }).migrateToLatest();
    if (error) {
        const failed = results?.find((r) => r.status === 'Error')?.migrationName;
        const reason = error instanceof Error ? error.message : String(error);
        throw new Error(`lab storage: the database migration${failed ? ` ${failed}` : ''} failed: ${reason}`, { cause: error });
    }
}
