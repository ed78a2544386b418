import { spawnSync } from 'node:child_process';
import { randomUUID } from 'node:crypto';
import { chmodSync, existsSync, mkdirSync, readFileSync, rmSync, statSync, symlinkSync, writeFileSync } from 'node:fs';
import path from 'node:path';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { authFetch, json, q, repo, startSite, type TestSite } from './helpers.js';

const WORLD_WRITABLE = 0o002;
const mode = (p: string) => statSync(p).mode & 0o777;

describe('workspace writes: hidden paths and file modes', () => {
    let site: TestSite;

    beforeAll(async () => {
        site = await startSite({ empty: true });
        mkdirSync(path.join(site.workspace, '.git', 'hooks'), { recursive: true });
        writeFileSync(path.join(site.workspace, '.git', 'config'), '[core]\n');
        mkdirSync(path.join(site.workspace, 'models'));
        writeFileSync(path.join(site.workspace, 'models', '.env'), 'SECRET=1\n');
        // A link inside the workspace whose target is a hidden folder inside it.
        symlinkSync(path.join(site.workspace, '.git', 'hooks'), path.join(site.workspace, 'hooks'));
        writeFileSync(path.join(site.workspace, '.git', 'hooks', 'pre-commit.sample'), '#!/bin/sh\n');
        symlinkSync(path.join(site.workspace, '.git', 'hooks', 'pre-commit.sample'), path.join(site.workspace, 'pre-commit.arc'));
    });
    afterAll(() => site.dispose());

    const file = (p: string, init?: RequestInit) => authFetch(site.url(`/api/file?${q({ path: p })}`), init);

    it('refuses to write or delete hidden files and folders (403), directly or through a symlink', async () => {
        for (const [method, p] of [
            ['PUT', '.git/hooks/pre-commit'],
            ['PUT', '.git/config'],
            ['PUT', '.env'],
            ['PUT', 'models/.env'],
            ['PUT', 'a/.vscode/settings.json'],
            ['PUT', 'hooks/post-checkout'],
            ['PUT', 'pre-commit.arc'],
            ['DELETE', '.git/config'],
            ['DELETE', '.git'],
            ['DELETE', 'models/.env'],
            ['DELETE', 'hooks/x'],
        ] as const) {
            const res = await file(p, { method, body: method === 'PUT' ? '#!/bin/sh\necho pwned\n' : undefined });
            expect(res.status, `${method} ${p}`).toBe(403);
            expect((await json(res))['error']).toContain('hidden');
        }
        expect(existsSync(path.join(site.workspace, '.git', 'hooks', 'pre-commit'))).toBe(false);
        expect(existsSync(path.join(site.workspace, '.git', 'hooks', 'post-checkout'))).toBe(false);
        expect(readFileSync(path.join(site.workspace, '.git', 'config'), 'utf8')).toBe('[core]\n');
        expect(readFileSync(path.join(site.workspace, '.git', 'hooks', 'pre-commit.sample'), 'utf8')).toBe('#!/bin/sh\n');
        expect(existsSync(path.join(site.workspace, '.env'))).toBe(false);
        expect(existsSync(path.join(site.workspace, 'a'))).toBe(false);
        expect(readFileSync(path.join(site.workspace, 'models', '.env'), 'utf8')).toBe('SECRET=1\n');
    });

    it('saves a file whose name is as long as the file system allows, and refuses a longer one with 400', async () => {
        const longest = `${'n'.repeat(251)}.arc`;
        expect((await file(`models/${longest}`, { method: 'PUT', body: 'component N {}\n' })).status).toBe(200);
        expect(readFileSync(path.join(site.workspace, 'models', longest), 'utf8')).toBe('component N {}\n');
        const tooLong = `${'ü'.repeat(130)}.arc`;
        const res = await file(`models/${tooLong}`, { method: 'PUT', body: 'component U {}\n' });
        expect(res.status).toBe(400);
        expect((await json(res))['error']).toContain('too long (264 bytes');
    });

    it('still writes, reads and deletes ordinary paths, including names with inner dots', async () => {
        expect((await file('models/A.v2.arc', { method: 'PUT', body: 'component A {}\n' })).status).toBe(200);
        expect(await (await file('models/A.v2.arc')).text()).toBe('component A {}\n');
        expect((await file('models/A.v2.arc', { method: 'DELETE' })).status).toBe(200);
    });

    it('creates files and folders without write access for others, and keeps an existing file mode minus that', async () => {
        expect((await file('fresh/deeper/New.arc', { method: 'PUT', body: 'component N {}\n' })).status).toBe(200);
        for (const p of ['fresh', 'fresh/deeper', 'fresh/deeper/New.arc']) {
            expect(mode(path.join(site.workspace, p)) & WORLD_WRITABLE, p).toBe(0);
        }
        const script = path.join(site.workspace, 'models', 'run.timesync.py');
        writeFileSync(script, 'print(1)\n');
        chmodSync(script, 0o777);
        expect((await file('models/run.timesync.py', { method: 'PUT', body: 'print(2)\n' })).status).toBe(200);
        expect(mode(script)).toBe(0o775);
        chmodSync(script, 0o640);
        expect((await file('models/run.timesync.py', { method: 'PUT', body: 'print(3)\n' })).status).toBe(200);
        expect(mode(script)).toBe(0o640);
        expect(readFileSync(script, 'utf8')).toBe('print(3)\n');
    });
});

