#!/usr/bin/env node
// The VS Code extension's diagram webview in chromium, outside VS Code: the extension is built
// into a temporary folder (bin/build.mjs --out), its webview page (src/diagram/html.ts: the CSP
// with the nonce) is served over HTTP with the bundled out/webview files, and a stand-in for VS
// Code's acquireVsCodeApi relays the page's messages to the built language server over stdio
// (as src/diagram/panel.ts does through the LanguageClient). Checks: the C&C diagram of a model
// renders without a CSP violation, a click posts the element's trace, the editor's cursor selects
// the element, a run's live value and state chip cover no text, the palette follows the editor's
// theme, the command's Export SVG posts a standalone SVG named after the component, the automaton
// line opens the automaton view, which shows the active state pushed by showActiveStates and a
// highlighted trace point (maa.diagram.highlightTrace), and an edit updates the diagram. Exit code
// 0 when all pass.
//
//   flock /tmp/e2e.lock node e2e/vscode-diagram-webview.mjs   (needs the language server built)
import { spawn } from 'node:child_process';
import { cpSync, mkdtempSync, readFileSync, rmSync } from 'node:fs';
import http from 'node:http';
import { tmpdir } from 'node:os';
import path from 'node:path';
import { pathToFileURL } from 'node:url';
import { build } from 'esbuild';
import { createProtocolConnection, StreamMessageReader, StreamMessageWriter } from 'vscode-languageserver-protocol/node.js';
import { launchBrowser, repo, screenshot } from './lib.mjs';

const extPkg = path.join(repo, 'packages', 'vscode-extension');
const tmp = mkdtempSync(path.join(tmpdir(), 'maa-diagram-webview-'));
const cleanups = [() => rmSync(tmp, { recursive: true, force: true })];
const results = [];

function check(name, ok, detail = '') {
    results.push({ name, ok });
    console.log(`  ${ok ? '✓' : '✗'} ${name}${detail ? ` (${detail})` : ''}`);
}

function run(command, args) {
    return new Promise((resolve, reject) => {
        const child = spawn(command, args, { stdio: ['ignore', 'inherit', 'inherit'] });
        child.on('exit', (code) => (code === 0 ? resolve() : reject(new Error(`${args.join(' ')} exited with ${code}`))));
    });
}

/** The built extension and the page's HTML function (html.ts, bundled to an ES module). */
async function prepare() {
    const ext = path.join(tmp, 'extension');
    await run(process.execPath, [path.join(extPkg, 'bin', 'build.mjs'), '--out', ext]);
    const htmlModule = path.join(tmp, 'html.mjs');
    await build({
        entryPoints: [path.join(extPkg, 'src', 'diagram', 'html.ts')],
        outfile: htmlModule,
        bundle: true,
        format: 'esm',
        platform: 'node',
        logLevel: 'warning',
    });
    const { webviewHtml, newNonce } = await import(pathToFileURL(htmlModule).href);
    return { webviewDir: path.join(ext, 'out', 'webview'), webviewHtml, newNonce };
}

/** The language server over stdio, initialized on a copy of the toast example with Controller.arc open. */
async function startServer() {
    const ws = path.join(tmp, 'ws');
    cpSync(path.join(repo, 'examples', 'toast-service'), ws, { recursive: true });
    const file = path.join(ws, 'toast', 'Controller.arc');
    const uri = pathToFileURL(file).toString();
    const text = readFileSync(file, 'utf8');
    const proc = spawn(process.execPath, [path.join(repo, 'packages', 'language-server', 'dist', 'node', 'main.js'), '--stdio'], {
        stdio: 'pipe',
    });
    const conn = createProtocolConnection(new StreamMessageReader(proc.stdout), new StreamMessageWriter(proc.stdin));
    cleanups.push(() => {
        conn.dispose();
        proc.kill();
    });
    conn.onRequest('client/registerCapability', () => null);
    conn.onRequest('workspace/configuration', () => []);
    const checked = new Promise((resolve) => conn.onNotification('textDocument/publishDiagnostics', (p) => p.uri === uri && resolve()));
    conn.listen();
    const root = pathToFileURL(ws).toString();
    await conn.sendRequest('initialize', {
        processId: process.pid,
        rootUri: root,
        workspaceFolders: [{ uri: root, name: 'ws' }],
        capabilities: {},
    });
    await conn.sendNotification('initialized', {});
    await conn.sendNotification('textDocument/didOpen', { textDocument: { uri, languageId: 'arc', version: 1, text } });
    await checked;
    return { conn, uri, text };
}

