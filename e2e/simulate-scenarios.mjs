// Simulation in the browser IDE (issue 14): the MontiArc extension's web entry in VS Code's
// workbench (packages/vscode-extension/src/simulate/web.ts). The old IDE's scenario 7 ported to
// the workbench: MontiArc: Start Simulation from the command palette (timesync, TR.arcapp, the
// lock-step mode), the simulate view opens in a webview, a port value changes in its inspector,
// the viser canvas renders (a non-blank picture), the open diagram shows a live value, and
// MontiArc: Stop Simulation stops the run. Issue 19's polish on the way: Start disabled while the
// run runs, the 3D view resized by its drag handle and full screen, a reset starting the clock at
// 0, the port table keeping the last values after Stop. Each gets { page, url, workspace, shot(name) } (run.mjs).
import { fail, runCommand } from './host-kit.mjs';
import { startLockstepRun, until } from './lib.mjs';

/** How many different colours a PNG picture has (decoded by the browser on a blank page of its own). */
async function colours(page, png) {
    const scratch = await page.context().newPage();
    try {
        return await scratch.evaluate(async (data) => {
            const image = new Image();
            image.src = `data:image/png;base64,${data}`;
            await image.decode();
            const canvas = document.createElement('canvas');
            canvas.width = image.width;
            canvas.height = image.height;
            const g = canvas.getContext('2d');
            g.drawImage(image, 0, 0);
            const pixels = g.getImageData(0, 0, canvas.width, canvas.height).data;
            const seen = new Set();
            for (let i = 0; i < pixels.length && seen.size < 1000; i += 4)
                seen.add((pixels[i] << 16) | (pixels[i + 1] << 8) | pixels[i + 2]);
            return seen.size;
        }, png.toString('base64'));
    } finally {
        await scratch.close();
    }
}

/** The inspector's port values, joined. */
const inspectorValues = async (frame) =>
    (await frame.locator('[data-testid=port-inspector] [data-testid=port-value]').allTextContents()).join('|');

/** Waits until a port value in the inspector differs from the first one seen, stepping the lock-step run while it waits. */
async function portValueChanges(frame, page) {
    await frame.locator('[data-testid=port-inspector] [data-testid=port-value]').first().waitFor({ timeout: 90_000 });
    const first = await inspectorValues(frame);
    for (let i = 0; i < 120; i++) {
        const step = frame.locator('[data-testid=sim-step]');
        if (i % 10 === 0 && (await step.isEnabled().catch(() => false))) {
            await frame
                .locator('[data-testid=sim-steps]')
                .fill('25')
                .catch(() => undefined);
            await step.click().catch(() => undefined);
        }
        await page.waitForTimeout(500);
        const now = await inspectorValues(frame);
        if (now !== first && now.replace(/[–|]/g, '').length > 0) return;
    }
    await fail(`no port value changed in the inspector (values: ${first})`);
}

/**
 * The simulate view's polish (issue 19), during a lock-step run: Start is disabled while the run
 * runs, the drag handle resizes the 3D view, full screen fills the panel and Escape leaves it, and
 * a reset starts the simulated clock at 0 again.
 */
async function viewPolish(view, page, shot) {
    if (!(await view.locator('[data-testid=sim-start]').isDisabled())) await fail('Start is enabled while the simulation runs');
    if (!(await view.locator('[data-testid=sim-stop]').isEnabled())) await fail('Stop is disabled while the simulation runs');

    const viewer = view.locator('[data-testid=sim-viewer]');
    const before = await viewer.boundingBox();
    const handle = await view.locator('[data-testid=sim-split]').boundingBox();
    if (!before || !handle) await fail('the 3D view or its drag handle has no box');
    const y = handle.y + handle.height / 2;
    await page.mouse.move(handle.x + handle.width / 2, y);
    await page.mouse.down();
    await page.mouse.move(handle.x - 120, y, { steps: 6 });
    await page.mouse.up();
    const narrower = await viewer.boundingBox();
    if (!narrower || narrower.width > before.width - 60)
        await fail(`dragging the handle did not narrow the 3D view (${before.width} → ${narrower?.width})`);
    await shot('resized');

    const panel = await view.locator('[data-testid=simulate-panel]').boundingBox();
    await view.locator('[data-testid=sim-fullscreen]').click();
    const full = await viewer.boundingBox();
    if (!full || !panel || full.width < panel.width - 2 || full.height < panel.height - 2)
        await fail(`full screen does not fill the panel (${JSON.stringify(full)} in ${JSON.stringify(panel)})`);
    await shot('fullscreen');
    await page.keyboard.press('Escape');
    await until(page, 'Escape did not leave full screen', async () => ((await viewer.boundingBox())?.width ?? 0) < full.width - 60);

    // Reset: the simulated clock starts at 0 again (paused first, so no period runs after it)
    const status = view.locator('[data-testid=sim-status]');
    // a step of 50 periods pauses the run (if it was not) and takes the clock past 0.5 s
    await view.locator('[data-testid=sim-steps]').fill('50');
    await view.locator('[data-testid=sim-step]').click();
    await until(page, 'the run did not pause', async () => /paused/.test((await status.textContent()) ?? ''));
    await until(page, 'the clock did not pass 0.5 s before the reset', async () => {
        const t = /t (\d+\.\d+) s/.exec((await status.textContent()) ?? '');
        return !!t && Number(t[1]) > 0.5;
    });
    await view.locator('[data-testid=sim-reset]').click();
    await until(
        page,
        'the clock did not restart at 0 after the reset',
        async () => /t 0\.00 s/.test((await status.textContent()) ?? ''),
        60_000,
    );
    await view.locator('[data-testid=sim-resume]').click();
}

