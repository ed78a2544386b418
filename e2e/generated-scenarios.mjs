// The e2e scenarios of generating in the browser IDE (issue 14, VS Code's workbench with the
// MontiArc extension's web entry, docs/ide.md): MontiArc: Generate from the command palette, the
// generated code through the trace (Show Generated Code / Show Model Element, read-only
// `maa-generated:` documents of the backend's output), and a generation that fails (its errors in
// the Problems panel). Ported from the old IDE's 6 and 6b; each gets { page, url, workspace,
// shot(name) } (run.mjs) and loads its own page.
import { readFileSync } from 'node:fs';
import path from 'node:path';
import { CONTROLLER, fail, mod, openHost, ROBOT, runCommand, select, waitForDisk, waitForText } from './host-kit.mjs';
import { repo } from './lib.mjs';

const APP = 'toast-service/TR.arcapp';
/** The line of the robot whose removal leaves an input of `arm` unconnected: an error that stops generation. */
const ARM_CONNECTOR = '  ctrl.arm -> arm.cmd;\n';

/**
 * Runs **MontiArc: Generate** from the command palette for `platform` of TR.arcapp and resolves
 * with its summary (a notification, also in the status bar); `shot` gets the platform pick.
 */
async function generate(page, platform, shot) {
    const messages = [];
    const onConsole = (m) => messages.push(m.text());
    page.on('console', onConsole);
    try {
        await runCommand(page, 'MontiArc: Generate');
        // The platform pick: the platforms of the workspace's .arcapp files (found through the host's file search).
        const row = page.locator('.quick-input-list .monaco-list-row', { hasText: APP }).filter({ hasText: platform });
        await row.first().waitFor({ timeout: 20_000 });
        await shot?.('platform-pick');
        await row.first().click();
        const started = Date.now();
        const toasts = page.locator('.notifications-toasts .notification-toast');
        const pattern = new RegExp(`MontiArc: (generated \\d+ files|nothing generated) for ${platform}`);
        for (;;) {
            const summary = [...(await toasts.allInnerTexts()), ...messages].find((m) => pattern.test(m));
            if (summary) return summary;
            if (Date.now() - started > 180_000) await fail(`no summary of the generation; console: ${messages.slice(-5).join(' | ')}`);
            await page.waitForTimeout(200);
        }
    } finally {
        page.off('console', onConsole);
    }
}

/** Closes the notification toasts (a later summary is then the only one). */
async function clearNotifications(page) {
    await runCommand(page, 'Notifications: Clear All Notifications').catch(() => undefined);
    await page.keyboard.press('Escape');
}

/** The active editor: its document URI, text and selection (1-based lines). */
const activeEditor = (page) =>
    page.evaluate(() => {
        const editor = window.maaHost.activeEditor();
        const model = editor?.getModel();
        const s = editor?.getSelection();
        return model && s
            ? {
                  uri: model.uri.toString(),
                  text: model.getValue(),
                  selection: { start: s.startLineNumber, end: s.endLineNumber },
                  readOnly: editor.getRawOptions().readOnly === true,
              }
            : undefined;
    });

/** Waits until the active editor satisfies `predicate`; resolves with it. */
async function waitForActive(page, predicate, what, timeout = 30_000) {
    const started = Date.now();
    for (;;) {
        const editor = await activeEditor(page);
        if (editor && predicate(editor)) return editor;
        if (Date.now() - started > timeout) await fail(`${what} (active editor: ${editor?.uri ?? 'none'})`);
        await page.waitForTimeout(200);
    }
}

/** Problems panel rows that match `text`. */
const problemRows = (page, text) => page.locator('.markers-panel .monaco-list-row', { hasText: text });

/** Shows the Problems panel (Ctrl+Shift+M toggles it: only when it is not shown). */
async function showProblems(page) {
    if (!(await page.locator('.markers-panel').isVisible())) await page.keyboard.press(`${mod}+Shift+KeyM`);
    await page.locator('.markers-panel').waitFor({ state: 'visible', timeout: 10_000 });
}

