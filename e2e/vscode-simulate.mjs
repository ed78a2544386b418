#!/usr/bin/env node
// The VS Code extension's simulate view in chromium (docs/vscode.md "Simulate"), without VS Code:
// the extension's own pieces against the real maa-ide: its webview bundle (out/webview/simulate.js
// from bin/build.mjs), the page with its Content Security Policy (src/simulate/webview-html.ts),
// the backend started as the extension starts it (backend-process.ts with the built launcher),
// and the relay (relay.ts). The page is served through the relay by maa-ide (--app-dir), so its
// origin is the relay's; a stub acquireVsCodeApi records what the webview posts, and the test
// posts the extension's messages (init, start, reset, stop). Checks: the applications are listed,
// TR starts on timesync (lock-step), port values reach the inspector and the live-values
// messages, the automaton states arrive, the viser canvas renders, reset and stop answer.
//
//   node e2e/vscode-simulate.mjs      (run it under the e2e lock on a shared machine)
import { cpSync, mkdirSync, mkdtempSync, rmSync, writeFileSync } from 'node:fs';
import { createRequire } from 'node:module';
import os from 'node:os';
import path from 'node:path';
import { pathToFileURL } from 'node:url';
import { freshWorkspace, launchBrowser, repo, screenshot } from './lib.mjs';

const ext = path.join(repo, 'packages', 'vscode-extension');
const { build } = createRequire(path.join(ext, 'package.json'))('esbuild');
const tmp = mkdtempSync(path.join(os.tmpdir(), 'maa-vscode-simulate-'));
const built = path.join(tmp, 'extension');
const appDir = path.join(tmp, 'app');
const modules = path.join(tmp, 'modules');

async function run(command, args) {
    const { spawn } = await import('node:child_process');
    await new Promise((resolve, reject) => {
        const child = spawn(command, args, { cwd: ext, stdio: 'inherit' });
        child.on('exit', (code) => (code === 0 ? resolve() : reject(new Error(`${args.join(' ')} exited with ${code}`))));
    });
}

function fail(message) {
    throw new Error(message);
}

/** The extension's Node-side modules as ES modules this script can import. */
async function extensionModules() {
    for (const name of ['backend-process', 'relay', 'webview-html']) {
        await build({
            entryPoints: [path.join(ext, 'src', 'simulate', `${name}.ts`)],
            outfile: path.join(modules, `${name}.mjs`),
            bundle: true,
            platform: 'node',
            format: 'esm',
            logLevel: 'warning',
        });
    }
    const load = (name) => import(pathToFileURL(path.join(modules, `${name}.mjs`)).href);
    return { ...(await load('backend-process')), ...(await load('relay')), ...(await load('webview-html')) };
}

/** Every message the webview posted so far. */
const posted = (page) => page.evaluate(() => window.__posted);
/** Waits until the webview posted a message of `type` (and `command`, when given) for which `test` holds. */
const waitPosted = (page, type, command, timeout) =>
    page.waitForFunction(([t, c]) => window.__posted.some((m) => m.type === t && (c === null || m.command === c)), [type, command], {
        timeout,
    });
/** Waits until a live message of `type` names `key` (a port path or an instance path). */
const waitLive = (page, type, key, timeout) =>
    page.waitForFunction(
        ([t, k]) => window.__posted.some((m) => m.type === t && (m.values ?? m.states).some(([name]) => name === k)),
        [type, key],
        { timeout },
    );

await run(process.execPath, [path.join(ext, 'bin', 'build.mjs'), '--out', built]);
const { IdeBackend, SimRelay, simulateHtml } = await extensionModules();
mkdirSync(appDir, { recursive: true });
for (const f of ['simulate.js', 'simulate.css']) cpSync(path.join(built, 'out', 'webview', f), path.join(appDir, f));

