#!/usr/bin/env node
// The IDE benchmark (issues 7 and 18; a measurement, not a test): maa-ide on a fresh copy of
// examples/ and on a generated 200-component model, Debian's chromium (headless, no GPU) through
// playwright-core. Prints one table, each figure with its goal:
// - per phase (start, typing, generation, simulation start, a running simulation, stop) the
//   longest main-thread task and the number of tasks over 200 ms, seen by a PerformanceObserver
//   for 'longtask' in every frame (the workbench page and the webviews' iframes: the diagram, the
//   simulate view, viser);
// - time to interactive (cold: loads with the HTTP cache emptied; warm: loads with it), keystroke
//   → updated diagnostics, keystroke → updated diagram (medians);
// - the JavaScript bundle: the main entry raw and as served (Content-Encoding, bytes on the wire,
//   Cache-Control), and all files.
//
// The IDE is VS Code's workbench with the MontiArc extension; the diagram is the extension's webview.
//
//   node e2e/bench.mjs [--runs N] [--loads N] [--components N] [--json] [--no-sim] [--no-generate] [--no-example] [--no-large]
//                      [--run-seconds N] [--profile]
// (--loads N: N cold and N warm loads per workspace; the default is the runs, between 2 and 3)
import { readdirSync, statSync, readFileSync, writeFileSync, mkdirSync } from 'node:fs';
import http from 'node:http';
import path from 'node:path';
import { gzipSync } from 'node:zlib';
import { fail, frameWith, ROBOT, runCommand } from './host-kit.mjs';
import { appDir, artifacts, freshWorkspace, launchBrowser, screenshot, startIde, writeLargeModel } from './lib.mjs';
import { LongTasks, LONG_TASK_MS } from './longtasks.mjs';

const args = process.argv.slice(2);
const option = (name, fallback) => (args.includes(name) ? args[args.indexOf(name) + 1] : fallback);
const RUNS = Number(option('--runs', '5'));
const COMPONENTS = Number(option('--components', '200'));
const asJson = args.includes('--json');
const SIMULATE = !args.includes('--no-sim');
const RUN_SECONDS = Number(option('--run-seconds', '20'));
const PROFILE = args.includes('--profile');
const LARGE = !args.includes('--no-large');
const GENERATE = !args.includes('--no-generate');
const EXAMPLE = !args.includes('--no-example');
const LOADS = option('--loads', undefined);
const PAGE = 'index.html';

const progress = (line) => process.stderr.write(`bench: ${line}\n`);
const median = (xs) => {
    const s = [...xs].sort((a, b) => a - b);
    if (s.length === 0) return NaN;
    return s.length % 2 ? s[(s.length - 1) / 2] : (s[s.length / 2 - 1] + s[s.length / 2]) / 2;
};
const fmt = (ms) => (Number.isFinite(ms) ? `${Math.round(ms)} ms` : 'n/a');
const kb = (bytes) => `${(bytes / 1024).toFixed(0)} KiB`;

function bundleSize() {
    const files = [];
    const walk = (dir) => {
        for (const entry of readdirSync(dir, { withFileTypes: true })) {
            const file = path.join(dir, entry.name);
            if (entry.isDirectory()) walk(file);
            else if (entry.name.endsWith('.js')) files.push(file);
        }
    };
    walk(appDir);
    const index = readFileSync(path.join(appDir, PAGE), 'utf8');
    const entries = [...index.matchAll(/src="\.\/(assets\/[^"]+\.js)"/g)].map((m) => path.join(appDir, m[1]));
    const sum = (list) => list.reduce((acc, f) => acc + statSync(f).size, 0);
    const gz = (list) => list.reduce((acc, f) => acc + gzipSync(readFileSync(f)).length, 0);
    const workers = files.filter((f) => /worker/i.test(path.basename(f)));
    return {
        files: files.length,
        totalBytes: sum(files),
        totalGzipBytes: gz(files),
        entryBytes: sum(entries),
        entryGzipBytes: gz(entries),
        workerBytes: sum(workers),
        largest: files
            .map((f) => ({ file: path.relative(appDir, f), bytes: statSync(f).size }))
            .sort((a, b) => b.bytes - a.bytes)
            .slice(0, 5),
    };
}

