// The web entry's simulation target (src/simulate/web-target.ts): the backend base the simulate
// view gets in the browser IDE, the application path, and, against a real maa-ide, that the view's
// requests as the webview frame makes them (the page's origin, the page's token cookie) are let
// in while other origins and requests without the cookie stay refused, and that the view's CSP for
// that base admits exactly the endpoints the panel uses.
import { mkdtempSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import path from 'node:path';
import { type IdeServer, startIdeServer } from '@maa/ide-server';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
// The panel's endpoints (not exported by @maa/simulate-view: the webview bundle uses them internally).
import { simEndpoints } from '../../simulate-view/src/endpoints.js';
import { webAppPath, webBackendBase } from '../src/simulate/web-target.js';
import { otherLoopbackOrigin, simulateCsp } from '../src/simulate/webview-html.js';

describe('webBackendBase', () => {
    it('is the page folder without a trailing slash', () => {
        expect(webBackendBase('http://127.0.0.1:4000')).toBe('http://127.0.0.1:4000');
        expect(webBackendBase('http://127.0.0.1:4000/')).toBe('http://127.0.0.1:4000');
        expect(webBackendBase('https://lab.example/u/alice/')).toBe('https://lab.example/u/alice');
    });

    it('refuses other schemes and URLs with a query, fragment or credentials', () => {
        expect(() => webBackendBase('vscode-webview://abc')).toThrow(/http\(s\)/);
        expect(() => webBackendBase('ftp://host/')).toThrow(/http\(s\)/);
        expect(() => webBackendBase('http://host/?token=secret')).toThrow(/plain folder/);
        expect(() => webBackendBase('http://host/#x')).toThrow(/plain folder/);
        expect(() => webBackendBase('http://user:pw@host/')).toThrow(/plain folder/);
        expect(() => webBackendBase('not a url')).toThrow();
    });
});

describe('webAppPath', () => {
    it('is the path below the workspace folder with /', () => {
        expect(webAppPath('/workspace', '/workspace/toast-service/TR.arcapp')).toBe('toast-service/TR.arcapp');
        expect(webAppPath('/workspace/', '/workspace/TR.arcapp')).toBe('TR.arcapp');
        // Uri.fsPath on a Windows browser gives backslashes.
        expect(webAppPath('/workspace', '\\workspace\\toast-service\\TR.arcapp')).toBe('toast-service/TR.arcapp');
    });

    it('is undefined outside the folder, for the folder itself and for dot segments', () => {
        expect(webAppPath('/workspace', '/other/TR.arcapp')).toBeUndefined();
        expect(webAppPath('/workspace', '/workspace-2/TR.arcapp')).toBeUndefined();
        expect(webAppPath('/workspace', '/workspace')).toBeUndefined();
        expect(webAppPath('/workspace', '/workspace/')).toBeUndefined();
        expect(webAppPath('/workspace', '/workspace/../etc/TR.arcapp')).toBeUndefined();
        expect(webAppPath('/workspace', '/workspace/a/./TR.arcapp')).toBeUndefined();
        expect(webAppPath('/workspace', '/workspace//TR.arcapp')).toBeUndefined();
    });
});

describe("the simulate view's endpoints in the browser IDE", () => {
    it('are all on the page origin, and the CSP admits exactly that origin', () => {
        const base = webBackendBase('http://127.0.0.1:4000/');
        const endpoints = simEndpoints(base, { protocol: 'http:', host: 'unused:1' });
        expect(endpoints).toEqual({
            api: 'http://127.0.0.1:4000',
            rosbridge: 'ws://127.0.0.1:4000/sim/rosbridge',
            viser: 'http://127.0.0.1:4000/sim/viser/',
        });
        const csp = simulateCsp({ cspSource: 'https://cdn.example', relayOrigin: new URL(base).origin, nonce: 'n' });
        const directive = (name: string) =>
            csp
                .split(';')
                .map((d) => d.trim().split(/\s+/))
                .find((d) => d[0] === name)
                ?.slice(1);
        expect(directive('connect-src')).toEqual([new URL(endpoints.api).origin, new URL(endpoints.rosbridge).origin]);
        // the viser page also from the other loopback name: maa-ide moves it to a process of its own there
        expect(directive('frame-src')).toEqual([new URL(endpoints.viser).origin, 'http://localhost:4000']);
    });

    it('admits the viser frame from the other loopback name only for a loopback http origin', () => {
        expect(otherLoopbackOrigin('http://127.0.0.1:4000')).toBe('http://localhost:4000');
        expect(otherLoopbackOrigin('http://localhost:4000')).toBe('http://127.0.0.1:4000');
        expect(otherLoopbackOrigin('http://[::1]:4000')).toBe('http://127.0.0.1:4000');
        expect(otherLoopbackOrigin('https://lab.example')).toBeUndefined();
        expect(otherLoopbackOrigin('http://192.168.1.5:4000')).toBeUndefined();
        const lab = simulateCsp({ cspSource: 'https://cdn.example', relayOrigin: 'https://lab.example', nonce: 'n' });
        expect(lab).toMatch(/frame-src https:\/\/lab\.example$/);
    });

    it('keeps a lab prefix on every endpoint', () => {
        const endpoints = simEndpoints(webBackendBase('https://lab.example/u/alice/'), { protocol: 'http:', host: 'unused:1' });
        expect(endpoints.api).toBe('https://lab.example/u/alice');
        expect(endpoints.rosbridge).toBe('wss://lab.example/u/alice/sim/rosbridge');
        expect(endpoints.viser).toBe('https://lab.example/u/alice/sim/viser/');
    });
});

describe('a real maa-ide answers the view as the webview frame asks', () => {
    const TOKEN = 'simulate-web-token-0123456789abcdef';
    let dir = '';
    let server: IdeServer;
    let cookie = '';
    let base = '';

    beforeAll(async () => {
        dir = mkdtempSync(path.join(tmpdir(), 'maa-web-sim-'));
        server = await startIdeServer({ appDir: path.join(dir, 'no-app'), token: TOKEN, workspace: dir, port: 0 });
        base = webBackendBase(server.url);
        // The page's login: `?token=` sets the token cookie, which the page's frames then send.
        const login = await fetch(`${base}/?token=${TOKEN}`, { redirect: 'manual' });
        cookie = (login.headers.get('set-cookie') ?? '').split(';')[0] ?? '';
        expect(cookie).toMatch(/=/);
    });
    afterAll(async () => {
        await server?.close();
        rmSync(dir, { recursive: true, force: true });
    });

    const status = (headers: Record<string, string>) =>
        fetch(`${simEndpoints(base, { protocol: 'http:', host: 'x' }).api}/api/sim/status`, { headers });

    it("lets in the page's origin with the cookie (the webview frame's origin in this workbench)", async () => {
        const answer = await status({ cookie, origin: new URL(base).origin });
        expect(answer.status).toBe(200);
        expect(await answer.json()).toHaveProperty('running', false);
    });

    it('refuses a VS Code webview origin, another site, and a request without the cookie', async () => {
        expect((await status({ cookie, origin: 'vscode-webview://abc' })).status).toBe(403);
        expect((await status({ cookie, origin: 'http://evil.example' })).status).toBe(403);
        expect((await status({ origin: new URL(base).origin })).status).toBe(401);
    });
});
