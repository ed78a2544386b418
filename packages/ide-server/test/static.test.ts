import { mkdirSync, symlinkSync, writeFileSync } from 'node:fs';
import path from 'node:path';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { authFetch, json, rawGet, rawRequest, startSite, TEST_TOKEN, type TestSite } from './helpers.js';

describe('static serving of the built app', () => {
    let site: TestSite;

    beforeAll(async () => {
        site = await startSite({ empty: true });
        const app = path.join(site.dir, 'app');
        mkdirSync(path.join(app, 'assets'), { recursive: true });
        writeFileSync(path.join(app, 'index.html'), '<!doctype html><title>MAA</title>');
        const files: Record<string, string> = {
            'main-abc123.js': 'export {};',
            'worker.mjs': 'export {};',
            'style.css': 'body{}',
            'm.wasm': '\0asm',
            'data.json': '{}',
            'icon.svg': '<svg/>',
            'font.ttf': 'ttf',
            'font.woff2': 'woff2',
            'blob.bin': 'bin',
            'service-worker-Ab1_c.js': 'self.addEventListener("fetch", () => {});',
        };
        for (const [name, content] of Object.entries(files)) writeFileSync(path.join(app, 'assets', name), content);
        writeFileSync(path.join(site.dir, 'secret.txt'), 'TOP-SECRET-CONTENT');
        symlinkSync(path.join(site.dir, 'secret.txt'), path.join(app, 'leak.txt'));
        await site.server.close();
        const { startIdeServer } = await import('../src/index.js');
        site.server = await startIdeServer({ workspace: site.workspace, port: 0, token: TEST_TOKEN, appDir: app });
    });
    afterAll(() => site.dispose());

    it('serves index.html for / with revalidation', async () => {
        const res = await authFetch(site.url('/'));
        expect(res.status).toBe(200);
        expect(res.headers.get('content-type')).toBe('text/html; charset=utf-8');
        expect(res.headers.get('cache-control')).toBe('no-cache');
        expect(await res.text()).toContain('<title>MAA</title>');
        const again = await authFetch(site.url('/'), { headers: { 'If-None-Match': res.headers.get('etag')! } });
        expect(again.status).toBe(304);
    });

    it.each([
        ['main-abc123.js', 'text/javascript; charset=utf-8'],
        ['worker.mjs', 'text/javascript; charset=utf-8'],
        ['style.css', 'text/css; charset=utf-8'],
        ['m.wasm', 'application/wasm'],
        ['data.json', 'application/json; charset=utf-8'],
        ['icon.svg', 'image/svg+xml'],
        ['font.ttf', 'font/ttf'],
        ['font.woff2', 'font/woff2'],
        ['blob.bin', 'application/octet-stream'],
    ])('serves assets/%s as %s, cached for good', async (name, type) => {
        const res = await authFetch(site.url(`/assets/${name}`));
        expect(res.status).toBe(200);
        expect(res.headers.get('content-type')).toBe(type);
        expect(res.headers.get('cache-control')).toContain('immutable');
    });

    it('answers 404 for missing files, traversal and symlinks leading out; 405 for other methods', async () => {
        expect((await authFetch(site.url('/assets/nope.js'))).status).toBe(404);
        expect((await authFetch(site.url('/leak.txt'))).status).toBe(404);
        // Dot segments are resolved against the root of the URL (never above it), so these miss.
        for (const raw of ['/assets/%2e%2e/%2e%2e/secret.txt', '/../secret.txt', '/assets/..%2f..%2fsecret.txt']) {
            const res = await rawGet(site.server.url, raw);
            expect(res.status, raw).toBeGreaterThanOrEqual(400);
            expect(res.body, raw).not.toContain('TOP-SECRET-CONTENT');
        }
        const post = await authFetch(site.url('/'), { method: 'POST' });
        expect(post.status).toBe(405);
        expect((await json(post))['error']).toContain('POST');
    });

    it("serves VS Code's webview service worker script without the token, and nothing else (docs/ide.md, Access)", async () => {
        const noToken = { Authorization: null };
        const own = `127.0.0.1:${site.server.port}`;
        const worker = await rawRequest(site.server.url, '/assets/service-worker-Ab1_c.js', { headers: noToken });
        expect(worker.status).toBe(200);
        expect(worker.body).toContain('addEventListener');
        // Attacks on the exception: other files, other methods, look-alike names, dot segments, and a foreign Host or Origin.
        const refused: [string, Parameters<typeof rawRequest>[2], number][] = [
            ['/assets/main-abc123.js', { headers: noToken }, 401],
            ['/api/files', { headers: noToken }, 401],
            ['/assets/service-worker-Ab1_c.js', { method: 'POST', headers: noToken }, 401],
            ['/assets/service-worker-Ab1_c.js.map', { headers: noToken }, 401],
            ['/assets/sub/service-worker-Ab1_c.js', { headers: noToken }, 401],
            ['/assets/service-worker-Ab1_c.js/../main-abc123.js', { headers: noToken }, 401],
            ['/assets/service-worker-%2e%2e/../../api/files', { headers: noToken }, 401],
            ['/assets/service-worker-Ab1_c.js', { headers: { ...noToken, Host: 'evil.example:80' } }, 403],
            ['/assets/service-worker-Ab1_c.js', { headers: { ...noToken, Host: own, Origin: 'https://evil.example' } }, 403],
        ];
        for (const [p, options, status] of refused) {
            const res = await rawRequest(site.server.url, p, options);
            expect(res.status, `${options?.method ?? 'GET'} ${p} ${JSON.stringify(options?.headers)}`).toBe(status);
            expect(res.body).not.toContain('export {}');
        }
    });

    it('answers 503 with the build command when the app is not built', async () => {
        const { startIdeServer } = await import('../src/index.js');
        const bare = await startIdeServer({
            workspace: site.workspace,
            port: 0,
            token: TEST_TOKEN,
            appDir: path.join(site.dir, 'missing'),
        });
        try {
            const res = await authFetch(new URL('/', bare.url));
            expect(res.status).toBe(503);
            expect(await res.text()).toContain('npm run build -w @maa/ide-web');
            expect((await authFetch(new URL('/api/files', bare.url))).status).toBe(200);
        } finally {
            await bare.close();
        }
    });

    it('answers 502 on /sim/... while no simulation runs', async () => {
        const res = await authFetch(site.url('/sim/viser/'));
        expect(res.status).toBe(502);
        expect((await json(res))['error']).toContain('no simulation session');
        expect(await json(await authFetch(site.url('/api/sim/status')))).toEqual({ running: false, log: [] });
    });
});
