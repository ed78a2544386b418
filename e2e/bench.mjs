#!/usr/bin/env node
// The IDE benchmark (issue 7; a measurement, not a test): maa-ide on a fresh copy of examples/
// and on a generated 200-component model, Debian's chromium through playwright-core.
// Reports medians of: time to interactive editor (and to the first diagram), keystroke →
// updated diagnostics, keystroke → updated diagram; and the JavaScript bundle size of the app.
//
// The IDE is VS Code's workbench with the MontiArc extension; the diagram is the extension's webview.
//
//   node e2e/bench.mjs [--runs N] [--components N] [--json]
import { readdirSync, statSync, readFileSync, writeFileSync, mkdirSync } from 'node:fs';
import path from 'node:path';
import { gzipSync } from 'node:zlib';
import { appDir, artifacts, freshWorkspace, launchBrowser, screenshot, startIde, writeLargeModel } from './lib.mjs';

const args = process.argv.slice(2);
const option = (name, fallback) => (args.includes(name) ? args[args.indexOf(name) + 1] : fallback);
const RUNS = Number(option('--runs', '5'));
const COMPONENTS = Number(option('--components', '200'));
const asJson = args.includes('--json');
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
    return { interactiveMs: timings.editor, readyMs: timings.ready, diagramMs };
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

async function benchWorkspace(label, workspaceFrom, startFile, edits, browser) {
    const ws = freshWorkspace(workspaceFrom);
    const ide = await startIde(ws.workspace);
    const result = { label, load: [], edits: {} };
    try {
        const { page } = browser;
        await ide.login(page);
        for (let i = 0; i < Math.max(2, Math.min(RUNS, 3)); i++) {
            result.load.push(await loadIde(page, ide.url, startFile ?? edits[0]?.path));
            progress(`${label}: load ${i + 1}: ${JSON.stringify(result.load.at(-1))}`);
        }
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
            for (let i = 0; i < (edit.runs ?? RUNS); i++) {
                runs.push(await keystroke(page, edit));
                progress(`${label}: ${edit.name} ${i + 1}: ${JSON.stringify(runs.at(-1))}`);
            }
            result.edits[edit.name] = runs;
        }
        mkdirSync(artifacts, { recursive: true });
        await screenshot(page, `bench-${label.replace(/\W+/g, '-')}`);
    } finally {
        await ide.stop();
        ws.dispose();
    }
    return result;
}

const browser = await launchBrowser();
const results = [];
try {
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
        ),
    );

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
} finally {
    await browser.close();
}

const bundle = bundleSize();
const summary = results.map((r) => ({
    workspace: r.label,
    interactiveEditorMs: median(r.load.map((l) => l.interactiveMs)),
    firstLoadInteractiveMs: r.load[0]?.interactiveMs,
    firstDiagramMs: median(r.load.map((l) => l.diagramMs)),
    keystrokeToDiagnosticsMs: median((r.edits.diagnostics ?? []).map((e) => e.diagnosticsMs)),
    keystrokeToDiagramMs: median((r.edits.diagram ?? []).map((e) => e.diagramMs)),
    systemDiagramOpenMs: r.opened?.systemDiagram,
    systemKeystrokeToDiagramMs: median((r.edits.systemDiagram ?? []).map((e) => e.diagramMs)),
    runs: r.edits,
}));
mkdirSync(artifacts, { recursive: true });
writeFileSync(path.join(artifacts, 'bench.json'), JSON.stringify({ summary, bundle, load: results.map((r) => r.load) }, null, 2));
if (asJson) {
    console.log(JSON.stringify({ summary, bundle }, null, 2));
} else {
    console.log(`\nIDE benchmark (medians of ${RUNS} keystrokes; loads with a warm HTTP cache after the first)`);
    for (const s of summary) {
        console.log(`\n${s.workspace}`);
        console.log(`  time to interactive editor      ${fmt(s.interactiveEditorMs)} (first load ${fmt(s.firstLoadInteractiveMs)})`);
        console.log(`  time to the first diagram       ${fmt(s.firstDiagramMs)}`);
        console.log(`  keystroke → updated diagnostics ${fmt(s.keystrokeToDiagnosticsMs)}`);
        console.log(`  keystroke → updated diagram     ${fmt(s.keystrokeToDiagramMs)}`);
        if (s.systemDiagramOpenMs !== undefined) {
            console.log(
                `  System (every component type as a subcomponent): diagram after opening ${fmt(s.systemDiagramOpenMs)}, keystroke → diagram ${fmt(s.systemKeystrokeToDiagramMs)}`,
            );
        }
    }
    console.log(
        `\nJavaScript bundle: ${bundle.files} files, ${kb(bundle.totalBytes)} (${kb(bundle.totalGzipBytes)} gzip); ` +
            `entry ${kb(bundle.entryBytes)} (${kb(bundle.entryGzipBytes)} gzip); workers ${kb(bundle.workerBytes)}`,
    );
    console.log(`  largest: ${bundle.largest.map((f) => `${f.file} ${kb(f.bytes)}`).join(', ')}`);
    console.log(`\n(details in ${path.relative(process.cwd(), path.join(artifacts, 'bench.json'))})`);
}