/**
 * In the page: every document reachable from the top one through same-origin iframes (the
 * diagram is in a webview: an iframe holding another iframe, both served by maa-ide).
 */
const FIND_DIAGRAM = `(() => {
    const docs = (doc) => [doc, ...[...doc.querySelectorAll('iframe')].flatMap((f) => {
        try { return f.contentDocument ? docs(f.contentDocument) : []; } catch { return []; }
    })];
    window.maaBenchDiagram = () => docs(document).map((d) => d.querySelector('.maa-root')?.closest('svg')).find(Boolean);
})()`;

/**
 * Loads the IDE with `open` as the first editor and waits until it is interactive (its editor shows
 * the file) and until the diagram, which the IDE opens beside the first component file
 * (`maa.diagram.openOnStart`), draws a component. Times are from the start of the navigation.
 */
async function loadIde(page, url, open) {
    await page.goto(`${url}${open ? `?open=${encodeURIComponent(open)}` : ''}`);
    await page.waitForFunction(() => window.maaHost?.ready === true || document.body.dataset.failed, undefined, { timeout: 120_000 });
    const failed = await page.evaluate(() => document.body.dataset.failed);
    if (failed) throw new Error(`the IDE did not start: ${failed}`);
    await page.evaluate(FIND_DIAGRAM);
    const timings = await page.evaluate(() => window.maaHost.timings);
    let diagramMs = NaN;
    try {
        const drawn = await page.waitForFunction(
            () => (window.maaBenchDiagram()?.querySelector('.maa-component') ? performance.now() : false),
            undefined,
            { timeout: 120_000, polling: 'raf' },
        );
        diagramMs = await drawn.jsonValue();
    } catch (error) {
        progress(`no diagram: ${String(error?.message ?? error).split('\n')[0]}`);
    }
    // The main script as chromium got it (bytes on the wire and decoded; 0 on the wire from the HTTP cache).
    const mainScript = await page.evaluate(() => {
        const e = performance.getEntriesByType('resource').find((r) => /\/assets\/main-[^/]+\.js$/.test(r.name));
        return e ? { transferBytes: e.transferSize, encodedBytes: e.encodedBodySize, decodedBytes: e.decodedBodySize } : undefined;
    });
    return { interactiveMs: timings.editor, readyMs: timings.ready, diagramMs, mainScript };
}

/** Types `text` at the end of the first match of `needle` (in the editor of `file`) and measures, in the page,
 *  how long until the markers of the file change and until the diagram's DOM shows `expectInDiagram`
 *  (or, with `expectUpdate`, until the diagram's DOM changed and the next frame was drawn: in a huge
 *  diagram the edited element may lie outside the view, where Sprotty draws nothing). */
