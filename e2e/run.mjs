#!/usr/bin/env node
// The browser IDE's end-to-end tests (issues 7 and 14): maa-ide on a fresh copy of examples/
// (port 0) serving VS Code's workbench with the MontiArc extension (packages/ide-web), Debian's
// chromium through playwright-core, one scenario after the other in one workspace, screenshots in
// e2e/artifacts/. The scenarios: e2e/host-scenarios.mjs (open, errors, quick fix, completion,
// rename, the diagram and its export, the test explorer, the workbench host), generation
// (e2e/generated-scenarios.mjs), simulation (e2e/simulate-scenarios.mjs) and its panels
// (e2e/panels-scenarios.mjs) and breakpoints (e2e/breakpoint-scenarios.mjs), record and replay
// (e2e/replay-scenarios.mjs), then the large model's
// (last: it adds 200 component types to the workspace).
//
//   node e2e/run.mjs                 all scenarios (needs packages/ide-web/dist: npm run build -w @maa/ide-web)
//   node e2e/run.mjs --only 'error|fix'   scenarios whose name matches the regular expression
//   node e2e/run.mjs --log           also print maa-ide's output
import { mkdirSync, writeFileSync } from 'node:fs';
import path from 'node:path';
import { artifacts, freshWorkspace, launchBrowser, screenshot, startIde } from './lib.mjs';
import { generatedScenarios } from './generated-scenarios.mjs';
import { hostScenarios, largeModelScenarios } from './host-scenarios.mjs';
import { simulateScenarios } from './simulate-scenarios.mjs';
import { replayScenarios } from './replay-scenarios.mjs';
import { panelsScenarios } from './panels-scenarios.mjs';
import { breakpointScenarios } from './breakpoint-scenarios.mjs';

const scenarios = [
    ...hostScenarios,
    ...generatedScenarios,
    ...simulateScenarios,
    ...replayScenarios,
    ...panelsScenarios,
    ...breakpointScenarios,
    ...largeModelScenarios,
];

const args = process.argv.slice(2);
const only = args.includes('--only') ? args[args.indexOf('--only') + 1] : undefined;
const log = args.includes('--log');

const selected = scenarios.filter((s) => !only || new RegExp(only, 'i').test(s.name));
if (selected.length === 0) {
    console.error(`e2e: no scenario matches "${only}"`);
    process.exit(2);
}

mkdirSync(artifacts, { recursive: true });
const ws = freshWorkspace();
let ide;
let browser;
const results = [];
try {
    ide = await startIde(ws.workspace, { log });
    console.log(`e2e: maa-ide at ${ide.url} on ${ws.workspace}`);
    browser = await launchBrowser();
    await ide.login(browser.page);
    for (const scenario of selected) {
        const started = Date.now();
        const ctx = {
            page: browser.page,
            url: ide.url,
            workspace: ws.workspace,
            shot: (name) => screenshot(browser.page, `${scenario.id}-${name}`),
        };
        try {
            await scenario.run(ctx);
            await screenshot(browser.page, `${scenario.id}-pass`);
            results.push({ name: scenario.name, ok: true, ms: Date.now() - started });
            console.log(`  ✓ ${scenario.name} (${Date.now() - started} ms)`);
        } catch (error) {
            const file = await screenshot(browser.page, `${scenario.id}-FAIL`).catch(() => undefined);
            results.push({ name: scenario.name, ok: false, ms: Date.now() - started, error: String(error?.stack ?? error) });
            console.log(
                `  ✗ ${scenario.name} (${Date.now() - started} ms)\n    ${String(error?.message ?? error)
                    .split('\n')
                    .join('\n    ')}`,
            );
            if (file) console.log(`    screenshot: ${path.relative(process.cwd(), file)}`);
            const consoleTail = browser.consoleLines.slice(-15);
            if (consoleTail.length) console.log(`    browser console (last lines):\n      ${consoleTail.join('\n      ')}`);
        }
    }
} catch (error) {
    console.error(`e2e: ${error?.stack ?? error}`);
    results.push({ name: 'setup', ok: false, error: String(error) });
} finally {
    await browser?.close();
    await ide?.stop();
    ws.dispose();
}

writeFileSync(path.join(artifacts, 'results.json'), JSON.stringify(results, null, 2));
const failed = results.filter((r) => !r.ok);
console.log(
    `\ne2e: ${results.length - failed.length} passed, ${failed.length} failed; screenshots in ${path.relative(process.cwd(), artifacts) || artifacts}`,
);
process.exit(failed.length ? 1 : 0);
