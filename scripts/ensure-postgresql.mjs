#!/usr/bin/env node
// Makes sure Debian's PostgreSQL server programs (initdb, pg_ctl, postgres) are installed for the
// lab server's storage tests, which start a temporary cluster of their own (packages/lab-server/
// test/postgres-cluster.ts). Installs Debian's `postgresql` with apt-get when missing (needs root);
// prints the folder of the programs. Usage: node scripts/ensure-postgresql.mjs
// MAA_POSTGRES_BIN names another folder with initdb and pg_ctl.
import { existsSync, readdirSync } from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { aptInstall } from './apt-install.mjs';

const DEBIAN_ROOT = '/usr/lib/postgresql';

/** The folder with initdb and pg_ctl: MAA_POSTGRES_BIN, else Debian's newest /usr/lib/postgresql/<major>/bin; undefined when none. */
export function findPostgresBin() {
    const candidates = [];
    if (process.env.MAA_POSTGRES_BIN) candidates.push(process.env.MAA_POSTGRES_BIN);
    if (existsSync(DEBIAN_ROOT)) {
        const majors = readdirSync(DEBIAN_ROOT)
            .filter((name) => /^\d+$/.test(name))
            .sort((a, b) => Number(b) - Number(a));
        candidates.push(...majors.map((major) => path.join(DEBIAN_ROOT, major, 'bin')));
    }
    return candidates.find((dir) => existsSync(path.join(dir, 'initdb')) && existsSync(path.join(dir, 'pg_ctl')));
}

export function ensurePostgresql({ quiet = false } = {}) {
    const found = findPostgresBin();
    if (found) return found;
    aptInstall('postgresql', {
        tool: 'ensure-postgresql',
        missing: 'PostgreSQL (initdb, pg_ctl) is missing',
        hint: "Install Debian's PostgreSQL yourself: sudo apt-get install -y postgresql (or set MAA_POSTGRES_BIN to a folder with initdb and pg_ctl).",
        quiet,
    });
    const bin = findPostgresBin();
    if (!bin) throw new Error('ensure-postgresql: apt-get installed postgresql, but initdb and pg_ctl are still missing');
    return bin;
}

if (process.argv[1] && fileURLToPath(import.meta.url) === process.argv[1]) {
    try {
        console.log(ensurePostgresql());
    } catch (error) {
        console.error(error.message);
        process.exit(1);
    }
}
