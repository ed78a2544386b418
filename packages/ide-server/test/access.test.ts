import { existsSync, readFileSync } from 'node:fs';
import path from 'node:path';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import type WebSocket from 'ws';
import { startIdeServer } from '../src/index.js';
import { authFetch, authWebSocket, json, rawRequest, startSite, TEST_TOKEN, type TestSite } from './helpers.js';

/** The HTTP status a WebSocket handshake was answered with (101 when it opened). */
function handshakeStatus(ws: WebSocket): Promise<number> {
    return new Promise((resolve, reject) => {
        ws.once('open', () => {
            ws.close();
            resolve(101);
        });
        ws.once('unexpected-response', (_req, res) => {
            res.resume();
            resolve(res.statusCode ?? 0);
        });
        ws.once('error', (e) => reject(e));
    });
}

const NO_TOKEN = { Authorization: null };
const FILE = 'toast-service/toast/ArmController.arc';

describe('access: Host, Origin and the token', () => {
    let site: TestSite;
    let own: string;
    let original: string;

    beforeAll(async () => {
        site = await startSite();
        own = `127.0.0.1:${site.server.port}`;
        original = readFileSync(path.join(site.workspace, FILE), 'utf8');
    });
    afterAll(() => site.dispose());

    const raw = (p: string, options: Parameters<typeof rawRequest>[2] = {}) => rawRequest(site.server.url, p, options);
    const outDir = () => path.join(site.dir, '.maa-ide-out');
    const simRunning = async () => (await json(await authFetch(site.url('/api/sim/status'))))['running'];

    it('answers the loopback names and the served port', async () => {
        for (const host of [own, `localhost:${site.server.port}`, `LOCALHOST:${site.server.port}`]) {
            const res = await raw('/api/files', { headers: { Host: host } });
            expect(res.status, host).toBe(200);
        }
    });

    it('refuses a foreign Host (DNS rebinding): 403 for reads, saves and simulation starts, nothing written or started', async () => {
        const body = JSON.stringify({ app: 'toast-service/TR.arcapp', platform: 'timesync', mode: 'lockstep' });
        for (const host of [
            `evil.example:${site.server.port}`,
            'evil.example',
            `127.0.0.1:${site.server.port + 1}`,
            `127.0.0.1.evil.example:${site.server.port}`,
            'user@127.0.0.1',
        ]) {
            const attempts = [
                await raw('/', { headers: { Host: host } }),
                await raw('/api/files', { headers: { Host: host } }),
                await raw(`/api/file?path=${encodeURIComponent(FILE)}`, {
                    method: 'PUT',
                    headers: { Host: host },
                    body: 'component Pwned {}',
                }),
                await raw('/api/sim/start', { method: 'POST', headers: { Host: host, 'Content-Type': 'text/plain' }, body }),
            ];
            for (const res of attempts) {
                expect(res.status, `Host ${host}`).toBe(403);
                expect((JSON.parse(res.body) as { error: string }).error).toMatch(/host/i);
            }
        }
        expect(readFileSync(path.join(site.workspace, FILE), 'utf8')).toBe(original);
        expect(existsSync(outDir())).toBe(false);
        expect(await simRunning()).toBe(false);
    });

    it('refuses a foreign Origin (CSRF), with or without the token: nothing generated or started', async () => {
        const generate = JSON.stringify({ app: 'toast-service/TR.arcapp', platform: 'timesync' });
        for (const origin of ['http://evil.example', `http://localhost:${site.server.port}`, `https://${own}`, 'null']) {
            for (const auth of [{}, NO_TOKEN]) {
                for (const p of ['/api/generate', '/api/sim/start']) {
                    const res = await raw(p, {
                        method: 'POST',
                        headers: { ...auth, Origin: origin, 'Content-Type': 'text/plain' },
                        body: generate,
                    });
                    expect(res.status, `${p} from ${origin}`).toBe(403);
                    expect(res.body).toContain('origin');
                }
            }
        }
        expect(existsSync(outDir())).toBe(false);
        expect(await simRunning()).toBe(false);
    });

    it('refuses a cross-site text/plain POST without the token (401) and accepts its own origin with it', async () => {
        const body = JSON.stringify({ app: 'toast-service/TR.arcapp', platform: 'timesync' });
        for (const p of ['/api/generate', '/api/sim/start']) {
            const res = await raw(p, { method: 'POST', headers: { ...NO_TOKEN, 'Content-Type': 'text/plain' }, body });
            expect(res.status, p).toBe(401);
            expect(res.headers['www-authenticate']).toContain('Bearer');
        }
        expect(existsSync(outDir())).toBe(false);
        const ok = await raw('/api/files', { headers: { Origin: `http://${own}` } });
        expect(ok.status).toBe(200);
    });

    it('refuses cross-site and token-less WebSockets to /sim/rosbridge and /sim/viser', async () => {
        for (const p of ['/sim/rosbridge', '/sim/viser']) {
            expect(
                await handshakeStatus(
                    authWebSocket(site.url(p), undefined, { Authorization: `Bearer ${TEST_TOKEN}`, Origin: 'http://evil.example' }),
                ),
                p,
            ).toBe(403);
            expect(await handshakeStatus(authWebSocket(site.url(p), undefined, { Origin: `http://${own}` })), p).toBe(401);
            expect(
                await handshakeStatus(authWebSocket(site.url(p), undefined, { Authorization: 'Bearer wrong-token-0123456789' })),
                p,
            ).toBe(401);
            // Past the checks: no session runs, so the proxy has nowhere to go.
            expect(
                await handshakeStatus(
                    authWebSocket(site.url(p), undefined, { Authorization: `Bearer ${TEST_TOKEN}`, Origin: `http://${own}` }),
                ),
                p,
            ).toBe(502);
        }
    });

    it('turns ?token= into an HttpOnly SameSite=Strict cookie and redirects a page to the URL without it', async () => {
        const res = await raw(`/?open=${encodeURIComponent(FILE)}&token=${TEST_TOKEN}`, { headers: NO_TOKEN });
        expect(res.status).toBe(302);
        expect(res.headers['location']).toBe(`/?open=${encodeURIComponent(FILE)}`);
        const cookie = String(res.headers['set-cookie']);
        expect(cookie).toBe(`maa-ide-token-${site.server.port}=${TEST_TOKEN}; HttpOnly; SameSite=Strict; Path=/`);
        const withCookie = await raw('/api/files', {
            headers: { ...NO_TOKEN, Cookie: `other=1; maa-ide-token-${site.server.port}=${TEST_TOKEN}` },
        });
        expect(withCookie.status).toBe(200);
        // An API request with ?token= is answered (and stores the cookie) without a redirect.
        const api = await raw(`/api/files?token=${TEST_TOKEN}`, { headers: NO_TOKEN });
        expect(api.status).toBe(200);
        expect(String(api.headers['set-cookie'])).toContain(`maa-ide-token-${site.server.port}=`);
    });

    it('refuses a wrong token, a cookie of another port and no token; a browser gets a page that says what to open', async () => {
        expect((await raw(`/api/files?token=${TEST_TOKEN}x`, { headers: NO_TOKEN })).status).toBe(401);
        expect(
            (await raw('/api/files', { headers: { ...NO_TOKEN, Cookie: `maa-ide-token-${site.server.port + 1}=${TEST_TOKEN}` } })).status,
        ).toBe(401);
        expect(
            (await raw('/api/files', { headers: { ...NO_TOKEN, Cookie: `maa-ide-token-${site.server.port}=${TEST_TOKEN.slice(1)}` } }))
                .status,
        ).toBe(401);
        expect((await raw('/api/files', { headers: { Authorization: `Bearer ${TEST_TOKEN.toUpperCase()}` } })).status).toBe(401);
        const page = await raw('/', { headers: { ...NO_TOKEN, Accept: 'text/html,application/xhtml+xml' } });
        expect(page.status).toBe(401);
        expect(page.headers['content-type']).toContain('text/html');
        expect(page.body).toContain('Open the URL that <code>maa-ide</code> printed');
        const api = await raw('/api/files', { headers: NO_TOKEN });
        expect(api.status).toBe(401);
        expect((JSON.parse(api.body) as { error: string }).error).toContain('token');
        for (const p of ['/sim/viser/', '/assets/app.js', '/api/sim/status'])
            expect((await raw(p, { headers: NO_TOKEN })).status, p).toBe(401);
    });

    it('accepts the token as Authorization: Bearer (scripts)', async () => {
        const res = await raw('/api/files', { headers: { Authorization: `Bearer ${TEST_TOKEN}` } });
        expect(res.status).toBe(200);
        expect(res.headers['set-cookie']).toBeUndefined();
    });

    it('makes a new random token per start unless one is given, and refuses weak ones', async () => {
        const tokens: string[] = [];
        for (let i = 0; i < 2; i++) {
            const server = await startIdeServer({ workspace: site.workspace, port: 0, appDir: path.join(site.dir, 'no-app') });
            try {
                expect(server.loginUrl).toBe(`${server.url}?token=${server.token}`);
                expect(server.token).toMatch(/^[A-Za-z0-9_-]{43}$/); // 32 bytes, base64url
                tokens.push(server.token);
                expect((await fetch(`${server.url}api/files`)).status).toBe(401);
                expect((await fetch(`${server.url}api/files`, { headers: { Authorization: `Bearer ${server.token}` } })).status).toBe(200);
            } finally {
                await server.close();
            }
        }
        expect(tokens[0]).not.toBe(tokens[1]);
        await expect(startIdeServer({ workspace: site.workspace, port: 0, token: 'short' })).rejects.toThrow(/at least 16/);
        await expect(startIdeServer({ workspace: site.workspace, port: 0, token: 'has spaces and ; semicolons' })).rejects.toThrow(
            /only letters/,
        );
    });
});

describe('access: the --host it listens on', () => {
    it('prints a loopback URL when it listens on every address, and refuses the wildcard as Host', async () => {
        const site = await startSite({ empty: true, host: '0.0.0.0' });
        try {
            const port = site.server.port;
            expect(site.server.loginUrl).toBe(`http://127.0.0.1:${port}/?token=${TEST_TOKEN}`);
            expect((await rawRequest(site.server.url, '/api/files', { headers: { Host: `127.0.0.1:${port}` } })).status).toBe(200);
            expect((await rawRequest(site.server.url, '/api/files', { headers: { Host: `0.0.0.0:${port}` } })).status).toBe(403);
        } finally {
            await site.dispose();
        }
    });

    it('accepts its own --host name besides the loopback names, and nothing else', async () => {
        const site = await startSite({ empty: true, host: 'localhost' });
        try {
            const port = site.server.port;
            for (const host of [`localhost:${port}`, `127.0.0.1:${port}`])
                expect((await rawRequest(site.server.url, '/api/files', { headers: { Host: host } })).status, host).toBe(200);
            expect((await rawRequest(site.server.url, '/api/files', { headers: { Host: `example.com:${port}` } })).status).toBe(403);
        } finally {
            await site.dispose();
        }
    });
});
