#!/usr/bin/env node
// The classroom lab end to end (issue 15, docs/lab.md "The IDE in the lab"): a lab server (built
// packages/lab-server/dist, PGlite in a temporary folder) with an instructor and a roster of three
// students, the toast-controller exercise released. Two students work in separate browsers, each
// in the browser IDE of their own workspace (VS Code's workbench with the MontiArc extension,
// served by the lab at /ide/<course>/<exercise>/<login>/): ada edits and saves her controller (a
// read-only exercise file refuses the change) and runs the stream tests from the Testing view;
// bob starts a simulation. The instructor's dashboard shows both while bob's run goes on; ada
// gets 403 for bob's files; the instructor opens ada's IDE from the dashboard, read-only.
// Screenshots in e2e/artifacts/lab-ide-*.png.
//
//   flock /tmp/helpers/e2e.lock node e2e/lab-ide.mjs   (needs npm run build: lab-server, ide-web)
import { mkdtempSync, rmSync } from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { fail, runCommand } from './host-kit.mjs';
import { appDir, launchBrowser, repo, screenshot } from './lib.mjs';

const dist = path.join(repo, 'packages', 'lab-server', 'dist');
const { openLabStore } = await import(path.join(dist, 'storage', 'index.js'));
const { startLabServer } = await import(path.join(dist, 'http', 'server.js'));
const { hashPassword } = await import(path.join(dist, 'auth', 'passwords.js'));
const { parseRoster } = await import(path.join(dist, 'auth', 'roster.js'));
const { loadExercise, releaseExercise } = await import(path.join(dist, 'exercises', 'index.js'));

const PASSWORD = 'correct horse battery staple';
const COURSE = 'robotics';
const EXERCISE = 'toast-controller';
const ROSTER = `name,email,login,role
Ada Lovelace,ada@example.org,ada,student
Bob Builder,bob@example.org,bob,student
Carl Friedrich,carl@example.org,carl,student
`;
const CHANGE = "// ada's first change";

const results = [];
const step = async (name, run) => {
    const started = Date.now();
    try {
        await run();
        results.push({ name, ok: true });
        console.log(`  ✓ ${name} (${Date.now() - started} ms)`);
    } catch (error) {
        results.push({ name, ok: false });
        console.log(
            `  ✗ ${name}\n    ${String(error?.message ?? error)
                .split('\n')
                .join('\n    ')}`,
        );
        throw error;
    }
};

/** Polls `check` (async) until it is truthy; fails with `what` after `timeout` ms. */
async function until(check, what, timeout = 60_000) {
    const started = Date.now();
    for (;;) {
        const value = await check();
        if (value) return value;
        if (Date.now() - started > timeout) await fail(`not within ${timeout / 1000} s: ${what}`);
        await new Promise((r) => setTimeout(r, 250));
    }
}

/** Logs in through the lab's login page. */
async function logIn(page, base, login) {
    await page.goto(`${base}/login`);
    await page.fill('input[name=login]', login);
    await page.fill('input[name=password]', PASSWORD);
    await Promise.all([page.waitForURL((u) => !u.pathname.startsWith('/login')), page.click('button')]);
}

/** Opens a student's IDE in the lab and waits until the extension runs. */
async function openIde(page, base, login) {
    await page.goto(`${base}/ide/${COURSE}/${EXERCISE}/${login}/`);
    await page.waitForFunction(() => window.maaHost?.ready === true || document.body.dataset.failed, undefined, { timeout: 180_000 });
    const failed = await page.evaluate(() => document.body.dataset.failed);
    if (failed) await fail(`the IDE did not start in the lab: ${failed}`);
}

/** The first frame below the page that holds `selector` (webviews are nested iframes). */
async function frameWith(page, selector, what, timeout = 60_000) {
    return until(
        async () => {
            for (const frame of page.frames()) {
                if (frame === page.mainFrame()) continue;
                if (
                    (await frame
                        .locator(selector)
                        .count()
                        .catch(() => 0)) > 0
                )
                    return frame;
            }
            return undefined;
        },
        `a webview shows ${what}`,
        timeout,
    );
}

