// The simulate commands' own logic without an editor: which maa-ide runs, the application path
// the backend knows, maa-ide's serving line, the relay's admission rules, and the webview page.
import path from 'node:path';
import { describe, expect, it } from 'vitest';
import { backendArgs, servingPort } from '../src/simulate/backend-process.js';
import { backendAppPath, backendScript, readSimulateSettings } from '../src/simulate/launch.js';
import { originAllowed, relayAdmission, sameCapability } from '../src/simulate/relay-rules.js';
import { simulateCsp, simulateHtml, webSocketOrigin } from '../src/simulate/webview-html.js';

describe('maa-ide for the simulate view', () => {
    it('reads the settings with their defaults', () => {
        expect(readSimulateSettings(() => undefined)).toEqual({ backend: '', node: 'node' });
        expect(readSimulateSettings((k) => (k === 'maa.simulate.backend' ? ' /x/maa-ide.js ' : '  '))).toEqual({
            backend: '/x/maa-ide.js',
            node: 'node',
        });
    });

    it('finds the setting, else the workspace install, else the PATH, following bin links', () => {
        const real = (f: string) => `real:${f}`;
        const ws = path.join('/ws');
        const local = path.join(ws, 'node_modules', '.bin', 'maa-ide');
        const onPath = path.join('/usr/bin', 'maa-ide');
        const exists = (set: string[]) => (f: string) => set.includes(f);
        const s = readSimulateSettings(() => undefined);
        expect(backendScript(s, [ws], ['/usr/bin'], exists([local, onPath]), real)).toBe(`real:${local}`);
        expect(backendScript(s, [ws], ['', '/usr/bin'], exists([onPath]), real)).toBe(`real:${onPath}`);
        expect(backendScript(s, [ws], ['/usr/bin'], exists([]), real)).toBeUndefined();
        const named = { backend: '/opt/maa-ide.js', node: 'node' };
        expect(backendScript(named, [ws], ['/usr/bin'], exists(['/opt/maa-ide.js', local]), real)).toBe('real:/opt/maa-ide.js');
        expect(backendScript(named, [ws], ['/usr/bin'], exists([local]), real)).toBeUndefined();
    });

    it('names the application relative to its workspace folder, with /', () => {
        expect(backendAppPath(path.join('/ws'), path.join('/ws', 'examples', 'T.arcapp'))).toBe('examples/T.arcapp');
        expect(backendAppPath(path.join('/ws'), path.join('/other', 'T.arcapp'))).toBeUndefined();
        expect(backendAppPath(path.join('/ws'), path.join('/ws'))).toBeUndefined();
    });

    it("reads the port of maa-ide's serving line and starts it on loopback, any port", () => {
        expect(servingPort('maa-ide: serving /w s at http://127.0.0.1:41234/?token=abc')).toBe(41234);
        expect(servingPort('maa-ide: serving /w at http://localhost:80/?token=abc')).toBe(80);
        expect(servingPort('maa-ide: serving /w at http://0.0.0.0:80/?token=abc')).toBeUndefined();
        expect(servingPort('something at http://127.0.0.1:1/')).toBeUndefined();
        expect(backendArgs('/l.mjs', '/b.js', '/w')).toEqual([
            '/l.mjs',
            '/b.js',
            '--workspace',
            '/w',
            '--host',
            '127.0.0.1',
            '--port',
            '0',
        ]);
    });
});

