// The simulate view's way to the IDE backend, with the real maa-ide (@maa/ide-server's bin):
// the backend's lifecycle under the extension (start, reuse, replace, stop, and no orphan when
// the extension host dies), and the relay that the webview uses, attacked with foreign hosts,
// origins and capabilities while maa-ide keeps its own checks.
import { type ChildProcess, spawn } from 'node:child_process';
import { chmodSync, cpSync, mkdirSync, mkdtempSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { request } from 'node:http';
import { type AddressInfo, createServer } from 'node:net';
import { tmpdir } from 'node:os';
import path from 'node:path';
import { fileURLToPath, pathToFileURL } from 'node:url';
import { build } from 'esbuild';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { IdeBackend, type RunningBackend } from '../src/simulate/backend-process.js';
import { SimRelay } from '../src/simulate/relay.js';

const pkgDir = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..');
const bin = path.resolve(pkgDir, '..', 'ide-server', 'bin', 'maa-ide.js');
const tmp = mkdtempSync(path.join(tmpdir(), 'maa-simulate-'));
const launcher = path.join(tmp, 'out', 'backend-launcher.mjs');
const backendModule = path.join(tmp, 'out', 'backend-process.mjs');
const command = { node: process.execPath, bin };

function workspace(name: string): string {
    const dir = path.join(tmp, name);
    mkdirSync(dir, { recursive: true });
    writeFileSync(path.join(dir, 'A.arc'), 'component A { port in int i; }\n');
    return dir;
}

/** Whether a process exists (signal 0 checks without signalling). */
function alive(pid: number): boolean {
    try {
        process.kill(pid, 0);
        return true;
    } catch {
        return false;
    }
}

/** Resolves once `pid` is gone (a process that is not our child gives no event to wait for). */
async function gone(pid: number): Promise<void> {
    while (alive(pid)) await new Promise((r) => setTimeout(r, 50));
}

interface Answer {
    status: number;
    headers: Record<string, string | string[] | undefined>;
    body: string;
}

/** A raw HTTP request (fetch would not let a test send its own Host header). */
function http(url: string, headers: Record<string, string> = {}, method = 'GET', body?: string): Promise<Answer> {
    return new Promise((resolve, reject) => {
        const req = request(url, { method, headers }, (res) => {
            let body = '';
            res.setEncoding('utf8');
            res.on('data', (c: string) => {
                body += c;
            });
            res.on('end', () => resolve({ status: res.statusCode ?? 0, headers: res.headers, body }));
        });
        req.on('error', reject);
        req.end(body);
    });
}

/** A WebSocket handshake's status line (the upgrade is answered or refused before any frame). */
function upgrade(url: string, headers: Record<string, string>): Promise<string> {
    return new Promise((resolve, reject) => {
        const req = request(url, {
            headers: {
                connection: 'Upgrade',
                upgrade: 'websocket',
                'sec-websocket-version': '13',
                'sec-websocket-key': 'dGhlIHNhbXBsZSBub25jZQ==',
                ...headers,
            },
        });
        req.on('upgrade', (res, socket) => {
            socket.destroy();
            resolve(`${res.statusCode}`);
        });
        req.on('response', (res) => {
            res.resume();
            resolve(`${res.statusCode}`);
        });
        req.on('error', reject);
        req.end();
    });
}

beforeAll(async () => {
    const common = { bundle: true, platform: 'node' as const, format: 'esm' as const, target: 'node20', logLevel: 'warning' as const };
    await build({ ...common, entryPoints: [path.join(pkgDir, 'src', 'simulate', 'backend-launcher.ts')], outfile: launcher });
    await build({ ...common, entryPoints: [path.join(pkgDir, 'src', 'simulate', 'backend-process.ts')], outfile: backendModule });
}, 60_000);

afterAll(() => rmSync(tmp, { recursive: true, force: true }));

describe('the IDE backend under the extension', () => {
    const backend = new IdeBackend(launcher);
    afterAll(() => backend.stop());

    it('starts maa-ide on loopback with a token, reuses it, replaces it for another folder, and stops it', async () => {
        const a = workspace('ws-a');
        const first = await backend.ensure(a, command);
        expect(first.port).toBeGreaterThan(0);
        expect(first.token.length).toBeGreaterThanOrEqual(32);
        const authorized = await http(`http://127.0.0.1:${first.port}/api/apps`, { authorization: `Bearer ${first.token}` });
        expect(authorized.status).toBe(200);
        expect(JSON.parse(authorized.body)).toEqual({ apps: [] });
        expect((await http(`http://127.0.0.1:${first.port}/api/apps`)).status).toBe(401);

        const again = await backend.ensure(a, command);
        expect(again).toBe(first);
        expect(backend.pid).toBe(first.pid);
        // Calls at the same time take turns: one backend for both.
        const c = workspace('ws-concurrent');
        const [one, two] = await Promise.all([backend.ensure(c, command), backend.ensure(c, command)]);
        expect(two.pid).toBe(one.pid);
        expect(alive(first.pid)).toBe(false);

        const b = workspace('ws-b');
        const other = await backend.ensure(b, command);
        expect(other.pid).not.toBe(one.pid);
        expect(alive(one.pid)).toBe(false);
        expect(other.workspace).toBe(b);

        await backend.stop();
        expect(alive(other.pid)).toBe(false);
        expect(backend.pid).toBeUndefined();
        const restarted = await backend.ensure(b, command);
        expect(restarted.pid).not.toBe(other.pid);
        await backend.stop();
    }, 120_000);

    it('reports a backend that cannot start, with its output', async () => {
        const broken = new IdeBackend(launcher);
        await expect(
            broken.ensure(workspace('ws-c'), { node: process.execPath, bin: path.join(tmp, 'no-such-maa-ide.js') }),
        ).rejects.toThrow(/exited .* before it served/);
    }, 60_000);

    it('leaves no orphan when the extension host is killed during a simulation', async () => {
        // A stand-in maa-sim (as maa-ide's own tests use): its pid and its child's, a ready line,
        // and a rosbridge port that accepts connections.
        const listener = createServer((socket) => socket.destroy());
        await new Promise<void>((resolve) => listener.listen(0, '127.0.0.1', resolve));
        const rosbridgePort = (listener.address() as AddressInfo).port;
        const pidsFile = path.join(tmp, 'sim.pids');
        const fakeSim = path.join(tmp, 'fake-maa-sim');
        writeFileSync(
            fakeSim,
            `#!/bin/bash\nsleep 300 &\necho "$$ $!" > "${pidsFile}"\necho '{"event": "ready", "rosbridge": "ws://127.0.0.1:${rosbridgePort}", "viser": null}'\nwait\n`,
        );
        chmodSync(fakeSim, 0o755);
        const ws = workspace('ws-d');
        cpSync(path.join(pkgDir, '..', '..', 'examples', 'toast-service'), path.join(ws, 'toast-service'), { recursive: true });
        const hostScript = path.join(tmp, 'host.mjs');
        writeFileSync(
            hostScript,
            `import { IdeBackend } from ${JSON.stringify(pathToFileURL(backendModule).href)};
const backend = new IdeBackend(${JSON.stringify(launcher)});
const running = await backend.ensure(${JSON.stringify(ws)}, ${JSON.stringify({ ...command, extraArgs: ['--maa-sim', fakeSim] })});
console.log('backend ' + JSON.stringify(running));
setInterval(() => {}, 1000);
`,
        );
        const host: ChildProcess = spawn(process.execPath, [hostScript], { stdio: ['ignore', 'pipe', 'inherit'] });
        try {
            const running = await new Promise<RunningBackend>((resolve, reject) => {
                let out = '';
                host.stdout?.on('data', (c: Buffer) => {
                    out += c.toString();
                    const m = /backend (\{.*\})\n/.exec(out);
                    if (m?.[1]) resolve(JSON.parse(m[1]) as RunningBackend);
                });
                host.once('exit', (code) => reject(new Error(`the host exited (${code}) before the backend served: ${out}`)));
            });
            const started = await http(
                `http://127.0.0.1:${running.port}/api/sim/start`,
                { authorization: `Bearer ${running.token}`, 'content-type': 'application/json' },
                'POST',
                JSON.stringify({ app: 'toast-service/TR.arcapp', platform: 'timesync', mode: 'lockstep' }),
            );
            expect(started.status, started.body).toBe(200);
            const [simPid, sleepPid] = readFileSync(pidsFile, 'utf8').trim().split(' ').map(Number);
            const pids = [running.pid, simPid ?? -1, sleepPid ?? -1];
            for (const pid of pids) expect(alive(pid), String(pid)).toBe(true);
            const hostExit = new Promise((r) => host.once('exit', r));
            host.kill('SIGKILL');
            await hostExit;
            for (const pid of pids) await gone(pid);
            for (const pid of pids) expect(alive(pid)).toBe(false);
        } finally {
            if (host.exitCode === null && host.signalCode === null) host.kill('SIGKILL');
            listener.close();
        }
    }, 180_000);
});

describe('the relay between the webview and the backend', () => {
    const backend = new IdeBackend(launcher);
    let running: RunningBackend;
    let relay: SimRelay;
    let base: URL;
    let port: string;

    beforeAll(async () => {
        running = await backend.ensure(workspace('ws-relay'), command);
        relay = new SimRelay({ port: running.port, token: running.token });
        base = new URL(await relay.base());
        port = base.port;
    }, 120_000);
    afterAll(async () => {
        await relay?.close();
        await backend.stop();
    });

    const webview = 'vscode-webview://1b2c3d4e5f';

    it('relays the webview with its capability to the backend with the token (CORS for the webview only)', async () => {
        const answer = await http(`${base.href}/api/apps`, { origin: webview });
        expect(answer.status).toBe(200);
        expect(JSON.parse(answer.body)).toEqual({ apps: [] });
        expect(answer.headers['access-control-allow-origin']).toBe(webview);
        expect(answer.headers['access-control-allow-credentials']).toBeUndefined();
        const preflight = await http(`${base.href}/api/sim/start`, { origin: webview, 'access-control-request-method': 'POST' }, 'OPTIONS');
        expect(preflight.status).toBe(204);
        expect(preflight.headers['access-control-allow-origin']).toBe(webview);
        // Without Origin (a script of the extension host) and from its own origin (the viser page).
        expect((await http(`${base.href}/api/sim/status`)).status).toBe(200);
        const own = await http(`${base.href}/api/sim/status`, { origin: `http://127.0.0.1:${port}` });
        expect(own.status).toBe(200);
        expect(own.headers['access-control-allow-origin']).toBeUndefined();
    });

    it('keeps the capability in redirects and drops the backend cookie', async () => {
        const answer = await http(`${base.href}/sim/viser`);
        expect(answer.status).toBe(301);
        expect(answer.headers.location).toBe(`${base.pathname}/sim/viser/`);
        expect(answer.headers['set-cookie']).toBeUndefined();
    });

    it("keeps the viser frame's page on the relay (maa-ide moves only frames the browser asks for itself)", async () => {
        // no session runs: maa-ide's own answer, not a redirect to its other loopback name
        const answer = await http(`${base.href}/sim/viser/`, { 'sec-fetch-dest': 'iframe' });
        expect(answer.headers.location).toBeUndefined();
        expect(answer.status).toBe(502);
    });

    it('refuses other origins, hosts and capabilities, for requests and WebSocket upgrades', async () => {
        const origin = `http://127.0.0.1:${port}`;
        for (const evil of [
            'http://evil.example',
            'https://127.0.0.1',
            `http://localhost:${Number(port) + 1}`,
            'null',
            'vscode-webview://x/path',
            `${origin}.evil.example`,
        ]) {
            const answer = await http(`${base.href}/api/apps`, { origin: evil });
            expect(answer.status, evil).toBe(403);
            expect(answer.headers['access-control-allow-origin'], evil).toBeUndefined();
            expect(await upgrade(`${base.href}/sim/rosbridge`, { origin: evil }), evil).toBe('403');
        }
        expect((await http(`${base.href}/api/apps`, { host: `evil.example:${port}` })).status).toBe(403);
        expect((await http(`${base.href}/api/apps`, { host: `127.0.0.1:${running.port}` })).status).toBe(403);
        expect((await http(`http://127.0.0.1:${port}/api/apps`)).status).toBe(404);
        expect((await http(`http://127.0.0.1:${port}/${'A'.repeat(43)}/api/apps`)).status).toBe(404);
        expect((await http(`http://127.0.0.1:${port}/`)).status).toBe(404);
        expect(await upgrade(`http://127.0.0.1:${port}/wrong/sim/rosbridge`, { origin: webview })).toBe('404');
    });

    it('leaves the backend its own checks: the webview origin and a missing token are refused there', async () => {
        const direct = `http://127.0.0.1:${running.port}/api/apps`;
        expect((await http(direct, { origin: webview, authorization: `Bearer ${running.token}` })).status).toBe(403);
        expect((await http(direct, { origin: webview })).status).toBe(403);
        expect((await http(direct)).status).toBe(401);
        // Through the relay, a WebSocket reaches maa-ide, which answers for the session (none runs: 502).
        expect(await upgrade(`${base.href}/sim/rosbridge`, { origin: webview })).toBe('502');
    });
});