const data = mkdtempSync(path.join(os.tmpdir(), 'maa-lab-ide-e2e-'));
let store;
let server;
const browsers = [];
try {
    store = await openLabStore({ dataDir: path.join(data, 'db') });
    const passwordHash = await hashPassword(PASSWORD);
    const teacher = await store.createUser({ login: 'teacher', name: 'The Teacher', role: 'instructor', passwordHash });
    const course = await store.createCourse({ name: COURSE, title: 'Robotics lab' });
    await store.enroll(course.id, teacher.id);
    const students = {};
    for (const { user } of parseRoster(ROSTER)) {
        students[user.login] = await store.createUser({ ...user, passwordHash });
        await store.enroll(course.id, students[user.login].id);
    }
    const exercise = await loadExercise(path.join(repo, 'examples', 'lab', EXERCISE));
    const released = await releaseExercise(store, exercise, { course: COURSE, authorId: teacher.id });
    const workspaceOf = async (login) => (await store.workspace(students[login].id, released.exercise.id)).id;
    server = await startLabServer({ store, port: 0, log: () => undefined, appDir, workspaces: { dataDir: path.join(data, 'ws') } });
    const base = server.url;
    console.log(`e2e: maa-lab at ${base}, ${Object.keys(students).length} students, ${EXERCISE} released`);

    const ada = await launchBrowser({ width: 1400, height: 900 });
    browsers.push(ada);
    const bob = await launchBrowser({ width: 1400, height: 900 });
    browsers.push(bob);

    await step('ada opens the IDE of her workspace: the workbench, the Exercise view, her files', async () => {
        await logIn(ada.page, base, 'ada');
        await openIde(ada.page, base, 'ada');
        await ada.page.locator('.pane-header', { hasText: 'Exercise' }).first().waitFor({ timeout: 30_000 });
        await ada.page.locator('.explorer-folders-view .monaco-list-row', { hasText: 'toast' }).first().waitFor({ timeout: 30_000 });
        await screenshot(ada.page, 'lab-ide-ada');
    });

    await step('a read-only exercise file refuses changes; her controller is saved as a new revision', async () => {
        const { page } = ada;
        await page.evaluate(() => window.maaHost.open('TR.arcapp'));
        const readOnly = await page.evaluate(() => window.maaHost.activeEditor()?.getRawOptions().readOnly === true);
        if (!readOnly) await fail('TR.arcapp (read-only in exercise.json) opens as a writable editor');
        const refused = await page.evaluate(async () => (await fetch('api/file?path=TR.arcapp', { method: 'PUT', body: 'x' })).status);
        if (refused !== 403) await fail(`saving TR.arcapp answered ${refused}, expected 403`);
        await page.evaluate(() => window.maaHost.open('toast/Controller.arc'));
        await page.locator('.editor-instance .monaco-editor .view-lines').first().click();
        await page.keyboard.press('Control+End');
        await page.keyboard.type(`\n${CHANGE}`);
        await page.keyboard.press('Control+S');
        const id = await workspaceOf('ada');
        await until(async () => (await store.readFile(id, 'toast/Controller.arc'))?.content.includes(CHANGE), 'the lab stores ada’s save');
    });

    await step('ada runs the stream tests from the Testing view; the lab records the result', async () => {
        const { page } = ada;
        // The Testing view shows the results; its run-all command runs every case of the exercise's tests.
        await page.locator('.activitybar .action-item a[aria-label^="Testing"]').first().click();
        await page.locator('.test-explorer .monaco-list-row').first().waitFor({ timeout: 60_000 });
        await runCommand(page, 'Test: Run All Tests');
        await page
            .locator('.test-explorer .codicon-testing-passed-icon, .test-explorer .codicon-testing-failed-icon')
            .first()
            .waitFor({ timeout: 240_000 });
        const id = await workspaceOf('ada');
        const recorded = await until(() => store.latestTestResult(id), 'the lab records ada’s test run', 120_000);
        if (recorded.passed + recorded.failed === 0) await fail(`the recorded run has no tests: ${JSON.stringify(recorded)}`);
        await screenshot(page, 'lab-ide-ada-tests');
    });

    await step('bob, in his own browser, starts a simulation in his IDE', async () => {
        const { page } = bob;
        await logIn(page, base, 'bob');
        await openIde(page, base, 'bob');
        await runCommand(page, 'MontiArc: Start Simulation');
        const row = page.locator('.quick-input-list .monaco-list-row', { hasText: 'TR.arcapp' }).filter({ hasText: 'timesync' }).first();
        await row.waitFor({ timeout: 30_000 });
        await row.click();
        const view = await frameWith(page, '[data-testid=simulate-panel]', 'the simulate panel', 90_000);
        await view.locator('[data-testid=viser-frame]').waitFor({ timeout: 240_000 });
        await until(
            async () => (await page.evaluate(async () => (await fetch('api/sim/status')).json())).running,
            'bob’s simulation runs',
            120_000,
        );
        await screenshot(page, 'lab-ide-bob-simulating');
    });

    await step("ada gets 403 for bob's workspace, through his IDE's paths and the API", async () => {
        const { page } = ada;
        const statuses = await page.evaluate(
            async ({ course, exercise }) => {
                const ide = `/ide/${course}/${exercise}/bob`;
                return [
                    (await fetch(`${ide}/api/file?path=toast/Controller.arc`)).status,
                    (await fetch(`${ide}/api/file?path=toast/Controller.arc`, { method: 'PUT', body: 'ada was here' })).status,
                    (await fetch(`/api/ws/${course}/${exercise}/bob/files`)).status,
                    (await fetch(`${ide}/`)).status,
                ];
            },
            { course: COURSE, exercise: EXERCISE },
        );
        if (statuses.some((s) => s !== 403)) await fail(`ada on bob's workspace got ${statuses.join(', ')}, expected 403 each`);
        const bobs = await store.readFile(await workspaceOf('bob'), 'toast/Controller.arc');
        if (bobs.content.includes('ada was here')) await fail("bob's controller was changed by ada");
    });

    await step("the instructor's dashboard shows ada's tests and bob simulating", async () => {
        const { page } = ada;
        await page.context().clearCookies();
        await logIn(page, base, 'teacher');
        await page.goto(`${base}/dashboard/${COURSE}`);
        await page.waitForSelector('table#dashboard tbody tr', { timeout: 120_000 });
        await page.waitForFunction(
            () => {
                const rows = [...document.querySelectorAll('table#dashboard tbody tr')].map((tr) => tr.textContent ?? '');
                const adaRow = rows.find((r) => r.includes('(ada)')) ?? '';
                const bobRow = rows.find((r) => r.includes('(bob)')) ?? '';
                return rows.length === 3 && /tests \d+\/\d+/.test(adaRow) && bobRow.includes('simulating now');
            },
            undefined,
            { timeout: 120_000 },
        );
        await screenshot(page, 'lab-ide-dashboard');
    });

    await step("the instructor opens ada's IDE from the dashboard: everything read-only", async () => {
        const { page } = ada;
        const link = page.locator('table#dashboard tbody tr', { hasText: '(ada)' }).locator('a', { hasText: 'in the IDE' }).first();
        await Promise.all([page.waitForURL(/\/ide\/robotics\/toast-controller\/ada\/$/), link.click()]);
        await page.waitForFunction(() => window.maaHost?.ready === true || document.body.dataset.failed, undefined, { timeout: 180_000 });
        await page.locator('.pane-body .monaco-list-row', { hasText: "ada's workspace" }).first().waitFor({ timeout: 30_000 });
        await page.evaluate(() => window.maaHost.open('toast/Controller.arc'));
        const readOnly = await page.evaluate(() => window.maaHost.activeEditor()?.getRawOptions().readOnly === true);
        if (!readOnly) await fail("ada's controller opens writable for the instructor");
        await screenshot(page, 'lab-ide-instructor-view');
    });

    await step('bob stops his simulation', async () => {
        const { page } = bob;
        await page.locator('.editor-instance .monaco-editor .view-lines').first().click();
        await runCommand(page, 'MontiArc: Stop Simulation');
        await until(
            async () => !(await page.evaluate(async () => (await fetch('api/sim/status')).json())).running,
            'bob’s simulation stops',
            60_000,
        );
    });
} catch (error) {
    console.error(`e2e: ${error?.stack ?? error}`);
    results.push({ name: 'run', ok: false });
    for (const [i, b] of browsers.entries()) await screenshot(b.page, `lab-ide-FAIL-${i}`).catch(() => undefined);
    for (const b of browsers) console.error(`  browser console (last lines):\n    ${b.consoleLines.slice(-10).join('\n    ')}`);
} finally {
    for (const b of browsers) await b.close();
    await server?.close();
    await store?.close();
    rmSync(data, { recursive: true, force: true });
}
const failed = results.filter((r) => !r.ok).length;
console.log(`\ne2e lab IDE: ${results.length - failed} passed, ${failed} failed`);
process.exit(failed ? 1 : 0);
