import { chmodSync, writeFileSync } from 'node:fs';
import { createServer, request, type Server } from 'node:http';
import path from 'node:path';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import WebSocket, { WebSocketServer } from 'ws';
import { authFetch, BEARER, startSite, TEST_TOKEN, type TestSite } from './helpers.js';

interface Answer {
    status: number;
    headers: Record<string, string | string[] | undefined>;
    body: string;
}

/** A GET to the test server with the given headers (a Host of our choosing: the browser's `localhost` without resolving it). */
function get(port: number, pathname: string, headers: Record<string, string>): Promise<Answer> {
    return new Promise((resolve, reject) => {
        request({ host: '127.0.0.1', port, path: pathname, headers }, (res) => {
            let body = '';
            res.on('data', (c: Buffer) => {
                body += c.toString();
            });
            res.on('end', () => resolve({ status: res.statusCode ?? 0, headers: res.headers, body }));
        })
            .on('error', reject)
            .end();
    });
}

// The viser page in a frame of another site, a renderer process of its own (src/viser-view.ts,
// issue 18), with a stand-in maa-sim whose viser is a small HTTP and WebSocket server here.
describe("the viser view in a frame of the other loopback name's site", () => {
    let viser: Server;
    let viserPort: number;
    let site: TestSite;
    let port: number;
    const seen: { url: string; authorization?: string; cookie?: string; origin?: string }[] = [];

    beforeAll(async () => {
        viser = createServer((req, res) => {
            seen.push({
                url: req.url ?? '',
                authorization: req.headers.authorization,
                cookie: req.headers.cookie,
                origin: req.headers.origin,
            });
            res.writeHead(200, { 'Content-Type': req.url?.endsWith('.js') ? 'text/javascript' : 'text/html' });
            res.end(req.url?.endsWith('.js') ? 'export {};' : '<!doctype html><title>Viser</title>');
        });
        new WebSocketServer({ server: viser }).on('connection', (ws, req) => {
            seen.push({ url: `ws:${req.url}`, authorization: req.headers.authorization, origin: req.headers.origin });
            ws.send('hello');
        });
        await new Promise<void>((resolve) => viser.listen(0, '127.0.0.1', resolve));
        viserPort = (viser.address() as { port: number }).port;
        site = await startSite();
        const fake = path.join(site.dir, 'fake-maa-sim');
        const ready = JSON.stringify({ event: 'ready', rosbridge: `ws://127.0.0.1:${viserPort}`, viser: `http://127.0.0.1:${viserPort}` });
        writeFileSync(fake, `#!/bin/bash\necho '${ready}'\nexec sleep 120\n`);
        chmodSync(fake, 0o755);
        await site.server.close();
        const { startIdeServer } = await import('../src/index.js');
        site.server = await startIdeServer({ workspace: site.workspace, port: 0, token: TEST_TOKEN, maaSim: fake });
        port = site.server.port;
        const started = await authFetch(site.url('/api/sim/start'), {
            method: 'POST',
            body: JSON.stringify({ app: 'toast-service/TR.arcapp', platform: 'timesync', mode: 'lockstep' }),
        });
        expect(started.status, await started.clone().text()).toBe(200);
    });
    afterAll(async () => {
        await site?.dispose();
        await new Promise<void>((resolve) => viser.close(() => resolve()));
    });

    /** The capability path a frame's request for the viser page is sent to. */
    async function moved(): Promise<URL> {
        const res = await get(port, '/sim/viser/?x=1', { ...BEARER, Host: `127.0.0.1:${port}`, 'Sec-Fetch-Dest': 'iframe' });
        expect(res.status).toBe(302);
        return new URL(String(res.headers.location));
    }

    it("sends a frame's viser page to the other loopback name, below a capability; everything else stays", async () => {
        const to = await moved();
        expect(to.origin).toBe(`http://localhost:${port}`);
        expect(to.pathname).toMatch(/^\/sim\/viser-view\/[\w-]{32,}\/$/);
        expect(to.search).toBe('?x=1');
        const fromLocalhost = await get(port, '/sim/viser/', { ...BEARER, Host: `localhost:${port}`, 'Sec-Fetch-Dest': 'iframe' });
        expect(new URL(String(fromLocalhost.headers.location)).origin).toBe(`http://127.0.0.1:${port}`);
        // not a frame (a script, a tab of its own): proxied where it was asked
        const direct = await get(port, '/sim/viser/', { ...BEARER, Host: `127.0.0.1:${port}` });
        expect(direct.status).toBe(200);
        expect(direct.body).toContain('<title>Viser</title>');
        // the redirect is for those with the token only
        expect((await get(port, '/sim/viser/', { Host: `127.0.0.1:${port}`, 'Sec-Fetch-Dest': 'iframe' })).status).toBe(401);
    });

    it('admits the page, its files and its WebSocket by the capability alone, with the session token to viser and no cookie', async () => {
        const to = await moved();
        const headers = { Host: `localhost:${port}`, Cookie: `maa-ide-token-${port}=${TEST_TOKEN}` };
        const page = await get(port, to.pathname, headers);
        expect(page.status).toBe(200);
        expect(page.body).toContain('<title>Viser</title>');
        const script = await get(port, `${to.pathname}assets/index.js`, { Host: `localhost:${port}`, Origin: `http://localhost:${port}` });
        expect(script.status).toBe(200);
        expect(script.body).toBe('export {};');
        expect(seen.find((s) => s.url === '/assets/index.js')).toMatchObject({ origin: undefined, cookie: undefined });
        expect(seen.find((s) => s.url === '/assets/index.js')?.authorization).toMatch(/^Bearer /);
        expect(seen.find((s) => s.url === '/assets/index.js')?.authorization).not.toContain(TEST_TOKEN);
        // viser's client opens its WebSocket at the page URL without the trailing slash
        const ws = new WebSocket(`ws://127.0.0.1:${port}${to.pathname.replace(/\/$/, '')}`, {
            headers: { Host: `localhost:${port}`, Origin: `http://localhost:${port}` },
        });
        const first = await new Promise<string>((resolve, reject) => {
            ws.once('message', (m) => resolve(String(m)));
            ws.once('error', reject);
        });
        ws.close();
        expect(first).toBe('hello');
        expect(seen.some((s) => s.url === 'ws:/' && s.origin === undefined)).toBe(true);
    });

    it('refuses a wrong capability, a foreign Origin, and anything but the viser proxy', async () => {
        const to = await moved();
        const capability = to.pathname.split('/')[3] ?? '';
        const local = { Host: `localhost:${port}` };
        expect((await get(port, `/sim/viser-view/${capability.slice(0, -1)}x/`, local)).status).toBe(401);
        expect((await get(port, '/sim/viser-view/', local)).status).toBe(401);
        expect((await get(port, to.pathname, { ...local, Origin: 'https://evil.example' })).status).toBe(403);
        expect((await get(port, to.pathname, { Host: 'evil.example' })).status).toBe(403);
        for (const p of [
            `/sim/viser-view/${capability}/../../../api/files`,
            `/api/files?c=${capability}`,
            `/sim/rosbridge/${capability}`,
        ]) {
            expect((await get(port, p, local)).status, p).toBe(401);
        }
    });
});
