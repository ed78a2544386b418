// The installed command: bin/maa-lab.js (the built dist) as a child process, with a password
// piped to --password-stdin (the real stdin reader), on the embedded database.
import { spawn } from 'node:child_process';
import { mkdtempSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { afterAll, describe, expect, it } from 'vitest';
import { LIFTOFF_ONLY } from './liftoff.js';

const BIN = fileURLToPath(new URL('../bin/maa-lab.js', import.meta.url));

function run(args: string[], stdin = ''): Promise<{ code: number | null; out: string; err: string }> {
    return new Promise((resolve, reject) => {
        // Liftoff only: the bin's PGlite without V8's optimizing tier (test/liftoff.ts says why)
        const child = spawn(process.execPath, [LIFTOFF_ONLY, BIN, ...args], {
            stdio: ['pipe', 'pipe', 'pipe'],
            env: { ...process.env, DATABASE_URL: '' },
        });
        let out = '';
        let err = '';
        child.stdout.on('data', (c: Buffer) => void (out += c.toString()));
        child.stderr.on('data', (c: Buffer) => void (err += c.toString()));
        child.on('error', reject);
        child.on('close', (code) => resolve({ code, out, err }));
        child.stdin.end(stdin);
    });
}

describe('bin/maa-lab.js', () => {
    const dir = mkdtempSync(path.join(tmpdir(), 'maa-lab-bin-'));
    afterAll(() => rmSync(dir, { recursive: true, force: true }));

    it('prints its help and exits 2 on a usage error', async () => {
        const help = await run(['--help']);
        expect(help.code).toBe(0);
        expect(help.out).toContain('Usage: maa-lab [options] [command]');
        const bad = await run(['users', 'add']);
        expect(bad.code).toBe(2);
        expect(bad.err).toContain("required option '--name <name>' not specified");
    });

    it('reads the first instructor password from a pipe, never printing it', async () => {
        const dataDir = path.join(dir, 'lab-data');
        const added = await run(
            ['users', 'add', 'teacher', '--name', 'T', '--role', 'instructor', '--password-stdin', '--data-dir', dataDir],
            'piped secret password\nnext line\n',
        );
        expect(added.code, added.err).toBe(0);
        expect(added.out + added.err).not.toContain('piped secret password');
        const listed = await run(['users', 'list', '--data-dir', dataDir]);
        expect(listed.out).toBe('teacher\tinstructor\tT\t\n');
        const empty = await run(['users', 'add', 'other', '--name', 'O', '--password-stdin', '--data-dir', dataDir], '');
        expect(empty.code).toBe(1);
        expect(empty.err).toBe('maa-lab: error: the password must have at least 10 characters\n');
    });
});
