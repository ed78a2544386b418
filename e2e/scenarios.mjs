import { readFileSync, writeFileSync } from 'node:fs';
import path from 'node:path';
import { artifacts, writeLargeModel } from './lib.mjs';
import { cliDiagram, diagramClasses, diagramIds, diagramRoutes, diagramTexts, idDifference, sameRoute } from './svg-compare.mjs';

// The e2e scenarios of issue 7, in order. Each gets { page, url, workspace, shot(name) }.
const ROBOT = 'toast-service/toast/ToastServiceRobot.arc';
const ARM = 'toast-service/toast/ArmController.arc';
const mod = process.platform === 'darwin' ? 'Meta' : 'Control';

async function fail(message) {
    throw new Error(message);
}

/** Loads the app and waits for the workbench (editor, language client, diagram). */
export async function openIde(page, url) {
    await page.goto(url);
    await page.waitForFunction(() => window.maaIde?.ready === true, undefined, { timeout: 60_000 });
}

async function openFile(page, path) {
    await page.locator(`[data-testid=explorer] .tree-row[data-path="${path}"]`).click();
    await page.locator(`[data-testid=editor-tabs] .tab.active[data-path="${path}"]`).waitFor({ timeout: 10_000 });
}

async function select(page, needle, options) {
    const ok = await page.evaluate(([n, o]) => window.maaIde.select(n, o), [needle, options ?? {}]);
    if (!ok) await fail(`"${needle}" not found in the active editor`);
}

const text = (page, path) => page.evaluate((p) => window.maaIde.text(p), path);

async function waitForModelText(page, path, predicate, what, timeout = 15_000) {
    const started = Date.now();
    for (;;) {
        const current = await text(page, path);
        if (current !== undefined && predicate(current)) return current;
        if (Date.now() - started > timeout) await fail(`${path}: ${what} (text now:\n${current})`);
        await page.waitForTimeout(200);
    }
}

const diagram = (page) => page.locator('[data-testid=diagram]');

/** Exports the shown diagram in the IDE and compares its element ids and label texts with `maa-gen diagram ARGS`'s SVG. */
async function compareExport(page, args, what) {
    const download = page.waitForEvent('download', { timeout: 15_000 });
    await page.locator('[data-testid=diagram-export]').click();
    const ide = readFileSync(await (await download).path(), 'utf8');
    const cli = await cliDiagram(args);
    const ideIds = diagramIds(ide);
    const cliIds = diagramIds(cli);
    if (ideIds.length < 10) await fail(`${what}: the IDE's export has only ${ideIds.length} elements with ids`);
    const { onlyFirst, onlySecond } = idDifference(ideIds, cliIds);
    if (onlyFirst.length || onlySecond.length || ideIds.length !== cliIds.length) {
        await fail(
            `${what}: the IDE's export and maa-gen diagram differ (${ideIds.length} vs ${cliIds.length} ids)\n` +
                `  only in the IDE's: ${onlyFirst.join(', ')}\n  only in maa-gen's: ${onlySecond.join(', ')}`,
        );
    }
    // Both documents beside the screenshots, for a look at what differs.
    const name = args[0].split('.').pop() + (args.includes('--automaton') ? '-automaton' : '');
    writeFileSync(path.join(artifacts, `5c-ide-${name}.svg`), ide);
    writeFileSync(path.join(artifacts, `5c-maa-gen-${name}.svg`), cli);
    const ideTexts = diagramTexts(ide);
    const cliTexts = diagramTexts(cli);
    const differing = [...ideTexts].filter(([id, text]) => cliTexts.get(id) !== text);
    if (differing.length || ideTexts.size !== cliTexts.size) {
        await fail(
            `${what}: labels differ: ${differing.map(([id, text]) => `${id}: "${text}" vs "${cliTexts.get(id)}"`).join('; ')} (${ideTexts.size} vs ${cliTexts.size} texts)`,
        );
    }
    const ideClasses = diagramClasses(ide);
    const cliClasses = diagramClasses(cli);
    const otherClasses = [...ideClasses].filter(([id, cls]) => cliClasses.get(id) !== cls);
    if (otherClasses.length) {
        await fail(`${what}: classes differ: ${otherClasses.map(([id, cls]) => `${id}: "${cls}" vs "${cliClasses.get(id)}"`).join('; ')}`);
    }
    // Connectors and transitions take the same way (maa-gen routes them as Sprotty does).
    const ideRoutes = diagramRoutes(ide);
    const cliRoutes = diagramRoutes(cli);
    const otherRoutes = [...ideRoutes].filter(([id, route]) => !sameRoute(route, cliRoutes.get(id)));
    if (ideRoutes.size === 0 || otherRoutes.length) {
        await fail(`${what}: ${ideRoutes.size} routes, these differ: ${otherRoutes.map(([id]) => id).join(', ')}`);
    }
    console.log(
        `    ${what}: ${ideIds.length} elements with their classes, ${ideTexts.size} labels and ${ideRoutes.size} edge routes alike`,
    );
}

