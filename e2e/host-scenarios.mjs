// The e2e scenarios of the browser IDE (issue 14): VS Code's workbench from
// @codingame/monaco-vscode-api with the MontiArc extension's web entry loaded into it (docs/ide.md).
// The scenarios of the old hand-written IDE (issue 7: 1-5c, 8) ported to the workbench's own UI
// (explorer, tabs, the Problems panel, the quick fix menu, the suggest widget, the rename box, the
// extension's diagram webview, its Export Diagram as SVG, the test explorer), then the host's own.
// Each gets { page, url, workspace, shot(name) } (run.mjs); each loads its own page, except
// 3-quickfix, which continues 2-error.
import { copyFileSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import path from 'node:path';
import {
    ARM,
    CONTROLLER,
    cursorLine,
    diagramFrame,
    editorOf,
    exportDiagram,
    fail,
    mod,
    openDiagram,
    openHost,
    ROBOT,
    runCommand,
    select,
    waitForDisk,
    waitForText,
} from './host-kit.mjs';
import { artifacts, repo, writeLargeModel } from './lib.mjs';
import { cliDiagram, diagramClasses, diagramIds, diagramRoutes, diagramTexts, idDifference, sameRoute } from './svg-compare.mjs';

/**
 * Puts the example's `files` back on disk once the workbench has saved every edit (File: Save
 * All; the web workbench saves by itself too, files.autoSave "afterDelay"), so that no later save
 * overwrites them: the next scenario's page reads the originals.
 */
async function restoreFiles(page, workspace, files) {
    await runCommand(page, 'File: Save All');
    await page.waitForFunction(() => !document.querySelector('.tabs-container .tab.dirty'), undefined, { timeout: 30_000 });
    for (const file of files) {
        // The disk has what the editor has (a file without an editor was saved by its refactoring).
        const edited = await page.evaluate((p) => (window.maaHost.editorOf(p) ? window.maaHost.text(p) : undefined), file);
        if (edited !== undefined) {
            const disk = path.join(workspace, file);
            await waitForDisk(page, disk, (t) => t === edited, `${file} was not saved`).catch(() =>
                fail(`${file} was not saved: the editor has\n${edited}\nthe disk\n${readFileSync(disk, 'utf8')}`),
            );
        }
        copyFileSync(path.join(repo, 'examples', file), path.join(workspace, file));
    }
}

/** The bounding box of `locator` once two polls in a row agree (the update's animation is over). */
async function settledBox(page, locator, timeout = 10_000) {
    const started = Date.now();
    let last = await locator.boundingBox();
    for (;;) {
        await page.waitForTimeout(150);
        const now = await locator.boundingBox();
        if (last && now && Math.abs(now.x - last.x) < 0.5 && Math.abs(now.y - last.y) < 0.5) return now;
        if (Date.now() - started > timeout) return now;
        last = now;
    }
}

/** Exports the shown diagram (the extension's command) and compares its element ids, labels, classes and routes with `maa-gen diagram ARGS`'s SVG. */
async function compareExport(page, workspace, model, args, what) {
    const name = args[0].split('.').pop() + (args.includes('--automaton') ? '-automaton' : '');
    const file = await exportDiagram(page, `5c-export-${name}.svg`, model);
    const ide = readFileSync(path.join(workspace, file), 'utf8');
    rmSync(path.join(workspace, file));
    const cli = await cliDiagram(args);
    const ideIds = diagramIds(ide);
    const cliIds = diagramIds(cli);
    if (ideIds.length < 10) await fail(`${what}: the export has only ${ideIds.length} elements with ids`);
    const { onlyFirst, onlySecond } = idDifference(ideIds, cliIds);
    if (onlyFirst.length || onlySecond.length || ideIds.length !== cliIds.length) {
        await fail(
            `${what}: the export and maa-gen diagram differ (${ideIds.length} vs ${cliIds.length} ids)\n` +
                `  only in the export: ${onlyFirst.join(', ')}\n  only in maa-gen's: ${onlySecond.join(', ')}`,
        );
    }
    // Both documents beside the screenshots, for a look at what differs.
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

export const hostScenarios = [
    {
        id: '1-open',
        name: "open the example: editor and diagram visible (the diagram from the editor's title button)",
        async run({ page, url, shot }) {
            await openHost(page, url);
            await page.locator('.tabs-container .tab.active', { hasText: 'ToastServiceRobot.arc' }).waitFor({ timeout: 10_000 });
            await editorOf(page, 'component ToastServiceRobot').first().waitFor({ state: 'visible', timeout: 10_000 });
            await page
                .locator('.explorer-folders-view .monaco-list-row', { hasText: 'toast-service' })
                .first()
                .waitFor({ timeout: 10_000 });
            const diagram = await openDiagram(page);
            // The IDE opened the diagram at start too: the model may still be rendering when the
            // first component shows, so wait for the whole robot rather than count once.
            const complete = await diagram
                .waitForFunction(() => document.querySelectorAll('.maa-component').length >= 8, undefined, { timeout: 30_000 })
                .then(() => true)
                .catch(() => false);
            const components = await diagram.locator('.maa-component').count();
            if (!complete) await fail(`the diagram shows ${components} components, expected the robot and its 7 subcomponents`);
            await diagram.locator('.maa-port').first().waitFor();
            await diagram.locator('.maa-connector').first().waitFor();
            await shot('diagram');
            // The diagram follows the active editor; the Controller has an automaton: the toggle shows its state machine and back.
            await page.evaluate((p) => window.maaHost.open(p), CONTROLLER);
            await diagram
                .locator('.maa-diagram-title', { hasText: /^Controller$/ })
                .first()
                .waitFor({ timeout: 20_000 });
            const toggle = diagram.locator('[data-testid=diagram-switch]');
            await toggle.waitFor({ state: 'visible', timeout: 20_000 });
            await toggle.click();
            await diagram.locator('.maa-state', { hasText: 'Toasting' }).first().waitFor({ timeout: 20_000 });
            await shot('automaton');
            await toggle.click();
            await diagram.locator('.maa-state').first().waitFor({ state: 'detached', timeout: 20_000 });
        },
    },
    {
        id: '2-error',
        name: 'introduce an error: the Problems panel and the diagram show it',
        async run({ page, url, shot }) {
            await openHost(page, url);
            await page.waitForFunction((p) => window.maaHost.checked(p), ROBOT, { timeout: 60_000 });
            const diagram = await openDiagram(page);
            // Remove the connector that feeds the arm controller: its input `cmd` is left unconnected (an error).
            await select(page, ROBOT, '  ctrl.arm -> arm.cmd;\n');
            await page.keyboard.press('Delete');
            await waitForText(page, ROBOT, (t) => !t.includes('ctrl.arm -> arm.cmd;'), 'the connector was not deleted');
            await page.keyboard.press(`${mod}+Shift+KeyM`);
            const problem = page.locator('.markers-panel .monaco-list-row', { hasText: 'cmd' }).first();
            await problem.waitFor({ timeout: 30_000 });
            await diagram
                .locator('.maa-component.maa-error[data-instance-path=arm]')
                .first()
                .waitFor({ timeout: 30_000 })
                .catch(() => fail('the diagram does not mark the subcomponent "arm"'));
            await shot('problems-and-diagram');
            // Clicking the problem jumps to it (the instance "arm", line 18).
            await problem.click();
            await page
                .waitForFunction((p) => window.maaHost.editorOf(p)?.getPosition()?.lineNumber === 18, ROBOT, { timeout: 10_000 })
                .catch(async () =>
                    fail(`the problem's click went to line ${await cursorLine(page, ROBOT)}, expected 18 (the instance "arm")`),
                );
        },
    },
    {
        id: '3-quickfix',
        name: 'fix the error with a quick fix (Ctrl+.)',
        async run({ page, shot, workspace }) {
            // Continues the previous scenario: the connector is missing, the diagram open.
            const diagram = await diagramFrame(page);
            if (!(await page.evaluate((p) => window.maaHost.markers(p).some((m) => m.severity === 8 && /cmd/.test(m.message)), ROBOT)))
                await fail('no error about the unconnected port "cmd" to fix (2-error runs first)');
            await select(page, ROBOT, 'ArmController arm;', { offset: 15, length: 0 });
            await page.keyboard.press(`${mod}+Period`);
            const menu = page.locator('.action-widget');
            await menu.locator('.monaco-list-row', { hasText: 'arm.cmd' }).first().waitFor({ timeout: 20_000 });
            await shot('quick-fix-menu');
            // Move the focus to the fix and apply it with Enter.
            for (let i = 0; i < 12; i++) {
                const focused = await menu
                    .locator('.monaco-list-row.focused')
                    .first()
                    .textContent()
                    .catch(() => '');
                if (focused.includes('arm.cmd')) break;
                await page.keyboard.press('ArrowDown');
            }
            await page.keyboard.press('Enter');
            await waitForText(page, ROBOT, (t) => t.includes('ctrl.arm -> arm.cmd;'), 'the quick fix did not connect the port');
            await page.waitForFunction((p) => !window.maaHost.markers(p).some((m) => m.severity === 8), ROBOT, { timeout: 30_000 });
            await page
                .locator('.markers-panel .monaco-list-row', { hasText: 'cmd' })
                .first()
                .waitFor({ state: 'detached', timeout: 30_000 });
            await diagram.locator('.maa-error').first().waitFor({ state: 'detached', timeout: 30_000 });
            // Ctrl+S saves the file (PUT /api/file; the web workbench also saves by itself after a second,
            // files.autoSave "afterDelay"): the dirty marker goes, the disk has the fix.
            await page.keyboard.press(`${mod}+KeyS`);
            await page
                .locator('.tabs-container .tab.active:not(.dirty)', { hasText: 'ToastServiceRobot.arc' })
                .waitFor({ timeout: 20_000 });
            await waitForDisk(page, path.join(workspace, ROBOT), (t) => t.includes('ctrl.arm -> arm.cmd;'), 'the saved file lacks the fix');
            // The example as it was (the fix may put the connector elsewhere) for the scenarios after this one.
            await restoreFiles(page, workspace, [ROBOT]);
        },
    },
    {
        id: '4-completion',
        name: 'completion inside a RobotArm block (ArmController.arc)',
        async run({ page, url, workspace, shot }) {
            await openHost(page, url);
            // Ctrl+P: quick open.
            await page.keyboard.press(`${mod}+KeyP`);
            const input = page.locator('.quick-input-widget .quick-input-box input');
            await input.waitFor({ timeout: 10_000 });
            await input.fill('ArmContr');
            await page.locator('.quick-input-list .monaco-list-row', { hasText: 'ArmController.arc' }).first().waitFor({ timeout: 20_000 });
            await page.keyboard.press('Enter');
            await page.locator('.tabs-container .tab.active', { hasText: 'ArmController.arc' }).waitFor({ timeout: 10_000 });
            await page.waitForFunction((p) => window.maaHost.checked(p), ARM, { timeout: 60_000 });
            // After the last statement of LoadBread.
            await select(page, ARM, 'move toaster; open; move top;', { offset: 'move toaster; open; move top;'.length, length: 0 });
            await page.keyboard.type(' move ab');
            // The server has the new text once it reports the unfinished `ab`; only then ask for completion,
            // so that the request is not raced by the editor's own quick suggestions on the keystrokes.
            await page
                .waitForFunction((p) => window.maaHost.markers(p).some((m) => m.message.includes("'ab'")), ARM, { timeout: 30_000 })
                .catch(() => fail("the server did not report the unfinished 'ab'"));
            await page.keyboard.press('Escape');
            const suggest = page.locator('.suggest-widget.visible');
            const item = suggest.locator('.monaco-list-row', { hasText: 'aboveBreadbox' }).first();
            await page.keyboard.press(`${mod}+Space`);
            await item.waitFor({ timeout: 30_000 });
            await shot('completion');
            await item.click();
            await page.keyboard.type(';');
            await waitForText(page, ARM, (t) => t.includes('move top; move aboveBreadbox;'), 'the completion was not inserted');
            await page
                .waitForFunction((p) => !window.maaHost.markers(p).some((m) => m.severity === 8 && !m.message.includes('package')), ARM, {
                    timeout: 30_000,
                })
                .catch(async () =>
                    fail(`errors after the completion: ${JSON.stringify(await page.evaluate((p) => window.maaHost.markers(p), ARM))}`),
                );
            await restoreFiles(page, workspace, [ARM]);
        },
    },
    {
        id: '5-rename',
        name: 'rename a port (F2): references and the diagram follow',
        async run({ page, url, workspace, shot }) {
            await openHost(page, url);
            await page.waitForFunction((p) => window.maaHost.checked(p), ROBOT, { timeout: 60_000 });
            const diagram = await openDiagram(page);
            if ((await diagram.locator('[data-testid=diagram]').textContent()).includes('progress'))
                await fail('the diagram shows "progress" before the rename');
            await select(page, ROBOT, 'arm.status', { offset: 5, length: 0 });
            await page.keyboard.press('F2');
            // The rename box takes the focus once the server answered prepareRename.
            await page.waitForFunction(() => document.activeElement?.classList.contains('rename-input'), undefined, { timeout: 20_000 });
            await page.locator('.rename-input').fill('progress');
            await page.keyboard.press('Enter');
            await waitForText(page, ROBOT, (t) => t.includes('arm.progress -> ctrl.armStatus'), 'the connector was not renamed');
            // The port's declaration in the other file, which has no editor: the rename saves it
            // (VS Code's refactoring auto-save), and the workbench keeps no model of it open.
            await waitForDisk(
                page,
                path.join(workspace, ARM),
                (t) => /out\s+ArmStatus\s+progress/.test(t),
                'the rename did not rename and save the port declaration in ArmController.arc, which has no editor',
            );
            await diagram
                .locator('.maa-port[data-port-path="arm.progress"]')
                .first()
                .waitFor({ state: 'attached', timeout: 30_000 })
                .catch(() => fail('the diagram does not show the renamed port "progress"'));
            await shot('renamed');
            await restoreFiles(page, workspace, [ROBOT, ARM]);
        },
    },
    {
        id: '5b-diagram',
        name: 'diagram: selection synced both ways, port types on hover, stable layout on edits, SVG export',
        async run({ page, url, workspace, shot }) {
            await openHost(page, url);
            await page.waitForFunction((p) => window.maaHost.checked(p), ROBOT, { timeout: 60_000 });
            const diagram = await openDiagram(page);
            const arm = diagram.locator('.maa-component[data-instance-path=arm]').first();
            await arm.waitFor({ timeout: 30_000 });
            // Text → diagram: the cursor on the instance declaration selects its node.
            await select(page, ROBOT, 'ArmController arm;', { offset: 15, length: 0 });
            await diagram
                .locator('.maa-component.selected[data-instance-path=arm]')
                .waitFor({ timeout: 20_000 })
                .catch(() => fail('the cursor on "ArmController arm;" did not select the node "arm"'));
            // Diagram → text: clicking the node "ctrl" moves the cursor to its declaration (line 15).
            await diagram.locator('.maa-component[data-instance-path=ctrl] .maa-label-type').first().click();
            await page
                .waitForFunction((p) => window.maaHost.editorOf(p)?.getPosition()?.lineNumber === 15, ROBOT, { timeout: 20_000 })
                .catch(async () => fail(`clicking the node "ctrl" moved the cursor to line ${await cursorLine(page, ROBOT)}, expected 15`));
            // Port types on hover (the SVG title of the port).
            const portTitle = await diagram.locator('.maa-port[data-port-path="arm.status"] title').first().textContent();
            if (!/ArmStatus/.test(portTitle ?? ''))
                await fail(`the hover text of arm.status is "${portTitle}", expected its type ArmStatus`);
            // An edit elsewhere in the file updates the diagram (a model update arrives in the webview) without moving the nodes.
            await diagram.evaluate(() => {
                window.maaUpdates = 0;
                window.addEventListener('message', (e) => {
                    if (e.data?.type === 'action' && e.data.message?.action?.kind === 'updateModel') window.maaUpdates++;
                });
            });
            // The cursor first (on "arm": it selects and reveals the node), then where the node rests, then the edit at the line's end.
            await select(page, ROBOT, 'ArmController arm;', { offset: 15, length: 0 });
            await diagram.locator('.maa-component.selected[data-instance-path=arm]').waitFor({ timeout: 20_000 });
            await page.keyboard.press('End');
            const before = await settledBox(page, arm);
            await page.keyboard.type(' // the arm');
            await diagram
                .waitForFunction(() => window.maaUpdates > 0, undefined, { timeout: 30_000 })
                .catch(() => fail('the diagram did not update after the edit'));
            const after = await settledBox(page, arm);
            if (!before || !after || Math.abs(before.x - after.x) > 3 || Math.abs(before.y - after.y) > 3) {
                await fail(`the node "arm" moved on an unrelated edit: ${JSON.stringify(before)} → ${JSON.stringify(after)}`);
            }
            await restoreFiles(page, workspace, [ROBOT]);
            // MontiArc: Export Diagram as SVG writes a standalone SVG of the shown diagram where the save dialog says.
            const file = await exportDiagram(page, '5b-ToastServiceRobot.svg', ROBOT);
            const svgText = readFileSync(path.join(workspace, file), 'utf8');
            rmSync(path.join(workspace, file));
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
        name: 'diagram export: the exported SVG and maa-gen diagram hold the same elements, classes, labels and edge routes',
        async run({ page, url, workspace, shot }) {
            await openHost(page, url);
            const diagram = await openDiagram(page);
            await diagram.locator('.maa-component[data-instance-path=arm]').first().waitFor({ timeout: 30_000 });
            const root = path.join(workspace, 'toast-service');
            // The C&C view of the example's robot, then the state machine of its Controller.
            await compareExport(page, workspace, ROBOT, ['toast.ToastServiceRobot', '--root', root], 'C&C view of toast.ToastServiceRobot');
            await page.evaluate((p) => window.maaHost.open(p), CONTROLLER);
            const toggle = diagram.locator('[data-testid=diagram-switch]');
            await toggle.waitFor({ state: 'visible', timeout: 20_000 });
            await toggle.click();
            await diagram.locator('.maa-state', { hasText: 'Toasting' }).first().waitFor({ timeout: 20_000 });
            await compareExport(
                page,
                workspace,
                CONTROLLER,
                ['toast.Controller', '--automaton', '--root', root],
                'state machine of toast.Controller',
            );
            await shot('automaton');
        },
    },
    {
        id: '9-tests',
        name: 'the test explorer: a .stream case passes; an edited expectation fails with expected vs produced at its line',
        async run({ page, url, workspace, shot }) {
            const STREAM = 'toast-service/toast/ArmController.stream';
            const CASE = 'IDLE initially, nothing without a command';
            await openHost(page, url, STREAM);
            await page.locator('.activitybar .action-item a[aria-label^="Testing"]').first().click();
            const explorer = page.locator('.test-explorer');
            const fileRow = explorer.locator('.monaco-list-row', { hasText: 'ArmController.stream' }).first();
            await fileRow.waitFor({ timeout: 60_000 });
            const caseRow = explorer.locator('.monaco-list-row', { hasText: CASE }).first();
            // Expand the file's row (its cases).
            if (!(await caseRow.count())) await fileRow.locator('.monaco-tl-twistie').click();
            await caseRow.waitFor({ timeout: 20_000 });
            const runCase = async () => {
                await caseRow.hover();
                await caseRow.locator('.action-label[aria-label="Run Test"]').click();
            };
            await runCase();
            await caseRow
                .locator('.codicon-testing-passed-icon')
                .waitFor({ timeout: 240_000 })
                .catch(async () => fail(`the case did not pass: ${await caseRow.textContent()}`));
            await shot('passed');
            // Make it fail: the expected status at the start becomes BUSY (an edit through the editor, saved).
            await select(page, STREAM, 'status  == IDLE Tk Tk;', { offset: 'status  == '.length, length: 'IDLE'.length });
            await page.keyboard.type('BUSY');
            await page.keyboard.press('Escape');
            await page.keyboard.press(`${mod}+KeyS`);
            await page.locator('.tabs-container .tab.active:not(.dirty)', { hasText: 'ArmController.stream' }).waitFor({ timeout: 20_000 });
            await waitForDisk(page, path.join(workspace, STREAM), (t) => t.includes('status  == BUSY Tk Tk;'), 'the edit was not saved');
            await runCase();
            await caseRow
                .locator('.codicon-testing-failed-icon')
                .waitFor({ timeout: 240_000 })
                .catch(async () => fail(`the case did not fail: ${await caseRow.textContent()}`));
            // The failure in the Test Results view: its message, and on a click expected vs produced side by side.
            const message = page.locator(
                '.test-output-peek-tree .monaco-list-row[aria-label="status: expected BUSY Tk Tk; got IDLE Tk Tk"]',
            );
            await message
                .first()
                .waitFor({ timeout: 30_000 })
                .catch(() => fail('the Test Results view has no message "status: expected BUSY Tk Tk; got IDLE Tk Tk"'));
            await message.first().click();
            const diff = page.locator('.monaco-diff-editor', { hasText: 'Expected' }).filter({ hasText: 'Actual' });
            await diff.filter({ hasText: 'BUSY Tk Tk' }).filter({ hasText: 'IDLE Tk Tk' }).first().waitFor({ timeout: 20_000 });
            // A double click on the failed case in the test explorer goes to the failure: the expectation's line.
            const statusLine = readFileSync(path.join(workspace, STREAM), 'utf8').split('\n').indexOf('  status  == BUSY Tk Tk;') + 1;
            await select(page, STREAM, 'component toast.ArmController;', { length: 0 });
            await caseRow.dblclick();
            await page
                .waitForFunction(([p, l]) => window.maaHost.editorOf(p)?.getPosition()?.lineNumber === l, [STREAM, statusLine], {
                    timeout: 20_000,
                })
                .catch(async () =>
                    fail(`the failed case did not lead to line ${statusLine} (the cursor is at ${await cursorLine(page, STREAM)})`),
                );
            await shot('failed');
            // Restore the file.
            await page.keyboard.press('Escape');
            await select(page, STREAM, 'status  == BUSY Tk Tk;', { offset: 'status  == '.length, length: 'BUSY'.length });
            await page.keyboard.type('IDLE');
            await page.keyboard.press('Escape');
            await page.keyboard.press(`${mod}+KeyS`);
            await page.locator('.tabs-container .tab.active:not(.dirty)', { hasText: 'ArmController.stream' }).waitFor({ timeout: 20_000 });
            const original = readFileSync(path.join(repo, 'examples', STREAM), 'utf8');
            await waitForDisk(page, path.join(workspace, STREAM), (t) => t === original, 'the .stream file was not restored');
        },
    },
    {
        id: 'h1-host-open',
        name: "workbench host: the example in VS Code's workbench (explorer, editor, the extension active, quick open)",
        async run({ page, url, shot }) {
            await openHost(page, url);
            await page
                .locator('.explorer-folders-view .monaco-list-row', { hasText: 'toast-service' })
                .first()
                .waitFor({ timeout: 10_000 });
            await page.locator('.tabs-container .tab.active', { hasText: 'ToastServiceRobot.arc' }).waitFor({ timeout: 10_000 });
            await editorOf(page, 'component ToastServiceRobot').first().waitFor({ timeout: 10_000 });
            // The language of the editor is the extension's (status bar), the grammar its TextMate grammar.
            await page.locator('.statusbar-item', { hasText: 'MontiArc' }).first().waitFor({ timeout: 10_000 });
            const active = await page.evaluate(() => window.maaHost.extensionActive());
            if (!active) await fail('the MontiArc extension is not active');
            await shot('workbench');
            // Quick open (Ctrl+P) finds workspace files through the host's file search provider.
            const mod = process.platform === 'darwin' ? 'Meta' : 'Control';
            await page.keyboard.press(`${mod}+KeyP`);
            const input = page.locator('.quick-input-widget .quick-input-box input');
            await input.waitFor({ timeout: 10_000 });
            await input.fill('toastercontroller.arc');
            const row = page.locator('.quick-input-list .monaco-list-row', { hasText: 'ToasterController.arc' }).first();
            await row.waitFor({ timeout: 20_000 });
            await shot('quick-open');
            await row.click();
            await page.locator('.tabs-container .tab.active', { hasText: 'ToasterController.arc' }).waitFor({ timeout: 10_000 });
        },
    },
    {
        id: 'h2-host-diagnostic',
        name: "workbench host: an edit gives a diagnostic from the extension's language server, undo clears it",
        async run({ page, url, workspace, shot }) {
            await openHost(page, url);
            const errors = () => page.evaluate((p) => window.maaHost.markers(p).filter((m) => m.severity === 8), ROBOT);
            // The example is clean before the edit (the server has checked it: wait for its first answer).
            await page.waitForFunction((p) => window.maaHost.checked(p), ROBOT, { timeout: 60_000 });
            if ((await errors()).length) await fail(`the example has errors before the edit: ${JSON.stringify(await errors())}`);
            await editorOf(page, 'component ToastServiceRobot').first().locator('.view-line', { hasText: 'ArmController arm;' }).click();
            await page.keyboard.press('End');
            await page.keyboard.type('\n  NoSuchType broken;');
            await page.waitForFunction(
                (p) => window.maaHost.markers(p).some((m) => m.severity === 8 && /NoSuchType/.test(m.message)),
                ROBOT,
                {
                    timeout: 30_000,
                },
            );
            await page.locator('.monaco-editor .squiggly-error').first().waitFor({ timeout: 10_000 });
            await shot('diagnostic');
            // Undo the edit: the error goes away. The web workbench saves edits by itself (files.autoSave
            // "afterDelay"): the file goes back to the example's on disk for the scenarios after this one.
            await page.keyboard.press(`${mod}+KeyZ`);
            await page.keyboard.press(`${mod}+KeyZ`);
            await page.waitForFunction((p) => !window.maaHost.markers(p).some((m) => m.severity === 8), ROBOT, { timeout: 30_000 });
            await restoreFiles(page, workspace, [ROBOT]);
        },
    },
];

/** Last: it adds a model root of 200 component types to the workspace. */
export const largeModelScenarios = [
    {
        id: '8-large',
        name: 'a component with 200 subcomponents: its diagram is drawn, readable, from the top',
        async run({ page, url, workspace, shot }) {
            writeLargeModel(path.join(workspace, 'large'), 200);
            await openHost(page, url, 'large/robot/System.arc');
            await page.waitForFunction((p) => window.maaHost.checked(p), 'large/robot/System.arc', { timeout: 180_000 });
            const diagram = await openDiagram(page, 180_000);
            await diagram
                .waitForFunction(
                    () => document.querySelector('[data-testid=diagram] .maa-root > title')?.textContent?.startsWith('System:'),
                    undefined,
                    {
                        timeout: 180_000,
                    },
                )
                .catch(() => fail('the diagram of System (200 subcomponents) was not drawn'));
            // Readable: the subcomponents in view are drawn at a zoom where their names can be read.
            const zoom = await diagram.evaluate(() =>
                Number(
                    /scale\(([\d.]+)\)/.exec(document.querySelector('[data-testid=diagram] svg > g')?.getAttribute('transform') ?? '')?.[1],
                ),
            );
            if (!(zoom >= 0.3)) await fail(`the diagram opened at zoom ${zoom}, unreadable`);
            const drawn = await diagram.locator('.maa-component:not(.maa-root)').count();
            if (drawn < 2) await fail(`only ${drawn} subcomponents are drawn in the view`);
            await shot('system');
            // Fit shows the whole diagram (every subcomponent drawn). A model update still arriving (the server's
            // checks of the 200 types) may bring the remembered view back: Fit again then.
            const fitted = () =>
                diagram.waitForFunction(
                    () => document.querySelectorAll('[data-testid=diagram] .maa-component:not(.maa-root)').length >= 200,
                    undefined,
                    { timeout: 10_000 },
                );
            for (let attempt = 1; ; attempt++) {
                await diagram.locator('[data-testid=diagram-fit]').click();
                if (
                    await fitted().then(
                        () => true,
                        () => false,
                    )
                )
                    break;
                if (attempt === 5) break;
            }
            await diagram
                .waitForFunction(
                    () => document.querySelectorAll('[data-testid=diagram] .maa-component:not(.maa-root)').length >= 200,
                    undefined,
                    {
                        timeout: 30_000,
                    },
                )
                .catch(async () =>
                    fail(`after Fit ${await diagram.locator('.maa-component:not(.maa-root)').count()} of 200 subcomponents are drawn`),
                );
        },
    },
];
