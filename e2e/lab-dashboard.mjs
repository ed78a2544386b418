#!/usr/bin/env node
// The lab's instructor dashboard in chromium (issue 15 item 5, docs/lab.md "The instructor's
// dashboard"): a lab server (built packages/lab-server/dist, PGlite in a temporary folder) with a
// course, two students and the toast-controller exercise released; ada's controller has an error,
// bob's stream tests passed. The instructor logs in through the login page and sees the table
// (both students, the cells' texts), filters it by name, sorts it, opens ada's workspace read-only
// (her file with its diagnostic) and resets it (confirm, CSRF token). Any CSP violation fails it.
//
//   node e2e/lab-dashboard.mjs   (needs npm run build -w @maa/lab-server)
import { mkdtempSync, rmSync } from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { launchBrowser, repo, screenshot, stepRunner } from './lib.mjs';

const dist = path.join(repo, 'packages', 'lab-server', 'dist');
const { openLabStore } = await import(path.join(dist, 'storage', 'index.js'));
const { startLabServer } = await import(path.join(dist, 'http', 'server.js'));
const { hashPassword } = await import(path.join(dist, 'auth', 'passwords.js'));
const { loadExercise, releaseExercise } = await import(path.join(dist, 'exercises', 'index.js'));

const PASSWORD = 'correct horse battery staple';
const results = [];
const step = stepRunner(results);

