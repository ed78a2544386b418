// A temporary PostgreSQL cluster for the storage tests: initdb in a temporary folder, started with
// pg_ctl on a Unix socket in that folder only (no TCP port, so nothing to collide with), stopped
// and removed after. PostgreSQL refuses to run as root: as root, the folder is given to the
// `postgres` user (Debian's package creates it; `nobody` otherwise) and the programs run as that
// user through runuser. The programs come from scripts/ensure-postgresql.mjs (the test command
// installs them).
import { execFile } from 'node:child_process';
import { chownSync, mkdtempSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import path from 'node:path';
import { promisify } from 'node:util';
import pg from 'pg';
// @ts-expect-error: a plain ES module of the repository's scripts, without type declarations
import { findPostgresBin } from '../../../scripts/ensure-postgresql.mjs';

const run = promisify(execFile);

export interface TemporaryPostgres {
    /** postgresql://lab@/postgres?host=<socket folder> */
    databaseUrl: string;
    /** A database URL for a fresh database of its own (CREATE DATABASE name). */
    createDatabase(name: string): Promise<string>;
    /** Stops the server (`immediate`: no shutdown checkpoint, as after a crash) and starts it again. */
    restart(options: { immediate: boolean }): Promise<void>;
    stop(): Promise<void>;
}

interface RunAs {
    uid: number;
    gid: number;
    user: string;
}

async function serverUser(): Promise<RunAs | undefined> {
    if (typeof process.getuid !== 'function' || process.getuid() !== 0) return undefined;
    for (const user of ['postgres', 'nobody']) {
        try {
            const uid = Number((await run('id', ['-u', user])).stdout.trim());
            const gid = Number((await run('id', ['-g', user])).stdout.trim());
            return { uid, gid, user };
        } catch {
            // no such user: try the next
        }
    }
    throw new Error('running as root, and neither a postgres nor a nobody user exists to run PostgreSQL as');
}

export async function startTemporaryPostgres(): Promise<TemporaryPostgres> {
    const bin: string | undefined = findPostgresBin();
    if (!bin) throw new Error('PostgreSQL is not installed: run `node scripts/ensure-postgresql.mjs` (npm test does)');
    const as = await serverUser();
    const dir = mkdtempSync(path.join(tmpdir(), 'maa-lab-pg-'));
    if (as) chownSync(dir, as.uid, as.gid);
    const data = path.join(dir, 'data');
    // In the cluster's folder: the server's user may not be allowed into the current directory
    // (a checkout under /root), and initdb fails when it cannot resolve it.
    const program = (name: string, args: string[]) =>
        as
            ? run('runuser', ['-u', as.user, '--', path.join(bin, name), ...args], { cwd: dir })
            : run(path.join(bin, name), args, { cwd: dir });
    await program('initdb', ['-D', data, '-U', 'lab', '--auth=trust', '-E', 'UTF8', '--no-sync']);
    // -w: pg_ctl returns once the server accepts connections.
    const options = `-c listen_addresses='' -k ${dir} -c fsync=on`;
    const start = () => program('pg_ctl', ['-D', data, '-l', path.join(dir, 'server.log'), '-w', '-o', options, 'start']);
    await start();
    const url = (database: string) => `postgresql://lab@/${database}?host=${encodeURIComponent(dir)}`;
    let stopped = false;
    return {
        databaseUrl: url('postgres'),
        createDatabase: async (name) => {
            if (!/^[a-z_][a-z0-9_]*$/.test(name)) throw new Error(`not a plain database name: ${name}`);
            const client = new pg.Client({ connectionString: url('postgres') });
            await client.connect();
            try {
                await client.query(`CREATE DATABASE ${name}`);
            } finally {
                await client.end();
            }
            return url(name);
        },
        restart: async ({ immediate }) => {
            await program('pg_ctl', ['-D', data, '-m', immediate ? 'immediate' : 'fast', '-w', 'stop']);
            await start();
        },
        stop: async () => {
            if (stopped) return;
            stopped = true;
            try {
                await program('pg_ctl', ['-D', data, '-m', 'fast', '-w', 'stop']);
            } finally {
                rmSync(dir, { recursive: true, force: true });
            }
        },
    };
}