const ws = freshWorkspace();
cpSync(path.join(repo, 'examples', 'toast-service'), path.join(ws.workspace, '..', 'toast-only', 'toast-service'), { recursive: true });
const workspace = path.join(ws.workspace, '..', 'toast-only');
const backend = new IdeBackend(path.join(built, 'out', 'simulate', 'backend-launcher.mjs'), (line) => {
    if (process.argv.includes('--log')) console.log(`[maa-ide] ${line}`);
});
let relay;
let browser;
let failed = false;
try {
    const running = await backend.ensure(workspace, {
        node: process.execPath,
        bin: path.join(repo, 'packages', 'ide-server', 'bin', 'maa-ide.js'),
        extraArgs: ['--app-dir', appDir],
    });
    relay = new SimRelay({ port: running.port, token: running.token });
    const base = await relay.base();
    const origin = new URL(base).origin;
    // The extension's page, with its CSP; the stub of VS Code's webview API runs with the page's nonce.
    const nonce = 'e2e-nonce-0123456789';
    const html = simulateHtml({
        cspSource: origin,
        script: `${base}/simulate.js`,
        style: `${base}/simulate.css`,
        relayOrigin: origin,
        nonce,
    }).replace(
        '<div id="simulate-root"></div>',
        `<div id="simulate-root"></div>\n<script nonce="${nonce}">window.__posted = []; window.__cspViolations = []; document.addEventListener('securitypolicyviolation', (e) => window.__cspViolations.push(e.violatedDirective + ' ' + e.blockedURI)); window.__state = undefined; window.acquireVsCodeApi = () => ({ postMessage: (m) => window.__posted.push(m), getState: () => window.__state, setState: (s) => { window.__state = s; } });</script>`,
    );
    writeFileSync(path.join(appDir, 'index.html'), html);
    browser = await launchBrowser();
    const { page } = browser;
    await page.goto(`${base}/index.html`);
    await waitPosted(page, 'ready', null, 30_000);
    await page.evaluate((b) => window.postMessage({ type: 'init', backendBase: b }, '*'), base);
    await page.locator('[data-testid=sim-platform] option[value=timesync]').waitFor({ state: 'attached', timeout: 30_000 });
    await page.evaluate(() => window.postMessage({ type: 'start', app: 'toast-service/TR.arcapp', platform: 'timesync' }, '*'));
    await waitPosted(page, 'done', 'start', 240_000);
    const started = (await posted(page)).find((m) => m.type === 'done' && m.command === 'start');
    if (!started.ok) fail('the panel did not start toast-service/TR.arcapp on timesync');
    await page.locator('[data-testid=viser-frame]').waitFor({ timeout: 60_000 });
    await waitLive(page, 'live-values', 'plate.angle', 90_000);
    await waitLive(page, 'active-states', 'ctrl', 90_000);
    const viser = page.frameLocator('[data-testid=viser-frame]');
    await viser.locator('canvas').first().waitFor({ state: 'attached', timeout: 60_000 });
    const sizes = await viser.locator('canvas').evaluateAll((cs) => cs.map((c) => [c.width, c.height]));
    if (!sizes.some(([w, h]) => w >= 10 && h >= 10)) fail(`no viser canvas has a size: ${JSON.stringify(sizes)}`);
    await screenshot(page, 'vscode-simulate-running');
    // the 3D view's size (its drag handle, by keyboard) is kept in the webview's state
    await page.locator('[data-testid=sim-split]').focus();
    await page.keyboard.press('ArrowLeft');
    const kept = await page.evaluate(() => window.__state?.['simulate.layout']?.viewFraction);
    if (typeof kept !== 'number' || Math.abs(kept - 0.5) > 1e-9)
        fail(`the webview state keeps the 3D view's size as ${kept}, expected 0.5`);
    await page.evaluate(() => window.postMessage({ type: 'reset' }, '*'));
    await waitPosted(page, 'done', 'reset', 30_000);
    if (!(await posted(page)).some((m) => m.type === 'done' && m.command === 'reset' && m.ok))
        fail('reset answered that no run was connected');
    await page.evaluate(() => window.postMessage({ type: 'stop' }, '*'));
    await waitPosted(page, 'done', 'stop', 60_000);
    // roslib's bson probes for WebAssembly once (inside try/catch, falling back to plain JS); the
    // CSP stays without 'wasm-unsafe-eval', so that probe is the one expected report.
    const violations = (await page.evaluate(() => window.__cspViolations)).filter((v) => v !== 'script-src wasm-eval');
    if (violations.length > 0) fail(`the page broke its Content Security Policy: ${violations.join(', ')}`);
    console.log('  ✓ the VS Code simulate view: started, live values and states, viser, reset, stop (through the relay, under the CSP)');
} catch (error) {
    failed = true;
    if (browser) await screenshot(browser.page, 'vscode-simulate-FAIL').catch(() => undefined);
    console.log(`  ✗ the VS Code simulate view: ${error?.message ?? error}`);
    if (browser) console.log(`    browser console (last lines):\n      ${browser.consoleLines.slice(-15).join('\n      ')}`);
} finally {
    await browser?.close();
    await relay?.close();
    await backend.stop();
    ws.dispose();
    rmSync(tmp, { recursive: true, force: true });
}
process.exit(failed ? 1 : 0);