const data = mkdtempSync(path.join(os.tmpdir(), 'maa-lab-e2e-'));
let store;
let server;
let browser;
try {
    store = await openLabStore({ dataDir: path.join(data, 'db') });
    const passwordHash = await hashPassword(PASSWORD);
    const teacher = await store.createUser({ login: 'teacher', name: 'The Teacher', role: 'instructor', passwordHash });
    const ada = await store.createUser({ login: 'ada', name: 'Ada Lovelace', role: 'student', passwordHash });
    const bob = await store.createUser({ login: 'bob', name: 'Bob Builder', role: 'student', passwordHash });
    const course = await store.createCourse({ name: 'robotics', title: 'Robotics lab' });
    for (const u of [teacher, ada, bob]) await store.enroll(course.id, u.id);
    const exercise = await loadExercise(path.join(repo, 'examples', 'lab', 'toast-controller'));
    const released = await releaseExercise(store, exercise, { course: 'robotics', authorId: teacher.id });
    const adaWs = await store.workspace(ada.id, released.exercise.id);
    const controller = await store.readFile(adaWs.id, 'toast/Controller.arc');
    await store.saveFile({
        workspaceId: adaWs.id,
        path: 'toast/Controller.arc',
        content: controller.content.replace(/\}\s*$/, '  port out NoSuchType broken;\n}\n'),
        authorId: ada.id,
    });
    const bobWs = await store.workspace(bob.id, released.exercise.id);
    await store.recordTestResult({ workspaceId: bobWs.id, submissionId: null, passed: 4, failed: 0, skipped: 0, details: null });
    server = await startLabServer({ store, port: 0, log: () => undefined, workspaces: { dataDir: path.join(data, 'ws') } });
    console.log(`e2e: maa-lab at ${server.url}`);

    browser = await launchBrowser({ width: 1400, height: 900 });
    const { page } = browser;
    const violations = [];
    page.on('console', (m) => {
        if (/Content Security Policy/i.test(m.text())) violations.push(m.text());
    });
    page.on('dialog', (dialog) => void dialog.accept());

    await step('the instructor logs in and sees the table of both students', async () => {
        await page.goto(`${server.url}/dashboard/robotics`);
        await page.waitForURL(/\/login$/);
        await page.fill('input[name=login]', 'teacher');
        await page.fill('input[name=password]', PASSWORD);
        await Promise.all([page.waitForURL((u) => !u.pathname.startsWith('/login')), page.click('button')]);
        await page.goto(`${server.url}/dashboard/robotics`);
        await page.waitForSelector('table#dashboard tbody tr', { timeout: 120_000 });
        // the first answer may have cells still "checking…" (the checker thread); the page polls every 5 s
        await page.waitForFunction(() => !document.querySelector('table#dashboard')?.textContent?.includes('checking'), undefined, {
            timeout: 120_000,
        });
        const rows = await page.$$eval('table#dashboard tbody tr', (trs) => trs.map((tr) => tr.textContent ?? ''));
        if (rows.length !== 2) throw new Error(`expected 2 rows, got ${rows.length}: ${rows.join(' | ')}`);
        if (!rows[0].includes('Ada Lovelace (ada)') || !/\d+ errors?/.test(rows[0]) || rows[0].includes('no problems'))
            throw new Error(`ada's row: ${rows[0]}`);
        if (!rows[1].includes('Bob Builder (bob)') || !rows[1].includes('tests 4/4 passed')) throw new Error(`bob's row: ${rows[1]}`);
        const headers = await page.$$eval('thead th', (ths) => ths.map((th) => `${th.getAttribute('scope')}:${th.textContent}`));
        if (headers.join('|') !== "col:Student ▲|col:The toast robot's controller") throw new Error(`headers: ${headers.join('|')}`);
        await page.waitForSelector('td.bad');
        await page.waitForSelector('td.good');
        await screenshot(page, 'lab-dashboard-table');
    });

    await step('filters by name and sorts by a column', async () => {
        await page.fill('#filter', 'bob');
        await page.waitForFunction(() => document.querySelectorAll('table#dashboard tbody tr').length === 1);
        await page.fill('#filter', '');
        await page.waitForFunction(() => document.querySelectorAll('table#dashboard tbody tr').length === 2);
        await page.click('thead th:nth-child(1) button');
        await page.waitForSelector('thead th:nth-child(1)[aria-sort=descending]');
        const first = await page.textContent('table#dashboard tbody tr:first-child th');
        if (first !== 'Bob Builder (bob)') throw new Error(`sorted descending, first row: ${first}`);
    });

    await step("opens ada's workspace read-only with its diagnostics", async () => {
        await page.fill('#filter', 'ada');
        await page.waitForFunction(() => document.querySelectorAll('table#dashboard tbody tr').length === 1);
        await Promise.all([page.waitForURL(/\/dashboard\/robotics\/toast-controller\/ada$/), page.click('text=open read-only')]);
        await page.waitForSelector('h2:has-text("toast/Controller.arc")', { timeout: 120_000 });
        const items = await page.$$eval('li.diag-error', (lis) => lis.map((li) => li.textContent ?? ''));
        if (!items.some((t) => t.includes('NoSuchType'))) throw new Error(`diagnostics: ${items.join(' | ')}`);
        await screenshot(page, 'lab-dashboard-workspace');
    });

    await step("resets ada's workspace after a confirm (with the CSRF token)", async () => {
        await page.goto(`${server.url}/dashboard/robotics`);
        await page.waitForSelector('table#dashboard tbody tr');
        await page.click('table#dashboard tbody tr:first-child button:has-text("Reset")');
        await page.waitForFunction(() => /Reset /.test(document.getElementById('status')?.textContent ?? ''), undefined, {
            timeout: 60_000,
        });
        const status = await page.textContent('#status');
        if (!status.startsWith("Reset ada's toast-controller")) throw new Error(`status: ${status}`);
        const content = (await store.readFile(adaWs.id, 'toast/Controller.arc')).content;
        if (content.includes('NoSuchType')) throw new Error('the reset did not restore the starter');
    });

    if (violations.length) throw new Error(`CSP violations:\n${violations.join('\n')}`);
} catch (error) {
    console.error(`e2e: ${error?.stack ?? error}`);
    results.push({ name: 'run', ok: false });
    if (browser) await screenshot(browser.page, 'lab-dashboard-FAIL').catch(() => undefined);
} finally {
    await browser?.close();
    await server?.close();
    await store?.close();
    rmSync(data, { recursive: true, force: true });
}
const failed = results.filter((r) => !r.ok).length;
console.log(`\ne2e lab dashboard: ${results.length - failed} passed, ${failed} failed`);
process.exit(failed ? 1 : 0);
