// The simulate view's panels in the browser IDE (issue 19): a lock-step run of the example fills
// the state timeline; clicking its Toasting -> Serving transition reveals the transition's source
// line in the editor (and highlights the diagram when the diagram side offers
// maa.diagram.highlightTrace); the log lists the transition, stepping moves the selection, a plot
// draws a port's values. Each gets { page, url, workspace, shot(name) } (run.mjs).
import { readFileSync } from 'node:fs';
import path from 'node:path';
import { CONTROLLER, cursorLine, fail, frameWith, runCommand } from './host-kit.mjs';
import { startLockstepRun, until } from './lib.mjs';

const TOASTING_TO_SERVING = '[data-testid=transition-mark][data-from=Toasting][data-to=Serving]';

/** Waits until `locator` has an element (polled). */
async function waitForCount(page, locator, what, timeout) {
    const started = Date.now();
    while ((await locator.count()) === 0) {
        if (Date.now() - started > timeout) await fail(`${what} did not appear within ${timeout / 1000} s`);
        await page.waitForTimeout(500);
    }
}

/** The line of the selection's start in the editor showing `path` (`undefined`: no editor shows it). */
const selectionLine = (page, path) => page.evaluate((p) => window.maaHost.editorOf(p)?.getSelection()?.startLineNumber, path);

/** The 1-based line of `needle` in the workspace file `file`. */
function lineOf(workspace, file, needle) {
    const text = readFileSync(path.join(workspace, file), 'utf8');
    const i = text.split('\n').findIndex((l) => l.includes(needle));
    return i < 0 ? undefined : i + 1;
}

/** The time window the panels draw (`data-window`: "t0 t1"). */
async function windowOf(panels) {
    const [t0, t1] = ((await panels.getAttribute('data-window')) ?? '').split(' ').map(Number);
    return { t0, t1, width: t1 - t0 };
}

/**
 * The mouse over a plot, as a person uses it: the wheel zooms its time axis in around the pointer
 * (the window narrows, the axis labels change), a drag to the left pans to later times (the window
 * moves by about the dragged share of its width, keeping its width). Real wheel and pointer events
 * at the plot's place in the page (the webview is an iframe in an iframe of the workbench).
 */
async function wheelZoomAndDragPan(page, plot, panels) {
    const drawing = plot.locator('svg.maa-plot-svg');
    await drawing.scrollIntoViewIfNeeded();
    const box = await drawing.boundingBox();
    if (!box || box.width < 100) await fail(`the plot has no room to use the mouse on (${JSON.stringify(box)})`);
    const ticks = async () => (await plot.locator('.maa-plot-tick').allTextContents()).join(' ');
    const before = await windowOf(panels);
    const ticksBefore = await ticks();
    const x = box.x + box.width / 2;
    const y = box.y + box.height / 2;
    await page.mouse.move(x, y);
    await page.mouse.wheel(0, -300); // up: zoom in (by e^-1)
    let zoomed = before;
    await until(page, 'the wheel over the plot did not zoom in', async () => {
        zoomed = await windowOf(panels);
        return zoomed.width < before.width * 0.6;
    }).catch(() => fail(`the wheel over the plot did not zoom in (window ${before.width} → ${zoomed.width} s)`));
    // around the pointer: the time under it stays where it was (the middle of the plot)
    const middle = (w) => (w.t0 + w.t1) / 2;
    if (Math.abs(middle(zoomed) - middle(before)) > before.width * 0.05)
        await fail(`the zoom did not keep the time under the pointer (${middle(before)} → ${middle(zoomed)} s)`);
    await until(page, 'the time axis labels did not change with the zoom', async () => (await ticks()) !== ticksBefore);

    await page.mouse.move(x, y);
    await page.mouse.down();
    await page.mouse.move(x - box.width / 4, y, { steps: 8 });
    await page.mouse.up();
    let panned = zoomed;
    const expected = zoomed.t0 + zoomed.width / 4;
    await until(page, 'dragging the plot did not pan its time window', async () => {
        panned = await windowOf(panels);
        return Math.abs(panned.t0 - expected) < zoomed.width * 0.05;
    }).catch(() => fail(`dragging the plot did not pan (t0 ${zoomed.t0} → ${panned.t0} s, expected about ${expected} s)`));
    if (Math.abs(panned.width - zoomed.width) > zoomed.width * 1e-6)
        await fail(`panning changed the window's width (${zoomed.width} → ${panned.width} s)`);
}

