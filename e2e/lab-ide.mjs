#!/usr/bin/env node
// The classroom lab end to end (issue 15, docs/lab.md "The IDE in the lab"), as an instructor runs
// it: `maa-lab course create`, `users add` (the instructor), `users import` of a roster of three
// students (invitation links), `exercise release`, then `maa-lab serve` on that data directory
// (PGlite in a temporary folder). The students set their passwords through their invitation
// links and reach the exercise from the start page. Two students work in separate browsers, each
// in the browser IDE of their own workspace (VS Code's workbench with the MontiArc extension,
// served by the lab at /ide/<course>/<exercise>/<login>/): ada edits and saves her controller (a
// read-only exercise file refuses the change), runs the stream tests from the Testing view and
// simulates; bob does the same and keeps his simulation running. The instructor's dashboard
// shows both students' tests and bob simulating; ada gets 403 for bob's files; the instructor
// opens ada's IDE from the dashboard, read-only. ada submits her controller for grading from the
// Exercise view (issue 17): the grade and its feedback appear there and in the dashboard's grading
// table, with the CSV and the scenario recordings. Screenshots in e2e/artifacts/lab-ide-*.png.
//
//   node e2e/lab-ide.mjs   (needs npm run build: lab-server, ide-web)
import { execFile, spawn } from 'node:child_process';
import { mkdtempSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { fail, frameWith, runCommand, waitForIde } from './host-kit.mjs';
import { appDir, launchBrowser, repo, screenshot, stepRunner } from './lib.mjs';

const MAA_LAB = path.join(repo, 'packages', 'lab-server', 'bin', 'maa-lab.js');

const PASSWORD = 'correct horse battery staple';
const COURSE = 'robotics';
const EXERCISE = 'toast-controller';
const ROSTER = `name,email,login,role
Ada Lovelace,ada@example.org,ada,student
Bob Builder,bob@example.org,bob,student
Carl Friedrich,carl@example.org,carl,student
`;

const results = [];
const step = stepRunner(results);

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

const data = mkdtempSync(path.join(os.tmpdir(), 'maa-lab-ide-e2e-'));
const dataDir = path.join(data, 'lab-data');

/** Runs a `maa-lab` command on the data directory (its output is printed when it fails). */
async function maaLab(args, input) {
    const child = execFile(process.execPath, [MAA_LAB, ...args, '--data-dir', dataDir], { cwd: data });
    if (input !== undefined) child.stdin.end(input);
    const [code, out, err] = await new Promise((resolve) => {
        let stdout = '';
        let stderr = '';
        child.stdout.on('data', (d) => (stdout += d));
        child.stderr.on('data', (d) => (stderr += d));
        child.on('close', (c) => resolve([c, stdout, stderr]));
    });
    if (code !== 0) await fail(`maa-lab ${args.join(' ')} exited with ${code}:\n${out}${err}`);
    return out;
}

/** Starts `maa-lab serve` on a free port; resolves with its URL and a stop function. */
async function serve() {
    const child = spawn(process.execPath, [MAA_LAB, 'serve', '--port', '0', '--data-dir', dataDir, '--app-dir', appDir], {
        cwd: data,
        stdio: ['ignore', 'pipe', 'pipe'],
    });
    let log = '';
    child.stderr.on('data', (d) => (log = (log + d).slice(-4000)));
    const url = await new Promise((resolve, reject) => {
        let out = '';
        child.stdout.on('data', (d) => {
            out += d;
            const m = /maa-lab serves (http:\/\/\S+) /.exec(out);
            if (m) resolve(m[1]);
        });
        child.once('exit', (code) => reject(new Error(`maa-lab serve exited with ${code}: ${log}`)));
    });
    return {
        url,
        log: () => log,
        stop: async () => {
            if (child.exitCode !== null) return;
            const exited = new Promise((resolve) => child.once('exit', resolve));
            child.kill('SIGTERM');
            const timer = setTimeout(() => child.kill('SIGKILL'), 10_000);
            await exited;
            clearTimeout(timer);
        },
    };
}

/** Sets a student's password through their invitation link (the link's address is the lab's). */
async function acceptInvitation(page, base, link) {
    const invitation = new URL(link);
    await page.goto(`${base}${invitation.pathname}${invitation.search}${invitation.hash}`);
    await page.fill('input[name=password]', PASSWORD);
    await Promise.all([page.waitForURL((u) => u.pathname === '/'), page.click('button')]);
}

/** From the start page, the exercise's link: the IDE of the student's own workspace. */
async function openFromStartPage(page, login) {
    await page.locator('a', { hasText: "The toast robot's controller" }).first().click();
    await page.waitForURL(new RegExp(`/ide/${COURSE}/${EXERCISE}/${login}/$`));
    await waitForIde(page, 180_000);
}

/** Opens the explorer's Exercise view (the explorer shows it collapsed under the files). */
async function expandExerciseView(page) {
    const header = page.locator('.pane-header', { hasText: 'Exercise' }).first();
    // The view is in the explorer; another view container (Testing) may be in front of it.
    if (!(await header.isVisible())) await page.locator('.activitybar .action-item a[aria-label^="Explorer"]').first().click();
    await header.waitFor({ timeout: 30_000 });
    if ((await header.getAttribute('aria-expanded')) !== 'true') await header.click();
}

/** A JSON answer of the lab, asked from the page (its session cookie). */
const ask = (page, url, init) =>
    page.evaluate(
        async ({ url, init }) => {
            const r = await fetch(url, init);
            return { status: r.status, json: await r.json().catch(() => undefined) };
        },
        { url, init },
    );

/** Appends a line to the student's controller in the editor and saves it (Ctrl+S); the lab stores it. */
async function saveEdit(page, login) {
    const change = `// ${login}'s first change`;
    await page.evaluate(() => window.maaHost.open('toast/Controller.arc'));
    await page.locator('.editor-instance .monaco-editor .view-lines').first().click();
    await page.keyboard.press('Control+End');
    await page.keyboard.type(`\n${change}`);
    await page.keyboard.press('Control+S');
    // The lab's answer comes from its database: a new revision of the file.
    await until(
        async () => (await page.evaluate(async () => (await fetch('api/file?path=toast/Controller.arc')).text())).includes(change),
        `the lab stores ${login}'s save`,
    );
}

/** Runs every stream test from the Testing view and waits until the lab recorded the run. */
async function runTests(page, login) {
    await page.locator('.activitybar .action-item a[aria-label^="Testing"]').first().click();
    await page.locator('.test-explorer .monaco-list-row').first().waitFor({ timeout: 60_000 });
    await runCommand(page, 'Test: Run All Tests');
    await page
        .locator('.test-explorer .codicon-testing-passed-icon, .test-explorer .codicon-testing-failed-icon')
        .first()
        .waitFor({ timeout: 240_000 });
    const recorded = await until(
        async () => (await ask(page, 'api/exercise')).json?.latestTests,
        `the lab records ${login}'s test run`,
        120_000,
    );
    if (recorded.passed + recorded.failed === 0) await fail(`${login}'s recorded run has no tests: ${JSON.stringify(recorded)}`);
}

/** The focus in a model editor (keys then reach the workbench, not a webview or the test results). */
async function focusEditor(page) {
    await page.keyboard.press('Escape');
    await page.evaluate(() => window.maaHost.open('toast/Controller.arc'));
}

const simRunning = async (page) => (await ask(page, 'api/sim/status')).json?.running === true;

/** MontiArc: Start Simulation (TR.arcapp on timesync): the simulate view with the 3D view, and the run. */
async function startSimulation(page, login) {
    await focusEditor(page);
    await runCommand(page, 'MontiArc: Start Simulation');
    const row = page.locator('.quick-input-list .monaco-list-row', { hasText: 'TR.arcapp' }).filter({ hasText: 'timesync' }).first();
    await row.waitFor({ timeout: 30_000 });
    await row.click();
    const view = await frameWith(page, '[data-testid=simulate-panel]', 'the simulate panel', 90_000);
    await view.locator('[data-testid=viser-frame]').waitFor({ timeout: 240_000 });
    await until(() => simRunning(page), `${login}'s simulation runs`, 120_000);
}

/** MontiArc: Stop Simulation, from the editor (the command palette belongs to the workbench, not the webview). */
async function stopSimulation(page, login) {
    await focusEditor(page);
    await runCommand(page, 'MontiArc: Stop Simulation');
    await until(async () => !(await simRunning(page)), `${login}'s simulation stops`, 60_000);
}

let server;
const browsers = [];
try {
    await maaLab(['course', 'create', COURSE, '--title', 'Robotics lab']);
    await maaLab(
        ['users', 'add', 'teacher', '--name', 'The Teacher', '--role', 'instructor', '--course', COURSE, '--password-stdin'],
        `${PASSWORD}\n`,
    );
    const roster = path.join(data, 'roster.csv');
    writeFileSync(roster, ROSTER);
    const linksFile = path.join(data, 'links.csv');
    await maaLab(['users', 'import', roster, '--course', COURSE, '--out', linksFile, '--public-url', 'http://lab.invalid']);
    const links = Object.fromEntries(
        readFileSync(linksFile, 'utf8')
            .trim()
            .split('\n')
            .slice(1)
            .map((line) => [line.split(',')[0], line.split(',').at(-1)]),
    );
    await maaLab(['exercise', 'release', path.join(repo, 'examples', 'lab', EXERCISE), '--course', COURSE]);
    server = await serve();
    const base = server.url;
    console.log(`e2e: maa-lab at ${base}, ${Object.keys(links).length} students invited, ${EXERCISE} released`);

    const ada = await launchBrowser({ width: 1400, height: 900 });
    browsers.push(ada);
    const bob = await launchBrowser({ width: 1400, height: 900 });
    browsers.push(bob);

    await step('ada opens the IDE of her workspace: the workbench, the Exercise view, her files', async () => {
        await acceptInvitation(ada.page, base, links.ada);
        await openFromStartPage(ada.page, 'ada');
        await expandExerciseView(ada.page);
        await ada.page.locator('.pane-body .monaco-list-row', { hasText: 'Your workspace (ada)' }).first().waitFor({ timeout: 30_000 });
        // The exercise's description opens with the IDE, in a read-only tab.
        await ada.page.locator('.tabs-container .tab', { hasText: 'description.md' }).first().waitFor({ timeout: 30_000 });
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
        await saveEdit(page, 'ada');
    });

    await step('ada runs the stream tests from the Testing view; the lab records the result', async () => {
        await runTests(ada.page, 'ada');
        await screenshot(ada.page, 'lab-ide-ada-tests');
    });

    await step('ada submits for grading from the Exercise view: her grade, feedback that opens the model at its line', async () => {
        const { page } = ada;
        await expandExerciseView(page);
        const row = (text) => page.locator('.pane-body .monaco-list-row', { hasText: text }).first();
        await row('Submit for grading').click();
        // Her controller is still the starter's stub: the lab grades it (hidden tests, three
        // scenarios in the sandbox on local Ray) and the Grading row shows the total.
        await row('/ 100').waitFor({ timeout: 600_000 });
        const grade = await row('/ 100').textContent();
        if (/100 \/ 100/.test(grade ?? '')) await fail(`the stub got full marks: ${grade}`);
        await screenshot(page, 'lab-ide-ada-graded');
        await row('keeps its interface').click();
        const item = row('toast/Controller.arc:');
        await item.waitFor({ timeout: 30_000 });
        await item.click();
        await page.locator('.tabs-container .tab.active', { hasText: 'Controller.arc' }).first().waitFor({ timeout: 30_000 });
    });

    await step('ada simulates: the run starts in her IDE and stops', async () => {
        await startSimulation(ada.page, 'ada');
        await stopSimulation(ada.page, 'ada');
    });

    await step('bob, in his own browser, edits and saves his controller and runs the tests', async () => {
        const { page } = bob;
        await acceptInvitation(page, base, links.bob);
        await openFromStartPage(page, 'bob');
        await saveEdit(page, 'bob');
        await runTests(page, 'bob');
    });

    await step('bob starts a simulation in his IDE', async () => {
        await startSimulation(bob.page, 'bob');
        await screenshot(bob.page, 'lab-ide-bob-simulating');
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
        const bobs = await bob.page.evaluate(async () => (await fetch('api/file?path=toast/Controller.arc')).text());
        if (bobs.includes('ada was here')) await fail("bob's controller was changed by ada");
    });

    await step("the instructor's dashboard shows both students' tests and bob simulating", async () => {
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
                const tested = (row) => /tests \d+\/\d+/.test(row);
                return rows.length === 3 && tested(adaRow) && tested(bobRow) && bobRow.includes('simulating now');
            },
            undefined,
            { timeout: 120_000 },
        );
        await screenshot(page, 'lab-ide-dashboard');
    });

    await step("the dashboard's grading: ada's scores per criterion, her feedback, the CSV and her recordings", async () => {
        const { page } = ada;
        const section = page.locator(`#grading-${EXERCISE}`);
        const adaRow = section.locator('table.grades tbody tr', { hasText: '(ada)' }).first();
        await adaRow.waitFor({ timeout: 60_000 });
        if (!/\/100\s*$/.test((await adaRow.textContent()) ?? ''))
            await fail(`ada's grading row has no total: ${await adaRow.textContent()}`);
        await adaRow.locator('button').click();
        const recording = section.locator('ul.recordings a').first();
        await recording.waitFor({ timeout: 10_000 });
        await recording.scrollIntoViewIfNeeded();
        await screenshot(page, 'lab-ide-dashboard-grading');
        const csvHref = await section.locator('a', { hasText: 'CSV' }).getAttribute('href');
        const got = await page.evaluate(
            async ({ csv, mcap }) => {
                const c = await fetch(csv);
                const m = await fetch(mcap);
                const bytes = new Uint8Array(await m.arrayBuffer());
                return {
                    csv: await c.text(),
                    mcap: m.status,
                    disposition: m.headers.get('content-disposition'),
                    magic: [...bytes.slice(0, 5)],
                };
            },
            { csv: csvHref, mcap: await recording.getAttribute('href') },
        );
        const [header, ...lines] = got.csv.trim().split('\n');
        if (!header.includes('hidden-tests') || !header.includes('scenarios') || !lines.some((l) => l.startsWith('ada,')))
            await fail(`the grades CSV lacks the criteria or ada:\n${got.csv}`);
        // an MCAP file starts with the magic bytes 0x89 'MCAP'
        if (got.mcap !== 200 || !/attachment/.test(got.disposition ?? '') || got.magic.join() !== '137,77,67,65,80')
            await fail(`ada's recording answered ${got.mcap} (${got.disposition}, ${got.magic})`);
    });

    await step("the instructor opens ada's IDE from the dashboard: everything read-only", async () => {
        const { page } = ada;
        const link = page.locator('table#dashboard tbody tr', { hasText: '(ada)' }).locator('a', { hasText: 'in the IDE' }).first();
        await Promise.all([page.waitForURL(/\/ide\/robotics\/toast-controller\/ada\/$/), link.click()]);
        await waitForIde(page, 180_000);
        await expandExerciseView(page);
        await page.locator('.pane-body .monaco-list-row', { hasText: "ada's workspace" }).first().waitFor({ timeout: 30_000 });
        await page.evaluate(() => window.maaHost.open('toast/Controller.arc'));
        const readOnly = await page.evaluate(() => window.maaHost.activeEditor()?.getRawOptions().readOnly === true);
        if (!readOnly) await fail("ada's controller opens writable for the instructor");
        await screenshot(page, 'lab-ide-instructor-view');
    });

    await step('bob stops his simulation', async () => {
        await stopSimulation(bob.page, 'bob');
    });
} catch (error) {
    console.error(`e2e: ${error?.stack ?? error}`);
    results.push({ name: 'run', ok: false });
    for (const [i, b] of browsers.entries()) await screenshot(b.page, `lab-ide-FAIL-${i}`).catch(() => undefined);
    for (const b of browsers) console.error(`  browser console (last lines):\n    ${b.consoleLines.slice(-10).join('\n    ')}`);
    if (server) console.error(`  maa-lab's log (last lines):\n${server.log()}`);
} finally {
    for (const b of browsers) await b.close();
    await server?.stop();
    rmSync(data, { recursive: true, force: true });
}
const failed = results.filter((r) => !r.ok).length;
console.log(`\ne2e lab IDE: ${results.length - failed} passed, ${failed} failed`);
process.exit(failed ? 1 : 0);
