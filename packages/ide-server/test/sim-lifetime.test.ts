import { chmodSync, existsSync, readFileSync, writeFileSync } from 'node:fs';
import { createServer, type IncomingHttpHeaders, type Server } from 'node:http';
import type { AddressInfo } from 'node:net';
import path from 'node:path';
import { afterAll, afterEach, beforeAll, describe, expect, it } from 'vitest';
import WebSocket, { WebSocketServer } from 'ws';
import { startIdeServer, type IdeServerOptions } from '../src/index.js';
import { processAlive } from '../src/process-group.js';
import { authFetch, BEARER, json, startSite, TEST_TOKEN, until, type TestSite } from './helpers.js';

// Session lifetime and the proxy's contract with maa-sim, with a shell script standing in for
// maa-sim and a WebSocket/HTTP server of the test standing in for its rosbridge and viser.

/** Waits for a file the stand-in writes once it started. */
async function readWhenWritten(file: string): Promise<string> {
    await until(() => existsSync(file) && readFileSync(file, 'utf8').endsWith('\n'), `${file} written`);
    return readFileSync(file, 'utf8').trim();
}

function openWs(url: string, headers: Record<string, string>): Promise<WebSocket> {
    return new Promise((resolve, reject) => {
        const ws = new WebSocket(url.replace(/^http/, 'ws'), { headers });
        ws.once('open', () => resolve(ws));
        ws.once('error', reject);
    });
}

