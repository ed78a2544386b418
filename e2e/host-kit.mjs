// Shared steps of the e2e scenarios on the browser IDE (VS Code's workbench from
// @codingame/monaco-vscode-api with the MontiArc extension's web entry, docs/ide.md).
import { readFileSync } from 'node:fs';

export const ROBOT = 'toast-service/toast/ToastServiceRobot.arc';

export async function fail(message) {
    throw new Error(message);
}

/** Waits until the loaded IDE page reports the extension active (`maaHost.ready`); fails with why it did not start. */
export async function waitForIde(page, timeout = 90_000) {
    await page.waitForFunction(() => window.maaHost?.ready === true || document.body.dataset.failed, undefined, { timeout });
    const failed = await page.evaluate(() => document.body.dataset.failed);
    if (failed) await fail(`the workbench host did not start: ${failed}`);
}

/** Loads the IDE with `open` as the first editor and waits until the extension is active. */
export async function openHost(page, url, open = ROBOT) {
    await page.goto(`${url}?open=${encodeURIComponent(open)}`);
    await waitForIde(page);
}

/** The first frame below the page that holds `selector` (webviews are nested iframes of the workbench). */
export async function frameWith(page, selector, what, timeout = 60_000) {
    const started = Date.now();
    for (;;) {
        for (const frame of page.frames()) {
            if (frame === page.mainFrame()) continue;
            const n = await frame
                .locator(selector)
                .count()
                .catch(() => 0);
            if (n > 0) return frame;
        }
        if (Date.now() - started > timeout) await fail(`no webview shows ${what}`);
        await page.waitForTimeout(250);
    }
}

/** Waits until the file on disk satisfies `predicate` (a save's PUT may still be under way; polled). */
export async function waitForDisk(page, file, predicate, what, timeout = 20_000) {
    const started = Date.now();
    while (!predicate(readFileSync(file, 'utf8'))) {
        if (Date.now() - started > timeout) await fail(what);
        await page.waitForTimeout(200);
    }
}

export const editorOf = (page, name) =>
    page.locator('.editor-instance .monaco-editor', { has: page.locator('.view-lines') }).filter({ hasText: name });

/** Runs a command by its title from the command palette (F1). */
export async function runCommand(page, title) {
    await page.keyboard.press('F1');
    const input = page.locator('.quick-input-widget .quick-input-box input');
    await input.waitFor({ timeout: 10_000 });
    await input.fill(`>${title}`);
    await page.locator('.quick-input-list .monaco-list-row', { hasText: title }).first().waitFor({ timeout: 10_000 });
    await page.keyboard.press('Enter');
}

export const ARM = 'toast-service/toast/ArmController.arc';
export const CONTROLLER = 'toast-service/toast/Controller.arc';
export const mod = process.platform === 'darwin' ? 'Meta' : 'Control';

/**
 * Selects `needle` (or `length` characters from `offset` into it) in the editor showing `path`
 * and focuses that editor (window.maaHost.editorOf: also while the diagram webview has the focus).
 */
export async function select(page, path, needle, { offset = 0, length } = {}) {
    const problem = await page.evaluate(
        ([p, n, o, l]) => {
            const editor = window.maaHost.editorOf(p);
            const model = editor?.getModel();
            if (!editor || !model) return `no editor shows ${p}`;
            const at = model.getValue().indexOf(n);
            if (at < 0) return `"${n}" not found in ${p}`;
            const start = model.getPositionAt(at + o);
            const end = model.getPositionAt(at + o + (l ?? n.length - o));
            editor.setSelection({
                startLineNumber: start.lineNumber,
                startColumn: start.column,
                endLineNumber: end.lineNumber,
                endColumn: end.column,
            });
            editor.revealRangeInCenter(editor.getSelection());
            editor.focus();
            return '';
        },
        [path, needle, offset, length],
    );
    if (problem) await fail(problem);
}

/** The cursor's line in the editor showing `path`. */
export const cursorLine = (page, path) => page.evaluate((p) => window.maaHost.editorOf(p)?.getPosition()?.lineNumber, path);

/** Waits until the text of `path`'s model (saved or not) satisfies `predicate` (polled). */
export async function waitForText(page, path, predicate, what, timeout = 30_000) {
    const started = Date.now();
    for (;;) {
        const current = await page.evaluate((p) => window.maaHost.text(p), path);
        if (current !== undefined && predicate(current)) return current;
        if (Date.now() - started > timeout) await fail(`${path}: ${what} (text now:\n${current})`);
        await page.waitForTimeout(200);
    }
}

/** The frame of the diagram webview (nested iframes of the webview host page), once its diagram is mounted. */
export function diagramFrame(page, timeout = 60_000) {
    return frameWith(page, '[data-testid=diagram]', 'a mounted diagram', timeout);
}

/** Opens the diagram of the active model file with the editor title button (MontiArc: Open Diagram); resolves with its frame. */
export async function openDiagram(page, timeout = 60_000) {
    const button = page.locator('.editor-actions .action-label[aria-label^="MontiArc: Open Diagram"]').first();
    await button.waitFor({ timeout: 30_000 });
    await button.click();
    await page.locator('.tabs-container .tab', { hasText: 'MontiArc Diagram' }).first().waitFor({ timeout: 20_000 });
    const frame = await diagramFrame(page, timeout);
    await frame.locator('.maa-component').first().waitFor({ state: 'visible', timeout });
    return frame;
}

/**
 * Runs **MontiArc: Export Diagram as SVG** from the editor of `model` (the command palette's keys
 * go to the workbench, not to the webview after a click into the diagram) and answers the save
 * dialog (the workbench's own simple file dialog on the web) with `name` beside the suggested
 * path; resolves with the path written, relative to the workspace.
 */
export async function exportDiagram(page, name, model) {
    await page.evaluate((p) => window.maaHost.editorOf(p)?.focus(), model);
    await runCommand(page, 'MontiArc: Export Diagram as SVG');
    const input = page.locator('.quick-input-widget .quick-input-box input');
    await page.waitForFunction(
        () => /\.svg$/.test(document.querySelector('.quick-input-widget .quick-input-box input')?.value ?? ''),
        undefined,
        { timeout: 30_000 },
    );
    const suggested = await input.inputValue();
    const target = `${suggested.slice(0, suggested.lastIndexOf('/') + 1)}${name}`;
    await input.fill(target);
    await page.keyboard.press('Enter');
    await page
        .locator('.notifications-toasts .notification-toast', { hasText: `diagram saved to` })
        .filter({ hasText: name })
        .first()
        .waitFor({ timeout: 30_000 });
    return target.replace(/^\/workspace\//, '');
}