async function keystroke(page, { needle, type, expectInDiagram, expectUpdate, path: file }) {
    await page.evaluate((p) => window.maaHost.open(p), file);
    return await page.evaluate(
        async ({ needle, type, expectInDiagram, expectUpdate, file }) => {
            const host = window.maaHost;
            const editor = host.activeEditor();
            const model = editor.getModel();
            const match = model.findMatches(needle, false, false, true, null, false)[0];
            if (!match) throw new Error(`${needle} not found`);
            editor.setPosition(match.range.getEndPosition());
            editor.focus();
            const markerKey = () =>
                JSON.stringify(
                    host
                        .allMarkers()
                        .filter((m) => m.path === file)
                        .map((m) => `${m.line}:${m.message}`)
                        .sort(),
                );
            const diagramEl = window.maaBenchDiagram();
            let mutations = 0;
            const observer = new MutationObserver(() => mutations++);
            if (diagramEl) observer.observe(diagramEl, { subtree: true, childList: true, attributes: true, characterData: true });
            const before = markerKey();
            const t0 = performance.now();
            for (const ch of type) editor.trigger('keyboard', 'type', { text: ch });
            let diagnosticsMs = NaN;
            let diagramMs = NaN;
            await new Promise((resolve) => {
                const limit = t0 + 20_000;
                const poll = () => {
                    const now = performance.now();
                    if (Number.isNaN(diagnosticsMs) && markerKey() !== before) diagnosticsMs = now - t0;
                    if (Number.isNaN(diagramMs) && expectInDiagram && diagramEl?.textContent?.includes(expectInDiagram))
                        diagramMs = now - t0;
                    if (Number.isNaN(diagramMs) && expectUpdate && mutations > 0) diagramMs = now - t0;
                    const done = !Number.isNaN(diagnosticsMs) && (!(expectInDiagram || expectUpdate) || !Number.isNaN(diagramMs));
                    if (done || now > limit) resolve(undefined);
                    else requestAnimationFrame(poll);
                };
                poll();
            });
            observer.disconnect();
            // Undo and wait until the markers are back (the next run starts from the same state).
            const t1 = performance.now();
            for (let i = 0; i < type.length; i++) editor.trigger('keyboard', 'deleteLeft', {});
            await new Promise((resolve) => {
                const settled = () => markerKey() === before && !(expectInDiagram && diagramEl?.textContent?.includes(expectInDiagram));
                const poll = () => (settled() || performance.now() - t1 > 20_000 ? resolve(undefined) : setTimeout(poll, 20));
                poll();
            });
            const revertMs = performance.now() - t1;
            await new Promise((resolve) => setTimeout(resolve, 300));
            return { diagnosticsMs, diagramMs, revertMs };
        },
        { needle, type, expectInDiagram, expectUpdate, file },
    );
}

async function benchWorkspace(label, workspaceFrom, startFile, edits, browser, after) {
    const ws = freshWorkspace(workspaceFrom);
    const ide = await startIde(ws.workspace);
    const result = { label, load: [], edits: {} };
    try {
        const { page } = browser;
        await ide.login(page);
        const loads = LOADS ? Math.max(1, Number(LOADS)) : Math.max(2, Math.min(RUNS, 3));
        const network = await page.context().newCDPSession(page);
        for (let i = 0; i < 2 * loads; i++) {
            // the first half cold (the HTTP cache emptied), the second half warm
            const cold = i < loads;
            if (cold) await network.send('Network.clearBrowserCache');
            await longTasks.drain(page); // the frames of the previous load go with the navigation
            const cdp = PROFILE && i === 0 ? await startProfile(page) : undefined;
            const load = await longTasks.phase('start', page, () => loadIde(page, ide.url, startFile ?? edits[0]?.path));
            result.load.push({ ...load, cold });
            if (cdp) await stopProfile(cdp, `bench-start-${label.split(' ')[0]}`);
            progress(`${label}: load ${i + 1}: ${JSON.stringify(result.load.at(-1))}`);
        }
        await network.detach().catch(() => undefined);
        for (const edit of edits) {
            if (edit.open && edit.open !== startFile) {
                // The diagram follows the active editor: the time until it shows the opened component
                // (its own node's title is "<name>: <qualified name>").
                const opened = Date.now();
                await page.evaluate((p) => window.maaHost.open(p), edit.open);
                const shown = await page
                    .waitForFunction(
                        (name) => window.maaBenchDiagram()?.querySelector('.maa-root > title')?.textContent?.startsWith(`${name}:`),
                        path.basename(edit.open, '.arc'),
                        { timeout: edit.openTimeout ?? 60_000, polling: 'raf' },
                    )
                    .then(
                        () => true,
                        () => false,
                    );
                result.opened ??= {};
                result.opened[edit.name] = shown ? Date.now() - opened : NaN;
                progress(`${label}: opened ${edit.open}: diagram ${shown ? `after ${Date.now() - opened} ms` : 'not shown'}`);
                await page.waitForTimeout(1500);
            }
            const runs = [];
            // The renderer's CPU time over the keystrokes and their undos (every same-site frame: the workbench, the webviews).
            const metrics = await page.context().newCDPSession(page);
            await metrics.send('Performance.enable');
            const cpuBefore = await rendererCpu(metrics);
            const typingProfile = PROFILE && edit.name !== 'diagnostics' ? await startProfile(page) : undefined;
            for (let i = 0; i < (edit.runs ?? RUNS); i++) {
                runs.push(await longTasks.phase('typing', page, () => keystroke(page, edit)));
                progress(`${label}: ${edit.name} ${i + 1}: ${JSON.stringify(runs.at(-1))}`);
            }
            if (typingProfile) await stopProfile(typingProfile, `bench-typing-${label.split(/\W/)[0]}-${edit.name}`);
            const cpuAfter = await rendererCpu(metrics);
            await metrics.detach().catch(() => undefined);
            result.cpuPerKeystroke ??= {};
            result.cpuPerKeystroke[edit.name] = {
                processMs: (cpuAfter.process - cpuBefore.process) / runs.length,
                mainThreadMs: (cpuAfter.thread - cpuBefore.thread) / runs.length,
            };
            progress(`${label}: ${edit.name}: renderer CPU per keystroke and undo ${JSON.stringify(result.cpuPerKeystroke[edit.name])}`);
            result.edits[edit.name] = runs;
        }
        if (after) await after(page, result, ide);
        mkdirSync(artifacts, { recursive: true });
        await screenshot(page, `bench-${label.replace(/\W+/g, '-')}`);
    } finally {
        await ide.stop();
        ws.dispose();
    }
    return result;
}