describe('simulation session lifetime and the proxy to maa-sim (stand-in)', () => {
    let upstream: Server;
    let wss: WebSocketServer;
    let upstreamPort: number;
    /** Headers of the last HTTP request and WebSocket handshake the stand-in endpoints got. */
    const seen: { http?: IncomingHttpHeaders; ws?: IncomingHttpHeaders } = {};
    let site: TestSite | undefined;

    beforeAll(async () => {
        upstream = createServer((req, res) => {
            seen.http = req.headers;
            res.writeHead(200, { 'Content-Type': 'text/html' });
            res.end('<title>stand-in viser</title>');
        });
        wss = new WebSocketServer({ server: upstream });
        wss.on('connection', (socket, req) => {
            seen.ws = req.headers;
            socket.send('hello');
        });
        await new Promise<void>((resolve) => upstream.listen(0, '127.0.0.1', resolve));
        upstreamPort = (upstream.address() as AddressInfo).port;
    });
    afterAll(async () => {
        for (const c of wss.clients) c.terminate();
        wss.close();
        await new Promise<void>((resolve) => upstream.close(() => resolve()));
    });
    afterEach(async () => {
        await site?.dispose();
        site = undefined;
    });

    /**
     * A site whose maa-sim is `script` (bash). The stand-in writes its pid (= its process group),
     * what it started and $MAA_SIM_TOKEN to files in the site folder, then prints the ready line.
     */
    async function siteWith(script: string, options: Partial<IdeServerOptions> = {}): Promise<TestSite> {
        const s = await startSite(options);
        const fake = path.join(s.dir, 'fake-maa-sim');
        const ready = `{"event": "ready", "rosbridge": "ws://127.0.0.1:${upstreamPort}", "viser": "http://127.0.0.1:${upstreamPort}"}`;
        writeFileSync(
            fake,
            `#!/bin/bash\necho "$MAA_SIM_TOKEN" > "${s.dir}/token"\necho "\${MAA_IDE_TOKEN:-unset}" > "${s.dir}/ide-token"\n${script}\necho "$$ $CHILD" > "${s.dir}/pids"\necho '${ready}'\nwait\n`,
        );
        chmodSync(fake, 0o755);
        await s.server.close();
        s.server = await startIdeServer({ token: TEST_TOKEN, ...options, workspace: s.workspace, port: 0, maaSim: fake });
        return s;
    }

    const start = async (s: TestSite) => {
        const res = await authFetch(s.url('/api/sim/start'), {
            method: 'POST',
            body: JSON.stringify({ app: 'toast-service/TR.arcapp', platform: 'timesync', mode: 'lockstep' }),
        });
        expect(res.status, await res.clone().text()).toBe(200);
        const [group, child] = (await readWhenWritten(path.join(s.dir, 'pids'))).split(' ').map(Number);
        return { group: group!, child: child! };
    };

    it('proxies with the session token as Bearer, the target as Host, and without Origin or maa-ide cookie', async () => {
        const previous = process.env['MAA_IDE_TOKEN'];
        process.env['MAA_IDE_TOKEN'] = TEST_TOKEN;
        try {
            site = await siteWith('sleep 300 & CHILD=$!');
            await start(site);
        } finally {
            if (previous === undefined) delete process.env['MAA_IDE_TOKEN'];
            else process.env['MAA_IDE_TOKEN'] = previous;
        }
        const sessionToken = readFileSync(path.join(site.dir, 'token'), 'utf8').trim();
        expect(sessionToken).toMatch(/^[A-Za-z0-9_-]{43}$/);
        expect(sessionToken).not.toBe(TEST_TOKEN);
        expect(readFileSync(path.join(site.dir, 'ide-token'), 'utf8').trim()).toBe('unset');

        const own = `http://127.0.0.1:${site.server.port}`;
        const cookie = `maa-ide-token-${site.server.port}=${TEST_TOKEN}`;
        const ws = await openWs(site.url('/sim/rosbridge'), { Origin: own, Cookie: cookie });
        ws.close();
        const page = await fetch(site.url('/sim/viser/index.html'), { headers: { Origin: own, Cookie: cookie } });
        expect(await page.text()).toContain('stand-in viser');
        for (const headers of [seen.ws!, seen.http!]) {
            expect(headers.authorization).toBe(`Bearer ${sessionToken}`);
            expect(headers.host).toBe(`127.0.0.1:${upstreamPort}`);
            expect(headers.origin).toBeUndefined();
            expect(headers.cookie).toBeUndefined();
        }
    });

    it('ends a session whose last client left, after the idle time, with every process of its group', async () => {
        site = await siteWith('sleep 300 & CHILD=$!', { sessionIdleSeconds: 1 });
        const { group, child } = await start(site);
        const ws = await openWs(site.url('/sim/rosbridge'), BEARER);
        // While a client is connected, the idle timer cannot run out (several idle times pass).
        for (let i = 0; i < 30; i++) await new Promise((r) => setTimeout(r, 100));
        expect(processAlive(group)).toBe(true);
        const closed = new Promise((r) => ws.once('close', r));
        ws.close();
        await closed;
        await until(() => !processAlive(group) && !processAlive(child), 'maa-sim and its child are gone');
        const status = await json<{ running: boolean; log: string[] }>(await authFetch(site.url('/api/sim/status')));
        expect(status.running).toBe(false);
        expect(status.log.join('\n')).toContain('no client for 1 s');
    });

    it('keeps a session that an API client polls', async () => {
        site = await siteWith('sleep 300 & CHILD=$!', { sessionIdleSeconds: 5 });
        const { group } = await start(site);
        // Eight seconds of polling, one request after the other: each one starts the idle time again.
        const polling = Date.now() + 8_000;
        while (Date.now() < polling) {
            expect((await json(await authFetch(site.url('/api/sim/status'))))['running']).toBe(true);
            await new Promise((r) => setTimeout(r, 100));
        }
        expect(processAlive(group)).toBe(true);
    });

    it('stops with SIGKILL what ignores SIGTERM, and the groups of descendants that made their own session', async () => {
        // `trap '' TERM` is inherited: the background sleep ignores SIGTERM too. The setsid sleep is
        // in a session and group of its own, as maa-sim's ROS 2 nodes are.
        site = await siteWith(`trap '' TERM\nsleep 300 & CHILD=$!\nsetsid sleep 300 & echo $! > "${'$'}(dirname "$0")/own-session"`, {
            simStopGraceMs: 500,
        });
        const { group, child } = await start(site);
        const ownSession = Number(await readWhenWritten(path.join(site.dir, 'own-session')));
        expect(processAlive(ownSession)).toBe(true);
        const res = await authFetch(site.url('/api/sim/stop'), { method: 'POST' });
        expect(res.status).toBe(200);
        await until(() => !processAlive(group) && !processAlive(child) && !processAlive(ownSession), 'all three processes are gone');
    });
});
