import { existsSync, mkdirSync, readFileSync, symlinkSync, writeFileSync } from 'node:fs';
import path from 'node:path';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { authFetch, json, q, rawGet, startSite, type TestSite } from './helpers.js';

describe('workspace file API', () => {
    let site: TestSite;
    let outside: string;

    beforeAll(async () => {
        site = await startSite({ empty: true, maxFileBytes: 64 * 1024 });
        // A folder next to the workspace, and symlinks into it from inside the workspace.
        outside = path.join(site.dir, 'outside');
        mkdirSync(outside);
        writeFileSync(path.join(outside, 'secret.txt'), 'secret');
        symlinkSync(path.join(outside, 'secret.txt'), path.join(site.workspace, 'link-file.txt'));
        symlinkSync(outside, path.join(site.workspace, 'link-dir'));
        symlinkSync(path.join(outside, 'missing.txt'), path.join(site.workspace, 'dangling.txt'));
        mkdirSync(path.join(site.workspace, 'models'));
        writeFileSync(path.join(site.workspace, 'models', 'A.arc'), 'component A {}\n');
        symlinkSync(path.join(site.workspace, 'models', 'A.arc'), path.join(site.workspace, 'alias.arc'));
        mkdirSync(path.join(site.workspace, '.hidden'));
        writeFileSync(path.join(site.workspace, '.hidden', 'x.txt'), 'x');
        mkdirSync(path.join(site.workspace, 'node_modules', 'pkg'), { recursive: true });
        writeFileSync(path.join(site.workspace, 'node_modules', 'pkg', 'index.js'), '');
    });
    afterAll(() => site.dispose());

    const file = (p: string, init?: RequestInit) => authFetch(site.url(`/api/file?${q({ path: p })}`), init);

    it.each([
        ['../x.txt', 400, "'..' segments"],
        ['a/../../x.txt', 400, "'..' segments"],
        ['/etc/passwd', 400, 'absolute path'],
        ['C:/x', 400, 'absolute path'],
        ['a\\b.txt', 400, 'backslash'],
        ['a\0b', 400, 'NUL byte'],
        ['', 400, 'missing query parameter'],
    ])('rejects %j (%i)', async (p, status, message) => {
        for (const method of ['GET', 'PUT', 'DELETE']) {
            const res = await file(p, { method, body: method === 'PUT' ? 'x' : undefined });
            expect(res.status, `${method} ${p}`).toBe(status);
            expect((await json(res))['error']).toContain(message);
        }
    });

    it('takes concurrent saves of one file (the last one wins, none fails)', async () => {
        const bodies = Array.from({ length: 20 }, (_, i) => `component A { /* save ${i} */ }\n`);
        const statuses = await Promise.all(
            bodies.map(async (body) => (await file('models/Concurrent.arc', { method: 'PUT', body })).status),
        );
        expect(
            statuses.every((s) => s >= 200 && s < 300),
            statuses.join(','),
        ).toBe(true);
        expect(bodies).toContain(readFileSync(path.join(site.workspace, 'models', 'Concurrent.arc'), 'utf8'));
        expect((await file('models/Concurrent.arc', { method: 'DELETE' })).status).toBeLessThan(300);
    });

    it('decodes %2e%2e/ before checking it', async () => {
        const res = await authFetch(site.url('/api/file?path=%2e%2e/outside/secret.txt'));
        expect(res.status).toBe(400);
        expect((await json(res))['error']).toContain("'..'");
    });

    it('refuses symlinks that lead outside (read, write, delete, symlinked parent folder, dangling)', async () => {
        for (const [method, p] of [
            ['GET', 'link-file.txt'],
            ['PUT', 'link-file.txt'],
            ['GET', 'link-dir/secret.txt'],
            ['PUT', 'link-dir/new.txt'],
            ['PUT', 'link-dir/deeper/new.txt'],
            ['DELETE', 'link-dir/secret.txt'],
            ['PUT', 'dangling.txt'],
        ] as const) {
            const res = await file(p, { method, body: method === 'PUT' ? 'pwned' : undefined });
            expect(res.status, `${method} ${p}`).toBe(403);
            expect((await json(res))['error']).toContain(p);
        }
        expect(readFileSync(path.join(outside, 'secret.txt'), 'utf8')).toBe('secret');
        expect(existsSync(path.join(outside, 'new.txt'))).toBe(false);
        expect(existsSync(path.join(outside, 'deeper'))).toBe(false);
        expect(existsSync(path.join(outside, 'missing.txt'))).toBe(false);
    });

    it('follows symlinks that stay inside', async () => {
        const res = await file('alias.arc');
        expect(res.status).toBe(200);
        expect(await res.text()).toBe('component A {}\n');
    });

    it('creates, reads, overwrites and deletes a file (missing folders created), deletes a folder', async () => {
        const p = 'new/folder/Ünïcode.arc';
        expect((await file(p)).status).toBe(404);
        let res = await file(p, { method: 'PUT', body: 'component B {}\n' });
        expect(res.status).toBe(200);
        expect(await json(res)).toEqual({ ok: true });
        res = await file(p);
        expect(res.status).toBe(200);
        expect(res.headers.get('content-type')).toBe('text/plain; charset=utf-8');
        expect(await res.text()).toBe('component B {}\n');
        await file(p, { method: 'PUT', body: 'component C {}\n' });
        expect(await (await file(p)).text()).toBe('component C {}\n');
        expect(readFileSync(path.join(site.workspace, 'new', 'folder', 'Ünïcode.arc'), 'utf8')).toBe('component C {}\n');
        res = await file(p, { method: 'DELETE' });
        expect(await json(res)).toEqual({ ok: true });
        expect((await file(p)).status).toBe(404);
        expect((await file(p, { method: 'DELETE' })).status).toBe(404);
        expect((await file('new', { method: 'DELETE' })).status).toBe(200);
        expect(existsSync(path.join(site.workspace, 'new'))).toBe(false);
    });

    it('refuses bodies over the limit (413) and writing onto a folder (409)', async () => {
        const res = await file('big.txt', { method: 'PUT', body: 'x'.repeat(65 * 1024) });
        expect(res.status).toBe(413);
        expect(existsSync(path.join(site.workspace, 'big.txt'))).toBe(false);
        expect((await file('models', { method: 'PUT', body: 'x' })).status).toBe(409);
        expect((await file('models')).status).toBe(400);
    });

    it('lists recursively and sorted, without hidden entries, node_modules or links leading out', async () => {
        const res = await authFetch(site.url('/api/files'));
        expect(res.status).toBe(200);
        const body = await json<{ root: string; entries: Array<{ path: string; type: string; size?: number }> }>(res);
        expect(body.root).toBe('ws');
        expect(body.entries).toEqual([
            { path: 'alias.arc', type: 'file', size: 15 },
            { path: 'models', type: 'directory' },
            { path: 'models/A.arc', type: 'file', size: 15 },
        ]);
    });

    it('answers malformed requests with JSON 4xx and keeps serving', async () => {
        let res = await authFetch(site.url('/api/nothing'));
        expect(res.status).toBe(404);
        expect((await json(res))['error']).toContain('/api/nothing');
        res = await authFetch(site.url('/api/files'), { method: 'POST' });
        expect(res.status).toBe(405);
        expect(res.headers.get('allow')).toContain('GET');
        for (const body of ['{', '[]', '"x"', '{"app": 3}', '{}']) {
            res = await authFetch(site.url('/api/generate'), { method: 'POST', body });
            expect(res.status, body).toBe(400);
            expect(typeof (await json(res))['error']).toBe('string');
        }
        // A raw request with a broken URL.
        expect((await rawGet(site.server.url, '/api/file?path=%E0%A4%A')).status).toBe(404);
        expect((await rawGet(site.server.url, '/api/file?path=%2e%2e%2Fsecret')).status).toBe(400);
        expect((await authFetch(site.url('/api/files'))).status).toBe(200);
    });
});