/** The renderer's CPU time so far (Chromium's ProcessTime and ThreadTime metrics, in ms; NaN when not reported). */
async function rendererCpu(cdp) {
    const { metrics } = await cdp.send('Performance.getMetrics');
    const value = (name) => (metrics.find((m) => m.name === name)?.value ?? NaN) * 1000;
    return { process: value('ProcessTime'), thread: value('ThreadTime') };
}

const APP = 'toast-service/TR.arcapp';

/** Picks the row of TR.arcapp on `platform` in the open quick pick of a command. */
async function pickApp(page, platform) {
    const row = page.locator('.quick-input-list .monaco-list-row', { hasText: APP }).filter({ hasText: platform }).first();
    await row.waitFor({ timeout: 30_000 });
    await row.click();
}

/** MontiArc: Generate for TR.arcapp on timesync, until its summary shows (a notification); resolves with the time it took. */
async function generation(page) {
    const started = Date.now();
    await runCommand(page, 'MontiArc: Generate');
    await pickApp(page, 'timesync');
    const pattern = /MontiArc: (generated \d+ files|nothing generated) for timesync/;
    const toasts = page.locator('.notifications-toasts .notification-toast');
    while (!(await toasts.allInnerTexts()).some((t) => pattern.test(t))) {
        if (Date.now() - started > 180_000) await fail('no summary of the generation within 180 s');
        await page.waitForTimeout(200);
    }
    return Date.now() - started;
}

/** How long the page takes to answer a trivial evaluation (a main thread busy with a long task answers late). */
async function roundTrip(page) {
    const t0 = Date.now();
    await page.evaluate(() => 1);
    return Date.now() - t0;
}

/**
 * Brings the diagram's tab to the front while the simulation runs. Playwright's click waits for
 * the page to draw (its actionability checks); the mouse-down a tab opens on, dispatched on the
 * element, does not: used when the click does not happen within 10 s, and recorded.
 */
