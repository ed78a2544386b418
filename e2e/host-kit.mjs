// Shared steps of the e2e scenarios on the browser IDE (VS Code's workbench from
// @codingame/monaco-vscode-api with the MontiArc extension's web entry, docs/ide.md).
export const ROBOT = 'toast-service/toast/ToastServiceRobot.arc';

export async function fail(message) {
    throw new Error(message);
}

/** Loads the IDE with `open` as the first editor and waits until the extension is active. */
export async function openHost(page, url, open = ROBOT) {
    await page.goto(`${url}?open=${encodeURIComponent(open)}`);
    await page.waitForFunction(() => window.maaHost?.ready === true || document.body.dataset.failed, undefined, { timeout: 90_000 });
    const failed = await page.evaluate(() => document.body.dataset.failed);
    if (failed) await fail(`the workbench host did not start: ${failed}`);
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
