#!/usr/bin/env node
// The pack-and-install test (issue 16; docs/testing.md, docs/releasing.md): packs every public
// workspace package with `npm pack`, installs the tarballs into an empty folder outside the
// repository (third-party packages from the registry, through the local npm cache), and there
// uses the tools as a user would: `npx maa-gen --version`, `new toast-service demo`, `check`, `lsp`,
// `generate` for both platforms, `test`, `diagram`, `sim` for the timesync platform until the
// goal, and `npx maa-ide` serving the project (the printed URL fetched with the token).
//
// Every step asserts its exit code and output; a step whose command this maa-gen lacks is
// skipped with the reason printed. Results (one per step: name, ok, skipped, reason, error, ms)
// go to --results FILE for scripts/test-all.mjs; the exit code is 0 exactly when no step failed.
// Tarball sizes and the install time are printed (and kept in the results as `facts`).
//
// Usage: node scripts/pack-install.mjs [--results FILE] [--keep]   (--keep leaves the folder)
// The packages must be built (npm test builds them first).
import { spawn } from 'node:child_process';
import { existsSync, mkdirSync, mkdtempSync, readdirSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { packPackages, publicPackages, readWorkspace } from './release/packages.mjs';
import { missingPackedTargets } from './release/packed-targets.mjs';

const repo = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..');
const npm = process.platform === 'win32' ? 'npm.cmd' : 'npm';
const npx = process.platform === 'win32' ? 'npx.cmd' : 'npx';

const argv = process.argv.slice(2);
const resultsFile = argv.includes('--results') ? path.resolve(argv[argv.indexOf('--results') + 1]) : undefined;
const keep = argv.includes('--keep');

const results = [];
const facts = {};
/** Set when a step the later ones need failed: they are reported as failed, not run. */
let blockedBy;

/** Runs one step: `body` throws to fail, returns `{ skip: reason }` to skip. */
async function step(name, body) {
    const started = Date.now();
    if (blockedBy) {
        results.push({ name, ok: false, error: `not run: '${blockedBy}' failed`, ms: 0 });
        console.log(`pack-install: FAIL ${name} (not run: '${blockedBy}' failed)`);
        return;
    }
    try {
        const outcome = await body();
        const ms = Date.now() - started;
        if (outcome?.skip) {
            results.push({ name, ok: true, skipped: true, reason: outcome.skip, ms });
            console.log(`pack-install: SKIP ${name}: ${outcome.skip}`);
        } else {
            results.push({ name, ok: true, ms });
            console.log(`pack-install: ok   ${name} (${(ms / 1000).toFixed(1)} s)`);
        }
    } catch (error) {
        results.push({ name, ok: false, error: error.message, ms: Date.now() - started });
        console.log(`pack-install: FAIL ${name}: ${error.message}`);
        return error;
    }
    return undefined;
}

/** Runs a command to its end; resolves `{ code, stdout, stderr }` (never rejects on a non-zero exit). */
function exec(command, args, cwd, env = {}) {
    return new Promise((resolve, reject) => {
        const child = spawn(command, args, { cwd, env: { ...process.env, npm_config_loglevel: 'error', ...env } });
        let stdout = '';
        let stderr = '';
        child.stdout.on('data', (d) => {
            stdout += d;
        });
        child.stderr.on('data', (d) => {
            stderr += d;
        });
        child.on('error', reject);
        child.on('close', (code, signal) => resolve({ code: code ?? signal, stdout, stderr }));
    });
}

/** `npx --no-install <bin> ...args` in `cwd` (the installed bin, never one fetched on the fly). */
async function npxRun(cwd, bin, args, env) {
    return exec(npx, ['--no-install', bin, ...args], cwd, env);
}

/** Fails unless `run` exited with `code`, quoting its output. */
function expectExit(run, code, what) {
    if (run.code !== code) {
        const tail = `${run.stdout}\n${run.stderr}`.trim().split('\n').slice(-12).join('\n');
        throw new Error(`${what} exited with ${run.code}, expected ${code}:\n${tail}`);
    }
}

function expect(condition, message) {
    if (!condition) throw new Error(message);
}

/** The sub-commands `maa-gen --help` lists. */
async function maaGenCommands(project) {
    const help = await npxRun(project, 'maa-gen', ['--help']);
    expectExit(help, 0, 'maa-gen --help');
    const section = help.stdout.split(/^Commands:$/m)[1] ?? '';
    return new Set([...section.matchAll(/^ {2}(\w[\w-]*)/gm)].map((m) => m[1]));
}

/** Every file below `dir`, relative, '/'-separated. */
function filesBelow(dir) {
    const out = [];
    const visit = (rel) => {
        for (const e of readdirSync(path.join(dir, rel), { withFileTypes: true })) {
            const child = rel ? `${rel}/${e.name}` : e.name;
            if (e.isDirectory()) visit(child);
            else out.push(child);
        }
    };
    visit('');
    return out;
}

/** Copies a folder (the fallback for a maa-gen without `new`). */
function copyDir(from, to) {
    for (const rel of filesBelow(from)) {
        if (rel.split('/').some((part) => part.startsWith('.') || part === 'generated' || part === '__pycache__')) continue;
        mkdirSync(path.dirname(path.join(to, rel)), { recursive: true });
        writeFileSync(path.join(to, rel), readFileSync(path.join(from, rel)));
    }
}

/**
 * Starts `npx maa-gen lsp --stdio` in `cwd`, sends LSP's initialize request and resolves with the
 * server's answer (its capabilities), then stops it (its whole process group).
 */
async function initializeLanguageServer(cwd) {
    const child = spawn(npx, ['--no-install', 'maa-gen', 'lsp', '--stdio'], {
        cwd,
        detached: true,
        env: { ...process.env, npm_config_loglevel: 'error' },
    });
    const exited = new Promise((resolve) => child.on('close', (code, signal) => resolve(code ?? signal)));
    let received = Buffer.alloc(0);
    let stderr = '';
    child.stderr.on('data', (d) => {
        stderr += d;
    });
    try {
        const answer = new Promise((resolve, reject) => {
            child.stdout.on('data', (d) => {
                received = Buffer.concat([received, d]);
                // one message: "Content-Length: N\r\n\r\n" and N bytes of JSON (others, e.g. log notifications, skipped)
                for (;;) {
                    const header = /^Content-Length: (\d+)\r\n\r\n/.exec(received.toString('latin1', 0, Math.min(received.length, 64)));
                    if (!header || received.length < header[0].length + Number(header[1])) return;
                    const body = received.subarray(header[0].length, header[0].length + Number(header[1]));
                    received = received.subarray(header[0].length + Number(header[1]));
                    const message = JSON.parse(body.toString('utf8'));
                    if (message.id === 1) resolve(message);
                }
            });
            exited.then((code) => reject(new Error(`maa-gen lsp exited with ${code} before answering:\n${stderr.trim()}`)));
        });
        const request = JSON.stringify({
            jsonrpc: '2.0',
            id: 1,
            method: 'initialize',
            params: { processId: null, rootUri: null, capabilities: {} },
        });
        child.stdin.write(`Content-Length: ${Buffer.byteLength(request)}\r\n\r\n${request}`);
        return await answer;
    } finally {
        try {
            process.kill(-child.pid, 'SIGTERM');
        } catch {
            // already gone
        }
        await exited;
    }
}

/**
 * Starts `npx maa-ide` serving `workspace` on a free port, waits for the URL it prints, fetches
 * the app and the workspace listing with the token, and stops it (its whole process group).
 */
async function serveIde(project, workspace) {
    const child = spawn(npx, ['--no-install', 'maa-ide', '--workspace', workspace, '--port', '0'], {
        cwd: project,
        detached: true,
        env: { ...process.env, npm_config_loglevel: 'error' },
    });
    const exited = new Promise((resolve) => child.on('close', (code, signal) => resolve(code ?? signal)));
    let output = '';
    try {
        const loginUrl = await new Promise((resolve, reject) => {
            const onData = (d) => {
                output += d;
                const m = /maa-ide: serving .* at (http:\/\/\S+\?token=\S+)/.exec(output);
                if (m) resolve(m[1]);
            };
            child.stdout.on('data', onData);
            child.stderr.on('data', onData);
            exited.then((code) => reject(new Error(`maa-ide exited with ${code} before serving:\n${output.trim()}`)));
        });
        const url = new URL(loginUrl);
        const token = url.searchParams.get('token');
        const headers = { authorization: `Bearer ${token}` };
        const page = await fetch(new URL('/', url), { headers });
        const html = await page.text();
        expect(page.status === 200 && /<script[^>]+src="[^"]*assets\//.test(html), `GET / gave ${page.status}, not the built app`);
        const anonymous = await fetch(new URL('/', url));
        expect(anonymous.status === 401 || anonymous.status === 403, `GET / without the token gave ${anonymous.status}`);
        const files = await fetch(new URL('/api/files', url), { headers });
        const listing = await files.text();
        expect(
            files.status === 200 && listing.includes('TR.arcapp'),
            `GET /api/files gave ${files.status} without TR.arcapp: ${listing.slice(0, 200)}`,
        );
    } finally {
        try {
            process.kill(-child.pid, 'SIGTERM');
        } catch {
            // already gone
        }
        await exited;
    }
}

/** Runs a step whose failure leaves the later steps nothing to work on (they are reported as not run). */
async function fatal(name, body) {
    if (await step(name, body)) blockedBy = name;
}

/** The folders of one run, in the system's temporary folder (never inside the repository). */
function createContext() {
    const root = mkdtempSync(path.join(tmpdir(), 'maa-pack-install-'));
    expect(path.relative(repo, root).startsWith('..'), `the install folder ${root} lies inside the repository`);
    const ctx = {
        root,
        tarballs: path.join(root, 'tarballs'),
        project: path.join(root, 'project'),
        demo: path.join(root, 'project', 'demo'),
        packages: publicPackages(readWorkspace(repo)),
        packed: [],
        commands: new Set(),
    };
    mkdirSync(ctx.tarballs);
    mkdirSync(ctx.project);
    return ctx;
}

async function packAndInstall(ctx) {
    await fatal('npm pack of every public package', async () => {
        ctx.packed = await packPackages(
            repo,
            ctx.packages.map((p) => p.json.name),
            ctx.tarballs,
        );
        const unpacked = ctx.packages.filter((p) => !ctx.packed.some((t) => t.name === p.json.name)).map((p) => p.json.name);
        expect(unpacked.length === 0, `not packed: ${unpacked.join(', ')}`);
        facts.tarballs = Object.fromEntries(ctx.packed.map((t) => [t.filename, t.size]));
    });
    await step('every file bin and exports name is in the tarball', async () => {
        const problems = ctx.packages.flatMap((p) => {
            const missing = missingPackedTargets(p.json, ctx.packed.find((t) => t.name === p.json.name).files);
            return missing.length > 0 ? [`${p.json.name}: ${missing.join(', ')}`] : [];
        });
        expect(problems.length === 0, `bin/exports name files the tarballs lack: ${problems.join('; ')}`);
    });
    await step('every tarball holds the LICENSE', async () => {
        const without = ctx.packed.filter((t) => !t.files.includes('LICENSE')).map((t) => t.name);
        expect(without.length === 0, `tarballs without LICENSE: ${without.join(', ')}`);
    });
    await fatal('npm install of the tarballs into an empty folder', async () => {
        writeFileSync(path.join(ctx.project, 'package.json'), `${JSON.stringify({ name: 'maa-install-test', private: true }, null, 2)}\n`);
        const started = Date.now();
        const files = ctx.packed.map((t) => path.join(ctx.tarballs, t.filename));
        const install = await exec(npm, ['install', '--no-audit', '--no-fund', '--prefer-offline', ...files], ctx.project);
        facts.installSeconds = (Date.now() - started) / 1000;
        expectExit(install, 0, 'npm install');
        // every @maa package must be a tarball of this run, never a namesake from the registry
        const lock = JSON.parse(readFileSync(path.join(ctx.project, 'package-lock.json'), 'utf8'));
        const fromRegistry = Object.entries(lock.packages)
            .filter(([where, p]) => /node_modules\/@maa\//.test(where) && !String(p.resolved).startsWith('file:'))
            .map(([where]) => where);
        expect(fromRegistry.length === 0, `@maa packages not from the tarballs: ${fromRegistry.join(', ')}`);
    });
}

async function createProject(ctx) {
    const { project, demo } = ctx;
    await fatal('npx maa-gen --version', async () => {
        const version = ctx.packages.find((p) => p.json.name === '@maa/cli')?.json.version;
        const run = await npxRun(project, 'maa-gen', ['--version']);
        expectExit(run, 0, 'maa-gen --version');
        expect(run.stdout.trim() === version, `maa-gen --version printed '${run.stdout.trim()}', not ${version}`);
        ctx.commands = await maaGenCommands(project);
    });
    await fatal('npx maa-gen new toast-service demo', async () => {
        if (!ctx.commands.has('new')) {
            copyDir(path.join(repo, 'examples', 'toast-service'), demo);
            return { skip: 'this maa-gen has no `new`; examples/toast-service copied instead' };
        }
        const run = await npxRun(project, 'maa-gen', ['new', 'toast-service', 'demo']);
        expectExit(run, 0, 'maa-gen new toast-service demo');
        expect(existsSync(path.join(demo, 'TR.arcapp')), 'demo/TR.arcapp was not created');
        const again = await npxRun(project, 'maa-gen', ['new', 'toast-service', 'demo']);
        expect(again.code !== 0, 'a second `maa-gen new` into demo/ did not refuse');
        return undefined;
    });
}

async function useMaaGen({ project, demo, commands }) {
    await step('npx maa-gen check .', async () => {
        const run = await npxRun(demo, 'maa-gen', ['check', '.']);
        expectExit(run, 0, 'maa-gen check .');
    });
    for (const [platform, marker] of [
        ['timesync', /(^|\/)maa_timesync\/runtime\.py$/],
        ['rospython', /(^|\/)package\.xml$/],
    ]) {
        await step(`npx maa-gen generate TR.arcapp --platform ${platform}`, async () => {
            const out = path.join(project, 'out', platform);
            const run = await npxRun(demo, 'maa-gen', ['generate', 'TR.arcapp', '--platform', platform, '--out', out]);
            expectExit(run, 0, `maa-gen generate --platform ${platform}`);
            const files = existsSync(out) ? filesBelow(out) : [];
            expect(
                files.some((f) => marker.test(f)),
                `no file matching ${marker} among the ${files.length} generated files`,
            );
        });
    }
    await step('npx maa-gen test TR.arcapp', async () => {
        const run = await npxRun(demo, 'maa-gen', ['test', 'TR.arcapp']);
        expectExit(run, 0, 'maa-gen test TR.arcapp');
        expect(
            /stream tests: [1-9]\d* passed, 0 failed/.test(`${run.stdout}\n${run.stderr}`),
            `maa-gen test did not report passed stream tests:\n${run.stderr.slice(-400)}`,
        );
    });
    await step('npx maa-gen check on a folder without models exits 2', async () => {
        const empty = path.join(project, 'empty');
        mkdirSync(empty, { recursive: true });
        const run = await npxRun(empty, 'maa-gen', ['check', '.']);
        expectExit(run, 2, 'maa-gen check . (no models)');
    });
    await step('npx maa-gen lsp --stdio answers initialize', async () => {
        if (!commands.has('lsp')) return { skip: 'this maa-gen has no `lsp`' };
        const answer = await initializeLanguageServer(demo);
        expect(answer.result?.capabilities?.textDocumentSync !== undefined, `no capabilities in ${JSON.stringify(answer).slice(0, 300)}`);
        return undefined;
    });
    await step('npx maa-gen diagram ToastServiceRobot', async () => {
        if (!commands.has('diagram')) return { skip: 'this maa-gen has no `diagram`' };
        const svg = path.join(project, 'ToastServiceRobot.svg');
        const run = await npxRun(demo, 'maa-gen', ['diagram', 'ToastServiceRobot', '--out', svg]);
        expectExit(run, 0, 'maa-gen diagram ToastServiceRobot');
        const text = existsSync(svg) ? readFileSync(svg, 'utf8') : '';
        expect(/<svg[\s>]/.test(text) && text.includes('ToastServiceRobot'), 'the diagram is not an SVG naming ToastServiceRobot');
        return undefined;
    });
}

async function useSimulatorAndIde({ project, demo, commands }) {
    await step('npx maa-sim --help (the first use installs the simulator into its cached venv)', async () => {
        // Through the launcher of @maa/sim-server, as maa-gen sim and maa-ide start it; the venv
        // lands in the user's cache (~/.cache/maa/sim-<hash>) and is reused while the sources stay the same.
        const run = await npxRun(project, 'maa-sim', ['--help'], { MAA_SIM: '' });
        expectExit(run, 0, 'maa-sim --help');
        expect(/usage: maa-sim/.test(run.stdout), `maa-sim --help printed no usage:\n${run.stdout.slice(0, 400)}`);
    });
    await step('npx maa-gen sim TR.arcapp --platform timesync --until-goal --record run.mcap', async () => {
        if (!commands.has('sim')) return { skip: 'this maa-gen has no `sim` yet' };
        const mcap = path.join(project, 'run.mcap');
        const args = ['sim', 'TR.arcapp', '--platform', 'timesync', '--until-goal', '--headless', '--record', mcap];
        const run = await npxRun(demo, 'maa-gen', args, { MAA_SIM: '' });
        expectExit(run, 0, 'maa-gen sim --until-goal');
        // the recorder runs in the installed simulator too: an MCAP file, by its magic bytes
        const magic = existsSync(mcap) ? readFileSync(mcap).subarray(0, 8) : Buffer.alloc(0);
        expect(magic.equals(Buffer.from([0x89, 0x4d, 0x43, 0x41, 0x50, 0x30, 0x0d, 0x0a])), 'maa-gen sim --record wrote no MCAP file');
        return undefined;
    });
    await step('npx maa-ide serving the project', () => serveIde(project, demo));
}

async function main() {
    const ctx = createContext();
    console.log(`pack-install: packing ${ctx.packages.length} public packages, installing them into ${ctx.project}`);
    await packAndInstall(ctx);
    await createProject(ctx);
    await useMaaGen(ctx);
    await useSimulatorAndIde(ctx);
    if (keep) console.log(`pack-install: kept ${ctx.root}`);
    else rmSync(ctx.root, { recursive: true, force: true });
}

function report() {
    if (facts.tarballs) {
        console.log('pack-install: tarball sizes');
        for (const [file, size] of Object.entries(facts.tarballs))
            console.log(`  ${file.padEnd(40)} ${(size / 1024).toFixed(0).padStart(6)} kB`);
    }
    if (facts.installSeconds !== undefined)
        console.log(`pack-install: npm install into an empty folder took ${facts.installSeconds.toFixed(1)} s`);
    const failed = results.filter((r) => !r.ok);
    const skipped = results.filter((r) => r.skipped);
    console.log(
        `pack-install: ${results.length - failed.length - skipped.length} passed, ${failed.length} failed, ${skipped.length} skipped`,
    );
    if (resultsFile) writeFileSync(resultsFile, `${JSON.stringify({ results, facts }, null, 2)}\n`);
    process.exit(failed.length === 0 ? 0 : 1);
}

main().then(report, (error) => {
    results.push({ name: 'pack-install', ok: false, error: error.message, ms: 0 });
    console.error(`pack-install: ${error.stack ?? error.message}`);
    report();
});