async function diagramTabToFront(page, result) {
    const tab = page.locator('.tabs-container .tab', { hasText: 'MontiArc Diagram' }).first();
    const t0 = Date.now();
    try {
        await tab.click({ timeout: 10_000 });
        result.diagramTab = `clicked after ${Date.now() - t0} ms`;
    } catch (error) {
        await tab.dispatchEvent('mousedown', { button: 0 }).catch(() => undefined);
        await tab.dispatchEvent('mouseup', { button: 0 }).catch(() => undefined);
        result.diagramTab = `click timed out (${String(error?.message ?? error).split('\n')[0]}); mouse-down dispatched`;
    }
    progress(`simulation: the diagram's tab: ${result.diagramTab}`);
}

/** The backend's simulation status, asked from the page (its origin and token cookie). */
const simStatus = (page) => page.evaluate(async () => (await fetch('api/sim/status')).json());

/**
 * Starts TR.arcapp on timesync (lock-step, 1× real time) from the command palette with the diagram
 * open, lets it run `RUN_SECONDS` (the diagram's tab in front for the second half), and stops it:
 * phases 'simulation start' (until the inspector shows a port value), 'running simulation' and
 * 'stop'. Records the longest round trip of a page evaluation while it runs.
 */
async function simulation(page, result, longTasks) {
    const started = Date.now();
    const view = await longTasks.phase('simulation start', page, async () => {
        await runCommand(page, 'MontiArc: Start Simulation');
        await pickApp(page, 'timesync');
        const frame = await frameWith(page, '[data-testid=simulate-panel]', 'the simulate panel', 60_000);
        await frame.locator('[data-testid=port-inspector] [data-testid=port-value]').first().waitFor({ timeout: 300_000 });
        return frame;
    });
    result.simulationStartMs = Date.now() - started;
    progress(`simulation: first port value after ${result.simulationStartMs} ms`);
    const trips = [];
    await longTasks.phase('running simulation', page, async () => {
        // a lock-step run starts paused: resume it (1× real time)
        const resume = view.locator('[data-testid=sim-resume]');
        if (await resume.isEnabled().catch(() => false)) await resume.click({ timeout: 10_000 }).catch(() => undefined);
        const until = Date.now() + RUN_SECONDS * 1000;
        let diagramInFront = false;
        while (Date.now() < until) {
            trips.push(await roundTrip(page));
            if (!diagramInFront && Date.now() > until - (RUN_SECONDS * 1000) / 2) {
                diagramInFront = true;
                await diagramTabToFront(page, result);
            }
            await page.waitForTimeout(250);
        }
    });
    result.values = (await view.locator('[data-testid=port-inspector] [data-testid=port-value]').allTextContents()).length;
    result.status = (
        await view
            .locator('[data-testid=sim-status]')
            .textContent()
            .catch(() => '')
    )?.trim();
    result.longestRoundTripMs = Math.max(...trips);
    await longTasks.phase('stop', page, async () => {
        const t0 = Date.now();
        // F1 goes to the workbench, not to the webview that has the focus: focus the model's editor first.
        await page.evaluate((p) => window.maaHost.editorOf(p)?.focus(), ROBOT);
        await runCommand(page, 'MontiArc: Stop Simulation');
        while ((await simStatus(page)).running) {
            if (Date.now() - t0 > 60_000) await fail('the simulation still runs 60 s after MontiArc: Stop Simulation');
            await page.waitForTimeout(200);
        }
        result.stopMs = Date.now() - t0;
    });
    progress(
        `simulation: ${result.values} port values, longest round trip ${result.longestRoundTripMs} ms, stopped after ${result.stopMs} ms`,
    );
}

