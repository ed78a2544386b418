// The e2e scenarios of the workbench host (issue 14, host.html): VS Code's workbench from
// @codingame/monaco-vscode-api with the MontiArc extension's web entry loaded into it. They run
// after the scenarios of the old IDE (run.mjs), in the same workspace, on their own page.
import { editorOf, fail, openHost, ROBOT, runCommand } from './host-kit.mjs';

export const hostScenarios = [
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
        async run({ page, url, shot }) {
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
            // Undo the edit (the file on disk was never saved): the error goes away.
            const mod = process.platform === 'darwin' ? 'Meta' : 'Control';
            await page.keyboard.press(`${mod}+KeyZ`);
            await page.keyboard.press(`${mod}+KeyZ`);
            await page.waitForFunction((p) => !window.maaHost.markers(p).some((m) => m.severity === 8), ROBOT, { timeout: 30_000 });
        },
    },
];