describe('temp files of interrupted saves', () => {
    it('removes orphaned temp files at start, and leaves others alone', async () => {
        // A process that has ended: its pid stands for a maa-ide killed during a save.
        const dead = spawnSync(process.execPath, ['-e', '0']).pid;
        const site = await startSite({ empty: true });
        const ws = site.workspace;
        mkdirSync(path.join(ws, 'models'));
        mkdirSync(path.join(ws, 'node_modules', 'pkg'), { recursive: true });
        const orphan = (dir: string, pid: number) => path.join(ws, dir, `.A.arc.maa-ide-${pid}-${randomUUID()}.tmp`);
        const files = {
            top: orphan('.', dead),
            nested: orphan('models', dead),
            live: orphan('models', process.pid), // a save of a running process (another maa-ide) in flight
            modules: orphan('node_modules/pkg', dead),
            unrelated: path.join(ws, 'models', '.A.arc.tmp'),
            userFile: path.join(ws, 'models', `A.arc.maa-ide-${dead}-${randomUUID()}.tmp`),
        };
        for (const f of Object.values(files)) writeFileSync(f, 'half a save');
        await site.server.close();
        const { startIdeServer } = await import('../src/index.js');
        site.server = await startIdeServer({ workspace: ws, port: 0, token: 'test-token-0123456789abcdef' });
        try {
            expect(existsSync(files.top)).toBe(false);
            expect(existsSync(files.nested)).toBe(false);
            for (const kept of [files.live, files.modules, files.unrelated, files.userFile]) expect(existsSync(kept), kept).toBe(true);
        } finally {
            await site.dispose();
        }
    });
});

describe('error bodies carry no absolute paths', () => {
    let site: TestSite;
    const absolute = () => [site.dir, repo, site.workspace];

    beforeAll(async () => {
        site = await startSite();
    });
    afterAll(() => site.dispose());

    const expectNoPaths = (body: string) => {
        for (const p of absolute()) expect(body).not.toContain(p);
    };

    it('answers an internal error (500) with what failed, not where (the details go to stderr)', async () => {
        // The workspace folder vanishes while maa-ide runs: listing it fails in the file system.
        const other = await startSite({ empty: true });
        try {
            rmSync(other.workspace, { recursive: true });
            const res = await authFetch(other.url('/api/files'));
            const body = await res.text();
            expect(res.status, body).toBe(500);
            expect(JSON.parse(body)).toEqual({ error: "internal error in GET /api/files (details are in maa-ide's log)" });
            for (const p of [other.dir, other.workspace]) expect(body).not.toContain(p);
        } finally {
            await other.dispose();
        }
    });

    it('reports a generation that cannot write its output without the output folder', async () => {
        // The output folder lies below a regular file.
        const blocker = path.join(site.dir, 'blocker');
        writeFileSync(blocker, '');
        await site.server.close();
        const { startIdeServer } = await import('../src/index.js');
        site.server = await startIdeServer({
            workspace: site.workspace,
            port: 0,
            token: 'test-token-0123456789abcdef',
            outDir: path.join(blocker, 'out'),
        });
        const res = await authFetch(site.url('/api/generate'), {
            method: 'POST',
            body: JSON.stringify({ app: 'toast-service/TR.arcapp', platform: 'timesync' }),
        });
        const body = await res.text();
        expect(JSON.parse(body)).toMatchObject({ ok: false });
        expect(body).toContain('<generated>/');
        expectNoPaths(body);
    });

    it('names a missing or broken simulator relative to the installation', async () => {
        const broken = path.join(site.dir, 'not-executable-maa-sim');
        writeFileSync(broken, '#!/bin/sh\n');
        chmodSync(broken, 0o644);
        for (const maaSim of [path.join(site.dir, 'missing-maa-sim'), broken]) {
            await site.server.close();
            const { startIdeServer } = await import('../src/index.js');
            site.server = await startIdeServer({ workspace: site.workspace, port: 0, token: 'test-token-0123456789abcdef', maaSim });
            const res = await authFetch(site.url('/api/sim/start'), {
                method: 'POST',
                body: JSON.stringify({ app: 'toast-service/TR.arcapp', platform: 'timesync', mode: 'lockstep' }),
            });
            const body = await res.text();
            expect(res.status, body).toBe(500);
            expect(body).toContain('maa-sim');
            expectNoPaths(body);
        }
    });

    it('reports paths inside the workspace relative to it', async () => {
        writeFileSync(path.join(site.workspace, 'plain.txt'), 'x');
        const res = await authFetch(site.url(`/api/file?${q({ path: 'plain.txt/below.arc' })}`), { method: 'PUT', body: 'x' });
        const body = await res.text();
        expect(res.status).toBeGreaterThanOrEqual(400);
        expectNoPaths(body);
    });
});