/** The main entry as maa-ide serves it to a browser that accepts br and gzip: encoding, bytes on the wire, cache headers. */
async function served(ide) {
    const index = readFileSync(path.join(appDir, PAGE), 'utf8');
    const entry = /src="\.\/(assets\/[^"]+\.js)"/.exec(index)?.[1];
    const get = (pathname, headers = {}) =>
        new Promise((resolve, reject) => {
            const req = http.get(new URL(pathname, ide.url), { headers: { authorization: `Bearer ${ide.token}`, ...headers } }, (res) => {
                let bytes = 0;
                res.on('data', (c) => {
                    bytes += c.length;
                });
                res.on('end', () => resolve({ status: res.statusCode, headers: res.headers, bytes }));
            });
            req.on('error', reject);
        });
    const accept = { 'accept-encoding': 'gzip, deflate, br' };
    const first = await get(entry, accept);
    const again = await get(entry, accept); // compressed on the fly: the second answer comes from the cache
    const page = await get(PAGE, accept);
    const revalidated = await get(PAGE, { ...accept, 'if-none-match': page.headers.etag ?? '' });
    return {
        entry,
        rawBytes: statSync(path.join(appDir, entry)).size,
        encoding: first.headers['content-encoding'] ?? 'identity',
        wireBytes: again.bytes,
        entryCacheControl: first.headers['cache-control'],
        pageCacheControl: page.headers['cache-control'],
        pageEtag: page.headers.etag,
        pageRevalidatedStatus: revalidated.status,
    };
}

const browser = await launchBrowser();
const longTasks = await LongTasks.attach(browser.context);
const results = [];
/** `--profile`: the CPU profile of the page's renderer (its main thread runs every same-site frame). */
async function startProfile(page) {
    const cdp = await page.context().newCDPSession(page);
    await cdp.send('Profiler.enable');
    await cdp.send('Profiler.setSamplingInterval', { interval: 1000 });
    await cdp.send('Profiler.start');
    return cdp;
}

async function stopProfile(cdp, name) {
    const { profile } = await cdp.send('Profiler.stop');
    await cdp.detach().catch(() => undefined);
    mkdirSync(artifacts, { recursive: true });
    const file = path.join(artifacts, `${name}.cpuprofile`);
    writeFileSync(file, JSON.stringify(profile));
    progress(`profile in ${path.relative(process.cwd(), file)}`);
}

let servedBundle;
let sim;
/** The example's steps after its loads and keystrokes: generation, a simulation, the bundle as served. */
async function exampleAfter(page, result, ide) {
    if (GENERATE) {
        result.generationMs = await longTasks.phase('generation', page, () => generation(page));
        progress(`generation: ${result.generationMs} ms`);
    }
    if (SIMULATE) {
        sim = {};
        const cdp = PROFILE ? await startProfile(page) : undefined;
        try {
            await simulation(page, sim, longTasks);
        } catch (error) {
            sim.error = String(error?.message ?? error).split('\n')[0];
            progress(`simulation failed: ${sim.error}`);
        } finally {
            if (cdp) await stopProfile(cdp, 'bench-simulation');
        }
    }
    servedBundle = await served(ide);
}
try {
    if (EXAMPLE)
        results.push(
            await benchWorkspace(
                'example (ToastServiceRobot)',
                undefined,
                undefined,
                [
                    { name: 'diagnostics', path: 'toast-service/toast/ToastServiceRobot.arc', needle: 'ctrl.distance', type: 'X' },
                    {
                        name: 'diagram',
                        path: 'toast-service/toast/ToastServiceRobot.arc',
                        needle: 'DistanceSensor dist',
                        type: 'Q',
                        expectInDiagram: 'distQ',
                    },
                ],
                browser,
                exampleAfter,
            ),
        );

    if (LARGE) await benchLarge();
} finally {
    await browser.close();
}

