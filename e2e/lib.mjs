// Shared helpers of the e2e tests and the IDE benchmark: a fresh workspace, the maa-ide
// backend on a free port, and Debian's chromium driven by playwright-core.
import { spawn } from 'node:child_process';
import { cpSync, existsSync, mkdirSync, mkdtempSync, rmSync, writeFileSync } from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { chromium } from 'playwright-core';
import { generateModels, writeSystemComponent } from '../packages/cli/bench/generate-models.mjs';
import { ensureChromium } from '../scripts/ensure-chromium.mjs';
import { fail, frameWith, openHost, ROBOT, runCommand } from './host-kit.mjs';

export const repo = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..');
/** The built app (MAA_IDE_APP_DIR overrides packages/ide-web/dist). */
export const appDir = process.env.MAA_IDE_APP_DIR
    ? path.resolve(process.env.MAA_IDE_APP_DIR)
    : path.join(repo, 'packages', 'ide-web', 'dist');
export const artifacts = path.join(repo, 'e2e', 'artifacts');

export const CHROMIUM_FLAGS = [
    '--headless',
    '--no-sandbox',
    '--disable-gpu',
    '--disable-quic',
    '--no-first-run',
    '--disable-background-networking',
    '--disable-component-update',
    '--disable-sync',
];

/**
 * A temp folder with a fresh copy of examples/ (or of `from`) as the workspace. The lab's
 * exercises (examples/lab/, served by the lab server) are left out: the scenarios work on the
 * toast example, whose application is then the only one in the pickers.
 */
export function freshWorkspace(from = path.join(repo, 'examples')) {
    const base = mkdtempSync(path.join(os.tmpdir(), 'maa-e2e-'));
    const workspace = path.join(base, 'workspace');
    const lab = path.join(repo, 'examples', 'lab');
    cpSync(from, workspace, { recursive: true, filter: (src) => src !== lab });
    return { base, workspace, dispose: () => rmSync(base, { recursive: true, force: true }) };
}

/** A model root of `components` generated component types in `root` (the CLI benchmark's
 *  generator), plus `robot/System.arc` with every type as a subcomponent once. */
export function writeLargeModel(root, components) {
    const gen = generateModels(root, components);
    writeFileSync(path.join(root, 'maa.json'), '{}\n');
    const types = writeSystemComponent(root, gen);
    return { gen, types };
}

/**
 * Starts maa-ide on a free port; resolves once it prints its URL (`http://127.0.0.1:<port>/?token=...`)
 * with `url` (the address without the token, for scenarios to navigate below), `tokenUrl` and
 * `login(page)`, which opens the token URL so the browser keeps the token in maa-ide's cookie.
 */
export async function startIde(workspace, { log = false } = {}) {
    const bin = path.join(repo, 'packages', 'ide-server', 'bin', 'maa-ide.js');
    if (!existsSync(path.join(appDir, 'index.html'))) {
        throw new Error(`${appDir} has no built app: run "npm run build -w @maa/ide-web" first`);
    }
    const child = spawn(process.execPath, [bin, '--workspace', workspace, '--port', '0', '--app-dir', appDir], {
        cwd: repo,
        stdio: ['ignore', 'pipe', 'pipe'],
    });
    const output = [];
    const printed = await new Promise((resolve, reject) => {
        const timer = setTimeout(() => reject(new Error(`maa-ide did not print its URL within 60 s:\n${output.join('')}`)), 60_000);
        const onData = (chunk) => {
            const text = chunk.toString();
            output.push(text);
            if (log) process.stderr.write(`[maa-ide] ${text}`);
            const match = /serving .* at (http:\/\/\S+)/.exec(output.join(''));
            if (match) {
                clearTimeout(timer);
                resolve(new URL(match[1]));
            }
        };
        child.stdout.on('data', onData);
        child.stderr.on('data', onData);
        child.on('exit', (code) => {
            clearTimeout(timer);
            reject(new Error(`maa-ide exited (${code}):\n${output.join('')}`));
        });
    });
    child.stdout.on('data', (c) => output.push(c.toString()));
    child.stderr.on('data', (c) => output.push(c.toString()));
    const token = printed.searchParams.get('token');
    if (!token) throw new Error(`maa-ide printed a URL without its token: ${printed}`);
    const tokenUrl = printed.toString();
    return {
        url: `${printed.origin}/`,
        tokenUrl,
        token,
        output,
        /** Opens the token URL: maa-ide sets its cookie and redirects to the app. */
        async login(page) {
            const response = await page.goto(tokenUrl);
            if (!response?.ok() || new URL(page.url()).searchParams.has('token')) {
                throw new Error(`opening ${tokenUrl} did not lead to the app (${response?.status()} at ${page.url()})`);
            }
        },
        async stop() {
            if (child.exitCode !== null) return;
            const exited = new Promise((resolve) => child.once('exit', resolve));
            child.kill('SIGTERM');
            const timer = setTimeout(() => child.kill('SIGKILL'), 5000);
            await exited;
            clearTimeout(timer);
        },
    };
}