/** Serves the webview page (with the acquireVsCodeApi stand-in, under the page's own nonce) and out/webview. */
async function serve({ webviewDir, webviewHtml, newNonce }) {
    const server = http.createServer((req, res) => {
        const origin = `http://127.0.0.1:${server.address().port}`;
        if (req.url === '/') {
            const nonce = newNonce();
            const page = webviewHtml({ cspSource: origin, nonce, scriptUri: `${origin}/diagram.js`, styleUri: `${origin}/diagram.css` });
            const stub = `<script nonce="${nonce}">window.acquireVsCodeApi = () => ({ postMessage: (m) => window.__toExtension(m) });</script>`;
            res.writeHead(200, { 'content-type': 'text/html' });
            res.end(page.replace('<body>', `<body>${stub}`));
            return;
        }
        const name = path.basename(req.url ?? '');
        try {
            const body = readFileSync(path.join(webviewDir, name));
            res.writeHead(200, { 'content-type': name.endsWith('.js') ? 'text/javascript' : 'text/css' });
            res.end(body);
        } catch {
            res.writeHead(404);
            res.end();
        }
    });
    await new Promise((resolve) => server.listen(0, '127.0.0.1', resolve));
    cleanups.push(() => server.close());
    return `http://127.0.0.1:${server.address().port}/`;
}

