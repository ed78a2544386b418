// Simulation in the browser IDE (issue 14): the MontiArc extension's web entry in VS Code's
// workbench (packages/vscode-extension/src/simulate/web.ts). The old IDE's scenario 7 ported to
// the workbench: MontiArc: Start Simulation from the command palette (timesync, TR.arcapp, the
// lock-step mode), the simulate view opens in a webview, a port value changes in its inspector,
// the viser canvas renders (a non-blank picture), the open diagram shows a live value, and
// MontiArc: Stop Simulation stops the run. Each gets { page, url, workspace, shot(name) } (run.mjs).
import { fail, frameWith, openHost, ROBOT, runCommand } from './host-kit.mjs';

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

/** The backend's simulation status, asked from the page (its origin and token cookie). */
const simStatus = (page) => page.evaluate(async () => (await fetch('api/sim/status')).json());

export const simulateScenarios = [
    {
        id: 's1-simulate',
        name: 'simulate in the workbench (lock-step): Start Simulation, a port value changes, the viser canvas renders, the diagram shows live values, Stop',
        async run({ page, url, shot }) {
            await openHost(page, url, ROBOT);
            // The diagram of the application's top component, open beside the run.
            await runCommand(page, 'MontiArc: Open Diagram');
            const diagram = await frameWith(page, '[data-testid=diagram] .maa-component', 'the diagram of ToastServiceRobot', 90_000);

            await runCommand(page, 'MontiArc: Start Simulation');
            const row = page
                .locator('.quick-input-list .monaco-list-row', { hasText: 'toast-service/TR.arcapp' })
                .filter({ hasText: 'timesync' })
                .first();
            await row.waitFor({ timeout: 30_000 });
            await row.click();
            await page.locator('.tabs-container .tab', { hasText: 'MontiArc Simulation' }).first().waitFor({ timeout: 30_000 });
            const view = await frameWith(page, '[data-testid=simulate-panel]', 'the simulate panel', 60_000);
            // The view lists the applications, then the extension's start command selects TR on timesync.
            const modeShown = Date.now();
            let mode = '';
            while (!/lock/i.test(mode)) {
                if (Date.now() - modeShown > 60_000) await fail(`the mode for timesync is "${mode}", expected lock-step`);
                await page.waitForTimeout(250);
                mode = (await view.locator('[data-testid=sim-mode]').textContent()) ?? '';
            }
            // The run starts (generation and the simulator take a while on a busy machine).
            const viserFrame = view.locator('[data-testid=viser-frame]');
            await viserFrame.waitFor({ timeout: 240_000 });
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

            // F1 goes to the workbench, not to the webview that has the focus: focus the model's editor first.
            await page.locator('.editor-instance .monaco-editor .view-line', { hasText: 'component ToastServiceRobot' }).first().click();
            await runCommand(page, 'MontiArc: Stop Simulation');
            const started = Date.now();
            while ((await simStatus(page)).running) {
                if (Date.now() - started > 60_000) await fail('the simulation still runs after MontiArc: Stop Simulation');
                await page.waitForTimeout(500);
            }
            await shot('stopped');
        },
    },
];