/** Launches chromium with a fresh profile; returns { context, page, close }. */
export async function launchBrowser({ width = 1600, height = 1000 } = {}) {
    const executablePath = ensureChromium();
    const userDataDir = mkdtempSync(path.join(os.tmpdir(), 'maa-chromium-'));
    const context = await chromium.launchPersistentContext(userDataDir, {
        executablePath,
        headless: true,
        args: CHROMIUM_FLAGS,
        viewport: { width, height },
    });
    const page = context.pages()[0] ?? (await context.newPage());
    const consoleLines = [];
    page.on('console', (m) => consoleLines.push(`${m.type()}: ${m.text()}`));
    page.on('pageerror', (e) => consoleLines.push(`pageerror: ${e.message}`));
    return {
        context,
        page,
        consoleLines,
        async close() {
            await context.close().catch(() => undefined);
            rmSync(userDataDir, { recursive: true, force: true });
        },
    };
}

export async function screenshot(page, name) {
    mkdirSync(artifacts, { recursive: true });
    const file = path.join(artifacts, `${name}.png`);
    await page.screenshot({ path: file });
    return file;
}

/**
 * The steps of a page script (lab-dashboard.mjs, lab-ide.mjs): `step(name, run)` runs one, prints
 * ✓ or ✗ with its time or error, records it in `results` and rethrows a failure (the later steps
 * build on it).
 */
export function stepRunner(results) {
    return async (name, run) => {
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
}

/** Waits until `check()` holds, polling every 250 ms; fails with `what` after `ms`. */
export async function until(page, what, check, ms = 30_000) {
    const started = Date.now();
    while (!(await check())) {
        if (Date.now() - started > ms) await fail(what);
        await page.waitForTimeout(250);
    }
}

/**
 * The set-up the simulate scenarios share (the IDE runs at `url`, run.mjs): the example's robot
 * opens (with `diagram`, also its diagram), MontiArc: Start Simulation picks TR.arcapp on
 * timesync (lock-step), and once the simulate view runs it (the 3D view and Pause shown) this
 * resolves with `{ view, diagram }` (the frames of the simulate view and of the diagram). A start
 * that fails fails with the view's error.
 */
export async function startLockstepRun(page, url, { diagram: withDiagram = false, timeout = 240_000 } = {}) {
    await openHost(page, url, ROBOT);
    let diagram;
    if (withDiagram) {
        await runCommand(page, 'MontiArc: Open Diagram');
        diagram = await frameWith(page, '[data-testid=diagram] .maa-component', 'the diagram of ToastServiceRobot', 90_000);
    }
    await runCommand(page, 'MontiArc: Start Simulation');
    const row = page
        .locator('.quick-input-list .monaco-list-row', { hasText: 'toast-service/TR.arcapp' })
        .filter({ hasText: 'timesync' })
        .first();
    await row.waitFor({ timeout: 30_000 });
    await row.click();
    const view = await frameWith(page, '[data-testid=simulate-panel]', 'the simulate panel', 60_000);
    const error = view.locator('[data-testid=sim-error]');
    // generation and the simulator take a while on a busy machine
    await until(
        page,
        `the run did not start within ${timeout / 1000} s`,
        async () => {
            if (await error.isVisible()) await fail(`the run did not start: ${((await error.textContent()) ?? '').slice(0, 600)}`);
            return (await view.locator('[data-testid=viser-frame]').isVisible()) && view.locator('[data-testid=sim-pause]').isVisible();
        },
        timeout,
    );
    return { view, diagram };
}