export const panelsScenarios = [
    {
        id: 'p1-panels',
        name: 'simulate panels (lock-step): the state timeline shows Toasting -> Serving, clicking it reveals the source line; log, stepping and a plot',
        async run({ page, url, workspace, shot }) {
            const { view } = await startLockstepRun(page, url);
            await view.locator('[data-testid=sim-panels]').waitFor({ timeout: 60_000 });
            const pause = view.locator('[data-testid=sim-pause]');
            await pause.waitFor({ timeout: 60_000 });
            const started = Date.now();
            while (!(await view.locator('[data-testid=sim-speed]').isEnabled())) {
                if (Date.now() - started > 60_000) await fail('the speed cannot be set during the run');
                await page.waitForTimeout(250);
            }
            await view.locator('[data-testid=sim-speed]').selectOption('10');

            // the log lists the transitions taken; once Toasting -> Serving is among them, pause
            await view.locator('[data-testid=panels-tab-log]').click();
            await waitForCount(
                page,
                view.locator('[data-testid=log-entry]', { hasText: 'Toasting → Serving' }),
                'the Toasting -> Serving transition in the log',
                300_000,
            );
            await pause.click();

            // the state timeline: a row per automaton, bands named by state; All shows the whole run
            await view.locator('[data-testid=panels-tab-states]').click();
            await waitForCount(page, view.locator('[data-testid=states-row]'), 'a row of the state timeline', 30_000);
            await view.locator('[data-testid=panels-fit]').click();
            const mark = view.locator(TOASTING_TO_SERVING).first();
            await mark.waitFor({ timeout: 10_000 });
            await shot('timeline');
            const bands = await view.locator('[data-testid=state-band]').allTextContents();
            for (const state of ['Toasting', 'Serving'])
                if (!bands.includes(state)) await fail(`the state timeline shows no ${state} band (bands: ${bands.join(', ')})`);

            // click the transition: the cursor moves there, the editor shows its line
            const expected = lineOf(workspace, CONTROLLER, 'Toasting -> Serving');
            await view.locator(TOASTING_TO_SERVING).first().click();
            const selectedInfo = view.locator('[data-testid=states-selected]');
            await selectedInfo
                .filter({ hasText: 'Toasting → Serving' })
                .waitFor({ timeout: 10_000 })
                .catch(async () => fail(`the selected transition reads "${await selectedInfo.textContent()}"`));
            const selected = (await selectedInfo.textContent()) ?? '';
            const revealStarted = Date.now();
            let line;
            while ((line = await selectionLine(page, CONTROLLER)) !== expected) {
                if (Date.now() - revealStarted > 30_000)
                    await fail(`the editor of ${CONTROLLER} does not show line ${expected} (selection at ${line ?? 'no editor'})`);
                await page.waitForTimeout(250);
            }
            if ((await cursorLine(page, CONTROLLER)) !== expected) await fail(`the cursor of ${CONTROLLER} is not at line ${expected}`);
            await shot('revealed');
            // zooming in around the cursor (at the transition) narrows the time window
            const panels = view.locator('[data-testid=sim-panels]');
            const windowWidth = async () => {
                const [t0, t1] = ((await panels.getAttribute('data-window')) ?? '').split(' ').map(Number);
                return t1 - t0;
            };
            const wideWindow = await windowWidth();
            await view.locator('[data-testid=panels-zoom-in]').click();
            await view.locator('[data-testid=panels-zoom-in]').click();
            const zoomStarted = Date.now();
            while (!((await windowWidth()) <= wideWindow / 3)) {
                if (Date.now() - zoomStarted > 10_000)
                    await fail(`zooming in did not narrow the time window (${wideWindow} → ${await windowWidth()} s)`);
                await page.waitForTimeout(200);
            }
            if ((await view.locator(TOASTING_TO_SERVING).count()) === 0) await fail('the selected transition left the zoomed window');
            // the open diagram highlights the trace point (maa.diagram.highlightTrace): the state, the transition or the instance's chip
            const diagram = await frameWith(page, '[data-testid=diagram]', 'the diagram', 30_000);
            await diagram
                .locator('.maa-state-highlight, .maa-transition-highlight, .maa-chip-highlight')
                .first()
                .waitFor({ state: 'attached', timeout: 30_000 })
                .catch(() => fail('the diagram highlights nothing of the selected transition'));

            // the log marks it; stepping to the previous transition of the component moves the selection
            await view.locator('[data-testid=panels-tab-log]').click();
            const entry = view.locator('[data-testid=log-entry]', { hasText: 'Toasting → Serving' }).first();
            await entry.waitFor({ timeout: 10_000 });
            if (!(await entry.getAttribute('class'))?.includes('maa-selected')) await fail('the log does not mark the selected transition');
            await view.locator('[data-testid=panels-tab-states]').click();
            await view.locator('[data-testid=transition-prev]').click();
            const stepStarted = Date.now();
            let before = selected;
            while (before === selected) {
                if (Date.now() - stepStarted > 10_000) await fail(`stepping back did not select the previous transition ("${before}")`);
                await page.waitForTimeout(200);
                before = (await selectedInfo.textContent()) ?? '';
            }
            if (!/ctrl: .* → /.test(before)) await fail(`stepping back selected "${before}", not a transition of ctrl`);

            // a plot of a port's values
            await view.locator('[data-testid=panels-tab-plots]').click();
            const plot = view.locator('[data-testid=plot]').first();
            await waitForCount(page, plot.locator('[data-testid=plot-topic] option'), 'a topic to plot', 10_000);
            const topics = await plot.locator('[data-testid=plot-topic] option').allTextContents();
            const topic = topics.find((t) => t.includes('distance')) ?? topics[0];
            if (!topic) await fail('the plot offers no topic with numeric values');
            await plot.locator('[data-testid=plot-topic]').selectOption(topic);
            await plot.locator('[data-testid=plot-add-series]').click();
            // a path with a move and at least one line (a flat one has no height: attached, not visible)
            await plot.locator('.maa-plot-line').first().waitFor({ state: 'attached', timeout: 10_000 });
            const d = (await plot.locator('.maa-plot-line').first().getAttribute('d')) ?? '';
            if (!/^M [-\d.]+ [-\d.]+ .*H/.test(d)) await fail(`the plot's line is "${d}"`);
            await shot('plot');
            await wheelZoomAndDragPan(page, plot, panels);
            await shot('plot-zoomed');

            // Live clears the cursor
            await view.locator('[data-testid=panels-live]').click();
            await page.locator('.editor-instance .monaco-editor .view-line').first().click();
            await runCommand(page, 'MontiArc: Stop Simulation');
        },
    },
];