async function main() {
    const prepared = await prepare();
    const { conn, uri, text } = await startServer();
    const url = await serve(prepared);
    const browser = await launchBrowser({ width: 1200, height: 800 });
    cleanups.unshift(() => browser.close());
    const { page } = browser;
    const violations = [];
    page.on('console', (m) => /Content Security Policy/.test(m.text()) && violations.push(m.text()));
    const toPage = (message) => page.evaluate((m) => window.postMessage(m, '*'), message);
    conn.onNotification('diagram/accept', (message) => void toPage({ type: 'action', message }));
    const posted = [];
    const waiters = new Set();
    await page.exposeFunction('__toExtension', (m) => {
        posted.push(m);
        if (m.type === 'action') void conn.sendNotification('diagram/accept', m.message);
        if (m.type === 'ready') void toPage({ type: 'show', target: { uri, diagramType: 'maa-cc' } });
        for (const w of [...waiters]) w();
    });
    const next = (type, since = 0) =>
        new Promise((resolve) => {
            const probe = () => {
                const hit = posted.slice(since).find((m) => m.type === type);
                if (!hit) return;
                waiters.delete(probe);
                resolve(hit);
            };
            waiters.add(probe);
            probe();
        });

    await page.goto(url);
    await next('ready');
    await page.waitForSelector('#maa-diagram-root svg [data-instance-path=""]', { timeout: 60_000 });
    check('the C&C diagram renders under the CSP', violations.length === 0, `${violations.length} violations`);
    check('its title names the component', (await page.textContent('.maa-diagram-title')) === 'Controller');

    const before = posted.length;
    await page.click('#maa-diagram-root svg [id$="root:distance"]', { force: true });
    const selected = await next('select', before);
    check("a click posts the element's trace", /Controller\.arc\?/.test(selected.traces[0] ?? ''), selected.traces[0]);

    const colorLine = text.split('\n').findIndex((l) => l.includes('in ToastColor color'));
    await toPage({ type: 'revealPosition', uri, position: { line: colorLine, character: 12 } });
    await page.waitForSelector('#maa-diagram-root svg [id$="root:color"].selected', { timeout: 10_000 });
    check('the cursor selects the element there', true);

    // A run's decorations in the C&C view: a live value beside its port and the current-state chip, covering no other text
    // (the browser's own text boxes); the atomic component shown on its own lists its port types and its automaton.
    await toPage({ type: 'liveValues', values: [['distance', '12345678901234567890']] });
    await toPage({ type: 'activeStates', states: [['', 'Toasting']] });
    await page.waitForSelector('#maa-diagram-root svg .maa-value', { timeout: 10_000 });
    await page.waitForSelector('#maa-diagram-root svg .maa-current-state', { timeout: 10_000 });
    const covered = await page.evaluate(() => {
        const boxes = [
            ...document.querySelectorAll(
                '#maa-diagram-root svg text, #maa-diagram-root svg .maa-value-label rect, #maa-diagram-root svg .maa-current-state rect, #maa-diagram-root svg .maa-badge rect',
            ),
        ]
            .filter((e) => !e.closest('.maa-value-label, .maa-current-state, .maa-badge') || e.tagName === 'rect')
            .map((e) => ({ what: `${e.getAttribute('class') ?? e.tagName}:${e.textContent ?? ''}`, r: e.getBoundingClientRect() }));
        const out = [];
        for (let i = 0; i < boxes.length; i++)
            for (let j = i + 1; j < boxes.length; j++) {
                const a = boxes[i].r;
                const b = boxes[j].r;
                if (a.right - 1 > b.left && b.right - 1 > a.left && a.bottom - 1 > b.top && b.bottom - 1 > a.top)
                    out.push(`${boxes[i].what} / ${boxes[j].what}`);
            }
        return out;
    });
    await screenshot(page, 'vscode-diagram-live');
    check('live values and the state chip cover no text (browser text boxes)', covered.length === 0, covered.slice(0, 3).join('; '));
    const portText = await page.textContent('#maa-diagram-root svg [id$="root:distance#name"]');
    check('the atomic component shown alone names its port types', portText === 'distance: int', portText ?? '');
    await toPage({ type: 'liveValues', values: [] });
    await toPage({ type: 'activeStates', states: [] });

    // The palette follows the editor's theme (VS Code's body classes).
    const rootFill = () =>
        page.evaluate(() => getComputedStyle(document.querySelector('#maa-diagram-root svg .maa-root > .maa-component-body')).fill);
    await page.evaluate(() => document.body.classList.add('vscode-light'));
    const light = await rootFill();
    await page.evaluate(() => document.body.classList.replace('vscode-light', 'vscode-dark'));
    const dark = await rootFill();
    check('the theme switch changes the palette (light, then dark)', light !== dark && dark === 'rgb(36, 51, 42)', `${light} -> ${dark}`);

    const exportFrom = posted.length;
    await toPage({ type: 'exportSvg' });
    const saved = await next('saveSvg', exportFrom);
    check(
        'Export SVG posts a standalone SVG named after the component',
        saved.fileName === 'Controller.svg' && saved.svg.startsWith('<?xml') && saved.svg.includes('maa-component'),
        saved.fileName,
    );

    // The automaton line of the atomic component opens its automaton view.
    await page.click('#maa-diagram-root svg .maa-behavior-link', { force: true });
    await page.waitForSelector('#maa-diagram-root svg .maa-state', { timeout: 60_000 });
    check('the automaton line opens the automaton view', true);
    await toPage({ type: 'show', target: { uri, component: 'toast.Controller', diagramType: 'maa-automaton' } });
    // The title follows the target at once; the states come with the server's model.
    await page.waitForSelector('#maa-diagram-root svg .maa-state', { timeout: 60_000 });

    // maa.diagram.highlightTrace: the state and the transition taken (by its allTransitions index), then cleared.
    const index = Number(await page.getAttribute('#maa-diagram-root svg [id$="tr:Toasting->Serving"]', 'data-transition-index'));
    await toPage({
        type: 'highlight',
        highlight: {
            component: 'toast.Controller',
            instancePath: 'ctrl',
            state: 'Serving',
            transition: { from: 'Toasting', to: 'Serving', index },
        },
    });
    await page.waitForSelector('#maa-diagram-root svg .maa-transition-highlight', { timeout: 10_000 });
    const lit = await page.evaluate(() =>
        [...document.querySelectorAll('#maa-diagram-root svg .maa-state-highlight, #maa-diagram-root svg .maa-transition-highlight')].map(
            (e) => e.id,
        ),
    );
    check(
        'a highlighted trace point marks its state and its transition',
        Number.isInteger(index) &&
            lit.length === 2 &&
            lit.some((id) => id.endsWith('state:Serving')) &&
            lit.some((id) => id.endsWith('tr:Toasting->Serving')),
        lit.join(', '),
    );
    await toPage({ type: 'highlight' });
    await page.waitForFunction(() => !document.querySelector('#maa-diagram-root svg .maa-transition-highlight'), undefined, {
        timeout: 10_000,
    });
    check('clearing the highlight unmarks them', true);
    await toPage({ type: 'activeStates', states: [['', 'Toasting']] });
    await page.waitForSelector('#maa-diagram-root svg .maa-state-active', { timeout: 10_000 });
    const active = await page.evaluate(() => [...document.querySelectorAll('#maa-diagram-root svg .maa-state-active')].map((e) => e.id));
    check(
        'the automaton view marks the active state',
        active.some((id) => id.includes('Toasting')),
        active.join(', '),
    );

    await conn.sendNotification('textDocument/didChange', {
        textDocument: { uri, version: 2 },
        contentChanges: [{ text: text.replace('state Serving;', 'state Serving;\n    state Cooling;') }],
    });
    await page.waitForSelector('#maa-diagram-root svg [id$="Cooling"]', { timeout: 60_000 });
    check('an edit updates the diagram', true);
}

let failed = false;
try {
    await main();
} catch (e) {
    failed = true;
    console.error(`vscode-diagram-webview: ${e instanceof Error ? e.stack : e}`);
} finally {
    for (const c of cleanups) await Promise.resolve(c()).catch(() => undefined);
}
failed ||= results.some((r) => !r.ok);
console.log(`vscode-diagram-webview: ${results.filter((r) => r.ok).length}/${results.length} checks passed`);
process.exit(failed ? 1 : 0);