describe("the relay's admission", () => {
    const cap = 'c'.repeat(43);
    const isCap = (s: string) => sameCapability(s, cap);
    const admit = (url: string, headers: { host?: string; origin?: string } = {}) =>
        relayAdmission({ host: headers.host ?? '127.0.0.1:5000', origin: headers.origin, url }, 5000, isCap);

    it('admits the capability and strips it; redirects keep it', () => {
        const a = admit(`/${cap}/api/sim/topics?app=x`, { origin: 'vscode-webview://abc' });
        expect(a).toMatchObject({ ok: true, path: '/api/sim/topics?app=x', cors: 'vscode-webview://abc' });
        if (a.ok) {
            expect(a.relocate('/sim/viser/')).toBe(`/${cap}/sim/viser/`);
            expect(a.relocate('//evil.example/')).toBe('//evil.example/');
            expect(a.relocate('http://x/')).toBe('http://x/');
        }
        expect(admit(`/${cap}`)).toMatchObject({ ok: true, path: '/', cors: undefined });
        expect(admit(`/${cap}?x=1`)).toMatchObject({ ok: true, path: '/?x=1' });
        expect(admit(`/${cap}/sim/viser`, { host: 'localhost:5000', origin: 'http://localhost:5000' })).toMatchObject({
            ok: true,
            cors: undefined,
        });
    });

    it('refuses foreign hosts, origins and capabilities', () => {
        expect(admit(`/${cap}/api`, { host: 'evil.example:5000' })).toMatchObject({ ok: false, status: 403 });
        expect(admit(`/${cap}/api`, { host: '127.0.0.1:5001' })).toMatchObject({ ok: false, status: 403 });
        expect(admit(`/${cap}/api`, { host: '127.0.0.1' })).toMatchObject({ ok: false, status: 403 });
        expect(relayAdmission({ host: undefined, origin: undefined, url: `/${cap}` }, 5000, isCap)).toMatchObject({
            ok: false,
            status: 403,
        });
        expect(admit(`/${cap}/api`, { origin: 'http://evil.example' })).toMatchObject({ ok: false, status: 403 });
        expect(admit('/api/apps')).toMatchObject({ ok: false, status: 404 });
        expect(admit(`/${cap}x/api`)).toMatchObject({ ok: false, status: 404 });
        expect(admit(`/x/${cap}/api`)).toMatchObject({ ok: false, status: 404 });
    });

    it('admits as origins only a webview and its own page', () => {
        expect(originAllowed('vscode-webview://0a1b2c', 5000)).toBe(true);
        expect(originAllowed('http://127.0.0.1:5000', 5000)).toBe(true);
        expect(originAllowed('http://localhost:5000', 5000)).toBe(true);
        for (const o of [
            'vscode-webview://',
            'vscode-webview://a/b',
            'vscode-file://vscode-app',
            'http://127.0.0.1:5001',
            'https://127.0.0.1:5000',
            'http://127.0.0.1:5000/',
            'null',
            'http://evil.example',
            'file://',
        ]) {
            expect(originAllowed(o, 5000), o).toBe(false);
        }
    });
});

describe('the simulate webview page', () => {
    const page = {
        cspSource: 'https://file+.vscode-resource.vscode-cdn.net',
        script: 'https://file+.vscode-resource.vscode-cdn.net/ext/out/webview/simulate.js',
        style: 'https://file+.vscode-resource.vscode-cdn.net/ext/out/webview/simulate.css',
        relayOrigin: 'http://127.0.0.1:40123',
        nonce: 'n0nce',
    };

    it('allows the nonce script and only the relay for connections and frames', () => {
        const csp = simulateCsp(page);
        expect(csp).toContain("default-src 'none'");
        expect(csp).toContain("script-src 'nonce-n0nce'");
        expect(csp).toContain('connect-src http://127.0.0.1:40123 ws://127.0.0.1:40123');
        expect(csp).toContain('frame-src http://127.0.0.1:40123');
        expect(csp).not.toContain('unsafe');
        expect(webSocketOrigin('https://tunnel.example')).toBe('wss://tunnel.example');
        expect(() => webSocketOrigin('ftp://x')).toThrow();
    });

    it('loads the script with the nonce and a fresh nonce each time', () => {
        const html = simulateHtml(page);
        expect(html).toContain(`<script nonce="n0nce" src="${page.script}"></script>`);
        expect(html).toContain('<div id="simulate-root"></div>');
        const { nonce: _n, ...rest } = page;
        const a = /nonce="([^"]+)"/.exec(simulateHtml(rest))?.[1];
        const b = /nonce="([^"]+)"/.exec(simulateHtml(rest))?.[1];
        expect(a).toBeDefined();
        expect(a).not.toBe(b);
        expect(simulateHtml({ ...page, script: 'x"><script>alert(1)</script>' })).not.toContain('"><script>alert');
    });
});