export const generatedScenarios = [
    {
        id: 'h3-host-generate',
        name: 'workbench host: "MontiArc: Generate" from the command palette generates timesync through the backend',
        async run({ page, url, shot }) {
            await openHost(page, url);
            const summary = await generate(page, 'timesync', shot);
            if (!/MontiArc: generated \d+ files for timesync \(0 errors/.test(summary)) await fail(`Generate reported: ${summary}`);
            // The summary in the status bar (what the user sees here).
            await page
                .locator('.statusbar-item', { hasText: /MontiArc: generated \d+ files for timesync/ })
                .first()
                .waitFor({ timeout: 10_000 });
            // The backend has the generated platform (its trace file).
            const status = await page.evaluate(() =>
                fetch('api/generated/trace?app=toast-service%2FTR.arcapp&platform=timesync').then((r) => r.status),
            );
            if (status !== 200) await fail(`the generated trace of timesync answered ${status}`);
            await shot('generated');
        },
    },
    {
        id: '6-generate',
        name: 'generate for rospython and open a generated node (Show Generated Code), and back to the model (Show Model Element)',
        async run({ page, url, shot }) {
            await openHost(page, url, CONTROLLER);
            await page.waitForFunction((p) => window.maaHost.checked(p), CONTROLLER, { timeout: 60_000 });
            const summary = await generate(page, 'rospython');
            if (!/MontiArc: generated \d+ files for rospython \(0 errors/.test(summary)) await fail(`Generate reported: ${summary}`);
            await shot('generated');
            // The cursor in Controller's automaton (rospython traces the automaton to its behavior node).
            await select(page, CONTROLLER, 'state Toasting', { offset: 6, length: 0 });
            await runCommand(page, 'MontiArc: Show Generated Code');
            const generated = await waitForActive(
                page,
                (e) => e.uri.startsWith('maa-generated:/rospython/') && e.uri.includes('controller_behavior.py'),
                'Show Generated Code did not open the generated behavior of Controller',
            );
            if (!/class Controller/.test(generated.text))
                await fail(`the generated node has no class Controller:\n${generated.text.slice(0, 400)}`);
            if (!generated.readOnly) await fail('the generated file opened writable');
            if (generated.selection.end <= generated.selection.start) await fail('the traced lines are not selected');
            await page.locator('.tabs-container .tab.active', { hasText: 'controller_behavior.py' }).waitFor({ timeout: 10_000 });
            await shot('show-generated-code');
            // Back: a line of the generated behavior (the cursor at the selection's start) leads to the automaton.
            await page.evaluate(() => {
                const editor = window.maaHost.activeEditor();
                const s = editor.getSelection();
                editor.setPosition({ lineNumber: s.startLineNumber + 2, column: 1 });
                editor.focus();
            });
            await runCommand(page, 'MontiArc: Show Model Element');
            const model = await waitForActive(
                page,
                (e) => e.uri.endsWith(CONTROLLER),
                'Show Model Element did not go back to Controller.arc',
            );
            const automatonLine = model.text.split('\n').findIndex((l) => l.includes('automaton {')) + 1;
            if (model.selection.start !== automatonLine)
                await fail(`Show Model Element selected line ${model.selection.start}, not the automaton's ${automatonLine}`);
            await shot('show-model-element');
        },
    },
    {
        id: '6b-generate-error',
        name: 'a generation that fails: its errors in the Problems panel, nothing generated; fixed, the error goes',
        async run({ page, url, workspace, shot }) {
            await openHost(page, url);
            await page.waitForFunction((p) => window.maaHost.checked(p), ROBOT, { timeout: 60_000 });
            // An unconnected input of the arm is an error: generation must refuse the model.
            await select(page, ROBOT, ARM_CONNECTOR);
            await page.keyboard.press('Delete');
            await page.keyboard.press(`${mod}+KeyS`);
            const file = path.join(workspace, ROBOT);
            await waitForDisk(page, file, (t) => !t.includes(ARM_CONNECTOR), 'the broken model was not saved');
            await clearNotifications(page);
            const summary = await generate(page, 'rospython');
            if (!/MontiArc: nothing generated for rospython \(\d+ errors?/.test(summary)) await fail(`Generate reported: ${summary}`);
            // The generation's own error (source maa-gen) in the Problems panel, beside the language server's.
            await showProblems(page);
            const row = problemRows(page, 'maa-gen')
                .filter({ hasText: /unconnected/i })
                .first();
            await row.waitFor({ timeout: 20_000 }).catch(() => fail("the Problems panel does not show the generation's error"));
            await shot('failed');
            // Restore the model (undo, save) and generate again: the generation's error goes.
            await select(page, ROBOT, 'ToastServiceRobot', { length: 0 });
            await page.keyboard.press(`${mod}+KeyZ`);
            await waitForText(page, ROBOT, (t) => t.includes(ARM_CONNECTOR), 'undo did not bring the connector back');
            await page.keyboard.press(`${mod}+KeyS`);
            const original = readFileSync(path.join(repo, 'examples', ROBOT), 'utf8');
            await waitForDisk(page, file, (t) => t === original, 'the model was not restored on disk');
            await clearNotifications(page);
            const again = await generate(page, 'rospython');
            if (!/MontiArc: generated \d+ files for rospython \(0 errors/.test(again))
                await fail(`Generate after the fix reported: ${again}`);
            await showProblems(page);
            await problemRows(page, 'maa-gen')
                .first()
                .waitFor({ state: 'detached', timeout: 20_000 })
                .catch(() => fail("the generation's error stays in the Problems panel after the fix"));
            await shot('fixed');
        },
    },
];