/** The generated model: loads, a keystroke in a composed component and an atomic one, the System diagram. */
async function benchLarge() {
    const big = freshWorkspace();
    const bigRoot = path.join(big.base, 'big');
    const { gen, types } = writeLargeModel(path.join(bigRoot, 'model'), COMPONENTS);
    const someAtomic = path.relative(bigRoot, gen.editable[0]).split(path.sep).join('/');
    // A composed component of the generated workspace (three subcomponents) for load and edits;
    // the System component with every component type as a subcomponent once, for the big diagram.
    const composedRel = path
        .relative(bigRoot, gen.files.find((f) => /C\d+_01\.arc$/.test(f)) ?? gen.files.find((f) => /C\d+_00\.arc$/.test(f)))
        .split(path.sep)
        .join('/');
    const composedText = readFileSync(path.join(bigRoot, composedRel), 'utf8');
    const instanceA = /^\s*(\S+ a)\(/m.exec(composedText)?.[1] ?? ' a';
    results.push(
        await benchWorkspace(
            `${COMPONENTS}-component model (${types} component types; diagram of ${path.basename(composedRel)})`,
            bigRoot,
            composedRel,
            [
                { name: 'diagram', path: composedRel, needle: instanceA, type: 'Q', expectInDiagram: 'aQ' },
                { name: 'diagnostics', open: someAtomic, path: someAtomic, needle: 'o1 = i1', type: 'X' },
                {
                    name: 'systemDiagram',
                    open: 'model/robot/System.arc',
                    openTimeout: 180_000,
                    path: 'model/robot/System.arc',
                    needle: ' x0',
                    type: 'Q',
                    expectUpdate: true,
                    runs: 3,
                },
            ],
            browser,
        ),
    );
    big.dispose();
}

const bundle = bundleSize();
const summary = results.map((r) => ({
    workspace: r.label,
    interactiveEditorMs: median(r.load.filter((l) => !l.cold).map((l) => l.interactiveMs)),
    coldInteractiveMs: median(r.load.filter((l) => l.cold).map((l) => l.interactiveMs)),
    firstDiagramMs: median(r.load.map((l) => l.diagramMs)),
    keystrokeToDiagnosticsMs: median((r.edits.diagnostics ?? []).map((e) => e.diagnosticsMs)),
    keystrokeToDiagramMs: median((r.edits.diagram ?? []).map((e) => e.diagramMs)),
    systemDiagramOpenMs: r.opened?.systemDiagram,
    systemKeystrokeToDiagramMs: median((r.edits.systemDiagram ?? []).map((e) => e.diagramMs)),
    generationMs: r.generationMs,
    cpuPerKeystroke: r.cpuPerKeystroke,
    runs: r.edits,
}));
const phases = longTasks.summary();
mkdirSync(artifacts, { recursive: true });
writeFileSync(
    path.join(artifacts, 'bench.json'),
    JSON.stringify({ summary, phases, simulation: sim, served: servedBundle, bundle, load: results.map((r) => r.load) }, null, 2),
);

/** The table's rows: figure, value, goal, met. */
function rows() {
    const example = summary.find((s) => s.workspace.startsWith('example'));
    const large = summary.find((s) => !s.workspace.startsWith('example'));
    const within = (ms, goal) => (Number.isFinite(ms) ? (ms <= goal ? 'met' : 'not met') : 'n/a');
    const out = [];
    for (const p of phases) {
        const frames = Object.entries(p.overByFrame)
            .map(([f, n]) => `${n} by ${f}`)
            .join(', ');
        out.push([
            `${p.phase}: longest task (tasks > ${LONG_TASK_MS} ms)`,
            `${fmt(p.longestMs)} (${p.over}${frames ? `: ${frames}` : ''}; ${(p.measuredMs / 1000).toFixed(0)} s observed)`,
            `≤ ${LONG_TASK_MS} ms`,
            p.over === 0 ? 'met' : 'not met',
        ]);
        if (p.ownProcessViserLongestMs > 0)
            out.push([`${p.phase}: longest task of viser (a process of its own)`, fmt(p.ownProcessViserLongestMs), '— (not the IDE)', '']);
    }
    if (sim && !sim.error) {
        out.push([
            'running simulation: longest page round trip',
            fmt(sim.longestRoundTripMs),
            `≤ ${LONG_TASK_MS} ms`,
            within(sim.longestRoundTripMs, LONG_TASK_MS),
        ]);
        out.push(['simulation start → first port value; Stop → stopped', `${fmt(sim.simulationStartMs)}; ${fmt(sim.stopMs)}`, '—', '']);
    } else if (SIMULATE) out.push(['simulation', `failed: ${sim?.error}`, '—', 'not met']);
    for (const [label, s] of [
        ['example', example],
        [`${COMPONENTS} components`, large],
    ]) {
        if (!s) continue;
        out.push([
            `${label}: time to interactive, cold (HTTP cache emptied)`,
            fmt(s.coldInteractiveMs),
            '≤ 2 s',
            within(s.coldInteractiveMs, 2000),
        ]);
        out.push([
            `${label}: time to interactive, warm (HTTP cache)`,
            fmt(s.interactiveEditorMs),
            '≤ 2 s',
            within(s.interactiveEditorMs, 2000),
        ]);
        out.push([`${label}: time to the first diagram`, fmt(s.firstDiagramMs), '—', '']);
        out.push([
            `${label}: keystroke → diagnostics`,
            fmt(s.keystrokeToDiagnosticsMs),
            '≤ 300 ms',
            within(s.keystrokeToDiagnosticsMs, 300),
        ]);
        out.push([`${label}: keystroke → diagram`, fmt(s.keystrokeToDiagramMs), '≤ 300 ms', within(s.keystrokeToDiagramMs, 300)]);
        if (s.systemDiagramOpenMs !== undefined) {
            out.push([`${label}: System (every type once): diagram after opening`, fmt(s.systemDiagramOpenMs), '—', '']);
            out.push([
                `${label}: System: keystroke → diagram`,
                fmt(s.systemKeystrokeToDiagramMs),
                '≤ 300 ms',
                within(s.systemKeystrokeToDiagramMs, 300),
            ]);
        }
    }
    if (example?.generationMs) out.push(['example: MontiArc: Generate (timesync) → summary', fmt(example.generationMs), '—', '']);
    if (servedBundle) {
        const b = servedBundle;
        const compressed = b.encoding === 'gzip' || b.encoding === 'br';
        out.push([`main bundle (${b.entry}) raw`, kb(b.rawBytes), '—', '']);
        out.push([
            'main bundle as served (Accept-Encoding: gzip, deflate, br)',
            `${kb(b.wireBytes)} ${b.encoding}`,
            'gzip or br',
            compressed ? 'met' : 'not met',
        ]);
        const got = results[0]?.load[0]?.mainScript;
        if (got)
            out.push([
                'main bundle as chromium got it (first load)',
                `${kb(got.encodedBytes)} on the wire for ${kb(got.decodedBytes)}`,
                'compressed',
                got.encodedBytes < got.decodedBytes ? 'met' : 'not met',
            ]);
        const cached =
            /immutable/.test(b.entryCacheControl ?? '') && /no-cache/.test(b.pageCacheControl ?? '') && b.pageRevalidatedStatus === 304;
        out.push([
            'cache headers (assets; index.html, its revalidation)',
            `${b.entryCacheControl}; ${b.pageCacheControl}, ETag → ${b.pageRevalidatedStatus}`,
            'immutable; no-cache + ETag',
            cached ? 'met' : 'not met',
        ]);
    }
    out.push([
        'JavaScript, all files (entry and its imports)',
        `${bundle.files} files, ${kb(bundle.totalBytes)} (${kb(bundle.totalGzipBytes)} gzip); entry ${kb(bundle.entryBytes)}`,
        '—',
        '',
    ]);
    return out;
}

if (asJson) {
    console.log(JSON.stringify({ summary, phases, simulation: sim, served: servedBundle, bundle }, null, 2));
} else {
    const table = rows();
    const width = (i) => Math.max(...table.map((r) => r[i].length));
    console.log(
        `\nIDE benchmark (medians of ${RUNS} keystrokes and of the loads; headless chromium without a GPU; long tasks in every frame)\n`,
    );
    for (const r of table) console.log(`  ${r[0].padEnd(width(0))}  ${r[1].padEnd(width(1))}  ${r[2].padEnd(width(2))}  ${r[3]}`);
    console.log(`\n(details in ${path.relative(process.cwd(), path.join(artifacts, 'bench.json'))})`);
}