export const scenarios = [
    {
        id: '1-open',
        name: 'open the example: editor and diagram visible',
        async run({ page, url, shot }) {
            await openIde(page, url);
            await page.locator('[data-testid=editor] .monaco-editor').waitFor({ state: 'visible' });
            await page.locator(`[data-testid=editor-tabs] .tab.active[data-path="${ROBOT}"]`).waitFor();
            await page.locator('[data-testid=editor] .view-lines', { hasText: 'component ToastServiceRobot' }).waitFor();
            await page.locator('[data-testid=explorer] .tree-row[data-path$="ArmController.arc"]').waitFor();
            await diagram(page).locator('.maa-component').first().waitFor({ state: 'visible', timeout: 20_000 });
            const components = await diagram(page).locator('.maa-component').count();
            if (components < 8) await fail(`the diagram shows ${components} components, expected the robot and its 7 subcomponents`);
            await diagram(page).locator('.maa-port').first().waitFor();
            await diagram(page).locator('.maa-connector').first().waitFor();
            // The Controller has an automaton: the toggle shows its state machine and back.
            await openFile(page, 'toast-service/toast/Controller.arc');
            const toggle = page.locator('[data-testid=diagram-switch]');
            await toggle.waitFor({ state: 'visible' });
            await toggle.click();
            await diagram(page).locator('.maa-state', { hasText: 'Toasting' }).first().waitFor({ timeout: 15_000 });
            await shot('automaton');
            await toggle.click();
            await diagram(page).locator('.maa-state').first().waitFor({ state: 'detached', timeout: 15_000 });
        },
    },
    {
        id: '2-error',
        name: 'introduce an error: problems panel and diagram show it',
        async run({ page, url, shot }) {
            await openIde(page, url);
            await diagram(page).locator('.maa-component').first().waitFor({ timeout: 20_000 });
            // Remove the connector that feeds the arm controller: its input `cmd` is left unconnected (an error).
            await select(page, '  ctrl.arm -> arm.cmd;\n');
            await page.keyboard.press('Delete');
            const problem = page
                .locator('[data-testid=problems] .problem.error[data-path$="ToastServiceRobot.arc"]', { hasText: 'cmd' })
                .first();
            await problem.waitFor({ timeout: 15_000 });
            await page.locator('[data-testid=editor-tabs] .tab.active.dirty').waitFor();
            await diagram(page).locator('.maa-error').first().waitFor({ timeout: 15_000 });
            const marked = await diagram(page).locator('.maa-component.maa-error[data-instance-path=arm]').count();
            if (!marked) await fail('the diagram does not mark the subcomponent "arm"');
            await page.locator('[data-testid=status-problems]').waitFor();
            await shot('problems-and-diagram');
            // Clicking the problem jumps to it.
            await problem.click();
            const line = await page.evaluate(() => window.maaIde.editor.getPosition().lineNumber);
            if (line !== 18) await fail(`the problem's click went to line ${line}, expected 18 (the instance "arm")`);
        },
    },
    {
        id: '3-quickfix',
        name: 'fix the error with a quick fix (Ctrl+.)',
        async run({ page, shot, workspace }) {
            // Continues the previous scenario: the cursor is on the problem.
            await select(page, 'ArmController arm;', { offset: 15, length: 0 });
            await page.keyboard.press(`${mod}+Period`);
            const menu = page.locator('.action-widget');
            await menu.locator('[role=option]', { hasText: 'arm.cmd' }).first().waitFor({ timeout: 10_000 });
            await shot('quick-fix-menu');
            // Move the focus to the fix and apply it with Enter (the menu blocks pointer events around it).
            for (let i = 0; i < 10; i++) {
                const focused = await menu
                    .locator('[role=option].focused')
                    .getAttribute('aria-label')
                    .catch(() => null);
                if (focused?.includes('arm.cmd')) break;
                await page.keyboard.press('ArrowDown');
            }
            await page.keyboard.press('Enter');
            await waitForModelText(page, ROBOT, (t) => t.includes('ctrl.arm -> arm.cmd;'), 'the quick fix did not connect the port');
            await page.waitForFunction((p) => !window.maaIde.markers().some((m) => m.path === p && m.severity === 8), ROBOT, {
                timeout: 15_000,
            });
            await page
                .locator('[data-testid=problems] .problem.error[data-path$="ToastServiceRobot.arc"]')
                .first()
                .waitFor({ state: 'detached', timeout: 15_000 });
            await diagram(page).locator('.maa-error').first().waitFor({ state: 'detached', timeout: 15_000 });
            // Ctrl+S saves the file (PUT /api/file): the dirty marker goes, the disk has the fix.
            await page.keyboard.press(`${mod}+KeyS`);
            await page.locator('[data-testid=editor-tabs] .tab.active:not(.dirty)').waitFor({ timeout: 10_000 });
            const onDisk = readFileSync(path.join(workspace, ROBOT), 'utf8');
            if (!onDisk.includes('ctrl.arm -> arm.cmd;')) await fail('the saved file lacks the fix');
        },
    },
    {
        id: '4-completion',
        name: 'completion inside a RobotArm block (ArmController.arc)',
        async run({ page, url, shot }) {
            await openIde(page, url);
            // Ctrl+P: quick open.
            await page.keyboard.press(`${mod}+KeyP`);
            await page.locator('[data-testid=quick-open]').fill('ArmContr');
            await page.keyboard.press('Enter');
            await page.locator(`[data-testid=editor-tabs] .tab.active[data-path="${ARM}"]`).waitFor({ timeout: 10_000 });
            // After the last statement of LoadBread.
            await select(page, 'move toaster; open; move top;', { offset: 'move toaster; open; move top;'.length });
            await page.keyboard.type(' move ab');
            // The server has the new text once it reports the unfinished `ab`; only then ask for completion,
            // so that the request is not raced by Monaco's own quick suggestions on the keystrokes.
            await page
                .waitForFunction((p) => window.maaIde.markers().some((m) => m.path === p && m.message.includes("'ab'")), ARM, {
                    timeout: 30_000,
                })
                .catch(() => fail("the server did not report the unfinished 'ab'"));
            await page.keyboard.press('Escape');
            const suggest = page.locator('.suggest-widget.visible');
            const item = suggest.locator('.monaco-list-row', { hasText: 'aboveBreadbox' }).first();
            await page.keyboard.press(`${mod}+Space`);
            // On a machine with every core busy the answer can take long.
            await item.waitFor({ timeout: 30_000 });
            await shot('completion');
            await suggest.locator('.monaco-list-row', { hasText: 'aboveBreadbox' }).first().click();
            await page.keyboard.type(';');
            await waitForModelText(page, ARM, (t) => t.includes('move top; move aboveBreadbox;'), 'the completion was not inserted');
            await page.waitForTimeout(1500);
            const errors = await page.evaluate(
                (p) => window.maaIde.markers().filter((m) => m.path === p && m.severity === 8 && !m.message.includes('package')),
                ARM,
            );
            if (errors.length) await fail(`errors after the completion: ${JSON.stringify(errors)}`);
        },
    },
    {
        id: '5-rename',
        name: 'rename a port (F2): references and the diagram follow',
        async run({ page, url, shot }) {
            await openIde(page, url);
            await diagram(page).locator('.maa-component').first().waitFor({ timeout: 20_000 });
            const before = await diagram(page).textContent();
            if (before.includes('progress')) await fail('the diagram shows "progress" before the rename');
            await select(page, 'arm.status', { offset: 5, length: 0 });
            await page.keyboard.press('F2');
            // The rename box takes the focus once the server answered prepareRename.
            await page.waitForFunction(() => document.activeElement?.classList.contains('rename-input'), undefined, { timeout: 10_000 });
            await page.locator('input.rename-input').fill('progress');
            await page.keyboard.press('Enter');
            await waitForModelText(page, ARM, (t) => /out\s+ArmStatus\s+progress/.test(t), 'the port declaration was not renamed');
            await waitForModelText(page, ROBOT, (t) => t.includes('arm.progress -> ctrl.armStatus'), 'the connector was not renamed');
            await page
                .waitForFunction(() => document.querySelector('[data-testid=diagram]')?.textContent?.includes('progress'), undefined, {
                    timeout: 15_000,
                })
                .catch(() => fail('the diagram does not show the renamed port "progress"'));
            await shot('renamed');
        },
    },
    {
        id: '5b-diagram',
        name: 'diagram: selection synced both ways, port types on hover, stable layout on edits, SVG export',
        async run({ page, url, shot }) {
            await openIde(page, url);
            const arm = diagram(page).locator('.maa-component[data-instance-path=arm]').first();
            await arm.waitFor({ timeout: 20_000 });
            // Text → diagram: the cursor on the instance declaration selects its node.
            await select(page, 'ArmController arm;', { offset: 15, length: 0 });
            await diagram(page)
                .locator('.maa-component.selected[data-instance-path=arm]')
                .waitFor({ timeout: 10_000 })
                .catch(() => fail('the cursor on "ArmController arm;" did not select the node "arm"'));
            // Diagram → text: clicking the node "ctrl" moves the cursor to its declaration (line 15).
            await diagram(page).locator('.maa-component[data-instance-path=ctrl] .maa-label-type').first().click();
            await page
                .waitForFunction(() => window.maaIde.editor.getPosition()?.lineNumber === 15, undefined, { timeout: 10_000 })
                .catch(async () =>
                    fail(
                        `clicking the node "ctrl" moved the cursor to line ${await page.evaluate(() => window.maaIde.editor.getPosition()?.lineNumber)}, expected 15`,
                    ),
                );
            // Port types on hover (the SVG title of the port).
            const portTitle = await diagram(page).locator('.maa-port[data-port-path="arm.status"] title').first().textContent();
            if (!/ArmStatus/.test(portTitle ?? ''))
                await fail(`the hover text of arm.status is "${portTitle}", expected its type ArmStatus`);
            // An edit elsewhere in the file updates the diagram without moving the nodes.
            const before = await arm.boundingBox();
            const updates = await page.evaluate(() => window.maaIde.diagramUpdates);
            await select(page, 'ArmController arm;', { offset: 'ArmController arm;'.length, length: 0 });
            await page.keyboard.type(' // the arm');
            await page
                .waitForFunction((n) => window.maaIde.diagramUpdates > n, updates, { timeout: 10_000 })
                .catch(() => fail('the diagram did not update after the edit'));
            await page.waitForTimeout(600); // the update animation
            const after = await arm.boundingBox();
            if (!before || !after || Math.abs(before.x - after.x) > 3 || Math.abs(before.y - after.y) > 3) {
                await fail(`the node "arm" moved on an unrelated edit: ${JSON.stringify(before)} → ${JSON.stringify(after)}`);
            }
            // Export SVG downloads a standalone SVG of the shown diagram.
            const download = page.waitForEvent('download', { timeout: 15_000 });
            await page.locator('[data-testid=diagram-export]').click();
            const file = await (await download).path();
            const svgText = readFileSync(file, 'utf8');
            if (
                !svgText.includes('<svg') ||
                !svgText.includes('xmlns="http://www.w3.org/2000/svg"') ||
                !svgText.includes('ToastServiceRobot')
            ) {
                await fail(`the exported SVG lacks the diagram (${svgText.length} bytes: ${svgText.slice(0, 200)})`);
            }
            await shot('diagram');
        },
    },
    {
        id: '5c-diagram-export',
        name: "diagram export: the IDE's Export SVG and maa-gen diagram hold the same elements, classes, labels and edge routes",
        async run({ page, url, workspace, shot }) {
            await openIde(page, url);
            await diagram(page).locator('.maa-component[data-instance-path=arm]').first().waitFor({ timeout: 20_000 });
            const root = path.join(workspace, 'toast-service');
            // The C&C view of the example's robot, then the state machine of its Controller.
            await compareExport(page, ['toast.ToastServiceRobot', '--root', root], 'C&C view of toast.ToastServiceRobot');
            await openFile(page, 'toast-service/toast/Controller.arc');
            const toggle = page.locator('[data-testid=diagram-switch]');
            await toggle.waitFor({ state: 'visible' });
            await toggle.click();
            await diagram(page).locator('.maa-state', { hasText: 'Toasting' }).first().waitFor({ timeout: 15_000 });
            await compareExport(page, ['toast.Controller', '--automaton', '--root', root], 'state machine of toast.Controller');
            await shot('automaton');
        },
    },
    {
        id: '6-generate',
        name: 'generate for rospython and open a generated node',
        async run({ page, url, shot }) {
            await openIde(page, url);
            await page.locator('[data-testid=generate-tab]').click();
            const panel = page.locator('[data-testid=generate-panel]');
            const value = await panel
                .locator('select option')
                .evaluateAll((options) => options.map((o) => o.value).find((v) => v.endsWith('\u0000rospython')));
            if (!value) await fail('no rospython platform in the picker');
            await panel.locator('select').selectOption(value);
            await panel.locator('[data-testid=generate-button]').click();
            await panel.locator('.generate-status.ok, .generate-status.failed').waitFor({ timeout: 120_000 });
            const status = await panel.locator('.generate-status').textContent();
            if (!(await panel.locator('.generate-status.ok').count())) await fail(`generation failed: ${status}`);
            const files = await panel
                .locator('[data-testid=generated-files] .tree-row.file')
                .evaluateAll((rows) => rows.map((r) => r.dataset.path));
            const node = files.find((f) => /controller.*\.py$/i.test(f) && !/toaster|arm/i.test(f)) ?? files.find((f) => f.endsWith('.py'));
            if (!node) await fail(`no generated Python node among ${files.join(', ')}`);
            await panel.locator(`[data-testid=generated-files] .tree-row.file[data-path="${node}"]`).click();
            await panel.locator('[data-testid=generated-preview] .view-lines', { hasText: 'class' }).first().waitFor({ timeout: 10_000 });
            await shot('generated-node');
            // Navigation from the generated code to the model through the trace.
            const link = panel.locator('[data-testid=trace-link]');
            const lineWithTrace = await page.evaluate(() => {
                const lines = document.querySelectorAll('[data-testid=generated-preview] .view-line');
                return lines.length;
            });
            if (lineWithTrace > 0) {
                await page.locator('[data-testid=generated-preview] .view-lines', { hasText: 'class' }).first().click();
                // Move the cursor through the file until a traced line is found.
                for (let i = 0; i < 60 && !(await link.count()); i++) await page.keyboard.press('ArrowDown');
                if (!(await link.count())) await fail('no generated line of the node is traced to the model');
                await link.click();
                await page.waitForFunction(() => window.maaIde.editor.getModel()?.uri.path.endsWith('.arc'), undefined, {
                    timeout: 10_000,
                });
            }
            // And back: "Show Generated Code" on the Controller's automaton.
            await openFile(page, 'toast-service/toast/Controller.arc');
            await select(page, 'state Toasting', { offset: 6, length: 0 });
            await page.keyboard.press(`${mod}+Alt+KeyG`);
            await page.waitForFunction(
                () => /controller/i.test(document.querySelector('[data-testid=generated-files] .tree-row.selected')?.dataset.path ?? ''),
                undefined,
                { timeout: 10_000 },
            );
            await shot('show-generated-code');
        },
    },
    {
        id: '6b-generate-error',
        name: 'a generation that fails: its errors in the Problems panel, no files',
        async run({ page, url, shot, workspace }) {
            await openIde(page, url);
            // An unconnected input of the arm controller is an error: generation must refuse the model.
            await select(page, '  ctrl.arm -> arm.cmd;\n');
            await page.keyboard.press('Delete');
            await page.keyboard.press(`${mod}+KeyS`);
            await page.locator('[data-testid=editor-tabs] .tab.active:not(.dirty)').waitFor({ timeout: 10_000 });
            await page.locator('[data-testid=generate-tab]').click();
            const panel = page.locator('[data-testid=generate-panel]');
            const value = await panel
                .locator('select option')
                .evaluateAll((options) => options.map((o) => o.value).find((v) => v.endsWith('\u0000rospython')));
            await panel.locator('select').selectOption(value);
            await panel.locator('[data-testid=generate-button]').click();
            await panel
                .locator('.generate-status.failed')
                .waitFor({ timeout: 120_000 })
                .catch(async () => fail(`generation did not fail: ${await panel.locator('.generate-status').textContent()}`));
            if ((await panel.locator('[data-testid=generated-files] .tree-row.file').count()) > 0)
                await fail('a failed generation lists generated files');
            await page.locator('[data-testid=problems-tab]').click();
            // The generation's own diagnostics (source "generate"), beside the language server's.
            await page
                .locator('[data-testid=problems] .problem.error[data-path$="ToastServiceRobot.arc"]', {
                    hasText: /generate\s+arc\/unconnected-sub-in-port/,
                })
                .first()
                .waitFor({ timeout: 10_000 })
                .catch(() => fail("the Problems panel does not show the generation's error"));
            await shot('failed');
            // Restore the model for the scenarios after this one.
            await page.evaluate(() => window.maaIde.editor.focus());
            await page.keyboard.press(`${mod}+KeyZ`);
            await page.keyboard.press(`${mod}+KeyS`);
            await page.waitForFunction(() => !document.querySelector('[data-testid=editor-tabs] .tab.active.dirty'), undefined, {
                timeout: 10_000,
            });
            if (!readFileSync(path.join(workspace, ROBOT), 'utf8').includes('ctrl.arm -> arm.cmd;'))
                await fail('the model was not restored on disk');
        },
    },
    {
        id: '7-simulate',
        name: 'simulate in lock-step mode: a port value changes, the viser canvas renders',
        async run({ page, url, shot }) {
            await openIde(page, url);
            await page.locator('[data-testid=simulate-tab]').click();
            const panel = page.locator('[data-testid=simulate-panel]');
            // Lock-step mode: the timesync platform.
            const platform = panel.locator('[data-testid=sim-platform]');
            await platform.locator('option[value=timesync]').waitFor({ state: 'attached', timeout: 15_000 });
            await platform.selectOption('timesync');
            const mode = (await panel.locator('[data-testid=sim-mode]').textContent()) ?? '';
            if (!/lock/i.test(mode)) await fail(`the mode for timesync is "${mode}", expected lock-step`);
            await panel.locator('[data-testid=sim-start]').click();
            const frame = page.locator('[data-testid=viser-frame]');
            await frame.waitFor({ timeout: 180_000 });
            await page.locator('[data-testid=port-inspector] [data-testid=port-value]').first().waitFor({ timeout: 90_000 });
            const values = async () =>
                (await page.locator('[data-testid=port-inspector] [data-testid=port-value]').allTextContents()).join('|');
            const first = await values();
            let changed = false;
            for (let i = 0; i < 120 && !changed; i++) {
                const step = panel.locator('[data-testid=sim-step]');
                if (i % 10 === 0 && (await step.isEnabled().catch(() => false))) {
                    await panel
                        .locator('[data-testid=sim-steps]')
                        .fill('25')
                        .catch(() => undefined);
                    await step.click().catch(() => undefined);
                }
                await page.waitForTimeout(500);
                const now = await values();
                changed = now !== first && now.replace(/[–|]/g, '').length > 0;
            }
            await shot('running');
            if (!changed) await fail(`no port value changed (values: ${first})`);
            await page.locator('[data-testid=diagram] .maa-value').first().waitFor({ timeout: 15_000 });
            // The viser canvas renders (a sized canvas inside the iframe).
            const viser = page.frameLocator('[data-testid=viser-frame]');
            await viser.locator('canvas').first().waitFor({ state: 'attached', timeout: 60_000 });
            const sizes = await viser.locator('canvas').evaluateAll((cs) => cs.map((c) => [c.width, c.height]));
            if (!sizes.some(([w, h]) => w >= 10 && h >= 10)) await fail(`no viser canvas has a size: ${JSON.stringify(sizes)}`);
            await page.waitForTimeout(2000);
            await shot('viser');
            await panel
                .locator('[data-testid=sim-stop]')
                .click()
                .catch(() => undefined);
        },
    },
    {
        // Last: it adds a model root of 200 component types to the workspace.
        id: '8-large',
        name: 'a component with 200 subcomponents: its diagram is drawn, readable, from the top',
        async run({ page, url, workspace, shot }) {
            writeLargeModel(path.join(workspace, 'large'), 200);
            await page.goto(`${url}?open=${encodeURIComponent('large/robot/System.arc')}`);
            await page.waitForFunction(() => window.maaIde?.ready === true, undefined, { timeout: 120_000 });
            await page
                .waitForFunction(
                    () => document.querySelector('[data-testid=diagram] .maa-root > title')?.textContent?.startsWith('System:'),
                    undefined,
                    { timeout: 120_000 },
                )
                .catch(() => fail('the diagram of System (200 subcomponents) was not drawn'));
            // Readable: the subcomponents in view are drawn at a zoom where their names can be read.
            const zoom = await page.evaluate(() =>
                Number(
                    /scale\(([\d.]+)\)/.exec(document.querySelector('[data-testid=diagram] svg > g')?.getAttribute('transform') ?? '')?.[1],
                ),
            );
            if (!(zoom >= 0.3)) await fail(`the diagram opened at zoom ${zoom}, unreadable`);
            const drawn = await diagram(page).locator('.maa-component:not(.maa-root)').count();
            if (drawn < 2) await fail(`only ${drawn} subcomponents are drawn in the view`);
            await shot('system');
            // Fit shows the whole diagram (every subcomponent drawn).
            await page.locator('[data-testid=diagram-fit]').click();
            await page
                .waitForFunction(
                    () => document.querySelectorAll('[data-testid=diagram] .maa-component:not(.maa-root)').length >= 200,
                    undefined,
                    { timeout: 15_000 },
                )
                .catch(async () =>
                    fail(
                        `after Fit ${await diagram(page).locator('.maa-component:not(.maa-root)').count()} of 200 subcomponents are drawn`,
                    ),
                );
        },
    },
];