/** After Stop: the port table keeps the last values, marked as the last run's. */
async function lastValuesKept(view) {
    const note = view.locator('[data-testid=port-stale]');
    await note.waitFor({ state: 'visible', timeout: 30_000 }).catch(() => fail('no note marks the values of the stopped run'));
    if (!/Last values of the stopped run/.test((await note.textContent()) ?? '')) await fail(`the note says "${await note.textContent()}"`);
    const values = await inspectorValues(view);
    if (values.replace(/[–|]/g, '').length === 0) await fail(`the port table lost its values after Stop: "${values}"`);
    if (await view.locator('[data-testid=sim-start]').isDisabled()) await fail('Start is disabled after Stop');
}

/** The backend's simulation status, asked from the page (its origin and token cookie). */
const simStatus = (page) => page.evaluate(async () => (await fetch('api/sim/status')).json());

export const simulateScenarios = [
    {
        id: 's1-simulate',
        name: 'simulate in the workbench (lock-step): Start Simulation, a port value changes, the viser canvas renders, the diagram shows live values, Stop',
        async run({ page, url, shot }) {
            // The diagram of the application's top component, open beside the run; the run in the simulate view.
            const { view, diagram } = await startLockstepRun(page, url, { diagram: true });
            await page.locator('.tabs-container .tab', { hasText: 'MontiArc Simulation' }).first().waitFor({ timeout: 30_000 });
            // The extension's start command selected TR on timesync: the view names its mode.
            const mode = (await view.locator('[data-testid=sim-mode]').textContent()) ?? '';
            if (!/lock/i.test(mode)) await fail(`the mode for timesync is "${mode}", expected lock-step`);
            const viserFrame = view.locator('[data-testid=viser-frame]');
            await portValueChanges(view, page);
            await shot('running');

            // The open diagram shows live port values (the view posts them to the extension).
            await diagram
                .locator('.maa-value')
                .first()
                .waitFor({ state: 'attached', timeout: 30_000 })
                .catch(() => fail('the diagram shows no live port value'));

            // The viser canvas renders: a sized canvas, and a picture of more than a few colours.
            const viser = view.frameLocator('[data-testid=viser-frame]');
            await viser.locator('canvas').first().waitFor({ state: 'attached', timeout: 90_000 });
            const sizes = await viser.locator('canvas').evaluateAll((cs) => cs.map((c) => [c.width, c.height]));
            if (!sizes.some(([w, h]) => w >= 10 && h >= 10)) await fail(`no viser canvas has a size: ${JSON.stringify(sizes)}`);
            let distinct = 0;
            for (let i = 0; i < 60 && distinct < 16; i++) {
                distinct = await colours(page, await viserFrame.screenshot());
                if (distinct < 16) await page.waitForTimeout(1000);
            }
            await shot('viser');
            if (distinct < 16) await fail(`the viser view is blank (${distinct} colours)`);

            // The diagram's tab: its live values are drawn (visible, not only in the hidden webview).
            await page.locator('.tabs-container .tab', { hasText: 'MontiArc Diagram' }).first().click();
            await diagram
                .locator('.maa-value')
                .first()
                .waitFor({ state: 'visible', timeout: 30_000 })
                .catch(() => fail('the diagram tab shows no live port value'));
            await shot('diagram-live');

            // Back to the simulate view: its polish (issue 19).
            await page.locator('.tabs-container .tab', { hasText: 'MontiArc Simulation' }).first().click();
            await viewPolish(view, page, shot);

            // F1 goes to the workbench, not to the webview that has the focus: focus the model's editor first.
            await page.locator('.editor-instance .monaco-editor .view-line', { hasText: 'component ToastServiceRobot' }).first().click();
            await runCommand(page, 'MontiArc: Stop Simulation');
            const started = Date.now();
            while ((await simStatus(page)).running) {
                if (Date.now() - started > 60_000) await fail('the simulation still runs after MontiArc: Stop Simulation');
                await page.waitForTimeout(500);
            }
            await page.locator('.tabs-container .tab', { hasText: 'MontiArc Simulation' }).first().click();
            await lastValuesKept(view);
            await shot('stopped');
        },
    },
];
