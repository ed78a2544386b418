#!/usr/bin/env node
// `npm start`: the main job. Builds the packages whose inputs changed since their last build
// (scripts/build-if-stale.mjs; a second start with nothing changed builds nothing), sets up the
// simulator's Python environment when its requirements changed (sim-server/scripts/setup_env.sh
// returns at once otherwise), prepares the workspace (a copy of examples/ in .maa-workspace/,
// created once and then kept, so your edits survive restarts) and starts the IDE backend
// `maa-ide`, which prints the address to open: it holds a secret token made at each start
// (docs/ide.md "Access"; MAA_IDE_TOKEN in the environment fixes it). Each phase prints one
// progress line with its time ("[2/13] built @maa/language-adl in 12.3 s").
//
//   npm start                              http://127.0.0.1:3000/?token=...
//   npm start -- --port 4000 --host 0.0.0.0
//   npm start -- --workspace ~/my-models   (any folder; not copied)
//   npm start -- --reset-workspace         (a fresh copy of examples/)
import { spawn } from 'node:child_process';
import { cpSync, existsSync, rmSync } from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { buildStale, readWorkspaces } from './build-if-stale.mjs';

const repo = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..');
const args = process.argv.slice(2);

const HELP = `Usage: npm start [-- options]

Builds what changed since the last start, sets up the simulator (sim-server/.venv) when its
requirements changed, and serves the browser IDE. Stop it with Ctrl-C.
Options:
  --workspace DIR     the folder to edit (default: .maa-workspace, a copy of examples/)
  --reset-workspace   replace .maa-workspace with a fresh copy of examples/
  --port N            HTTP port (default 3000; 0 = any free port)
  --host H            address to serve on (default 127.0.0.1; 0.0.0.0 serves every interface)
  --session-idle S    a simulation ends S seconds after its last client left (default 60)
  --skip-build        start without building (after a build of your own)
  --rebuild           build every package, even those that are up to date
  --verbose           show the output of every build and of the simulator setup
Open the URL maa-ide prints (it holds ?token=...; MAA_IDE_TOKEN=<token> fixes the token).`;

if (args.includes('--help') || args.includes('-h')) {
    console.log(HELP);
    process.exit(0);
}

function option(name) {
    const i = args.indexOf(name);
    return i >= 0 ? args[i + 1] : undefined;
}

function fail(message, code = 2) {
    console.error(`start: ${message}`);
    process.exit(code);
}

function seconds(since) {
    return `${((Date.now() - since) / 1000).toFixed(1)} s`;
}

/** Runs a command; resolves `{ code, output }` (output: what it printed, unless `verbose` streamed it). */
function runCaptured(command, commandArgs, verbose) {
    return new Promise((resolve) => {
        const child = spawn(command, commandArgs, { cwd: repo, stdio: verbose ? 'inherit' : ['ignore', 'pipe', 'pipe'] });
        const chunks = [];
        child.stdout?.on('data', (c) => chunks.push(c));
        child.stderr?.on('data', (c) => chunks.push(c));
        child.on('error', (e) => resolve({ code: 2, output: `could not start ${command}: ${e.message}\n` }));
        child.on('close', (code, signal) => resolve({ code: code ?? (signal ? 128 : 2), output: Buffer.concat(chunks).toString() }));
    });
}

/** The packages whose inputs changed are built; a failed build ends the start with its output shown. */
async function buildPhase(total, verbose) {
    const started = Date.now();
    const result = await buildStale(repo, { force: args.includes('--rebuild'), verbose, first: 1, total });
    if (!result.ok) fail(`building ${result.failed} failed; fix it and start again`, 1);
    const skipped = result.skipped.length > 0 ? `, ${result.skipped.length} up to date` : '';
    console.log(`      build: ${result.built.length} built${skipped} (${seconds(started)})`);
}

/** sim-server/.venv: created or updated by its setup script, which returns at once when its requirements are unchanged. */
async function simulatorPhase(phase, verbose) {
    const started = Date.now();
    process.stdout.write(`${phase} simulator environment sim-server/.venv (a first setup downloads for minutes) ...${verbose ? '\n' : ''}`);
    const { code, output } = await runCaptured('bash', [path.join(repo, 'sim-server', 'scripts', 'setup_env.sh')], verbose);
    const end = verbose ? `${phase} simulator environment:` : '';
    if (code !== 0) {
        console.log(`${end} failed (exit ${code}) after ${seconds(started)}`);
        if (output) process.stderr.write(output);
        fail('the simulator setup failed', code);
    }
    console.log(`${end} ${/is up to date/.test(output) ? 'up to date' : 'set up'}, ${seconds(started)}`);
}

/** The folder the IDE edits: --workspace, or .maa-workspace (a copy of examples/ but examples/lab/, made once). */
function prepareWorkspace() {
    const chosen = option('--workspace');
    if (chosen) {
        const workspace = path.resolve(chosen);
        if (!existsSync(workspace)) fail(`the workspace folder ${workspace} does not exist`);
        return workspace;
    }
    const workspace = path.join(repo, '.maa-workspace');
    if (args.includes('--reset-workspace')) rmSync(workspace, { recursive: true, force: true });
    if (!existsSync(workspace)) {
        // the lab's exercises (examples/lab/, with their reference solutions) belong to the lab server
        const lab = path.join(repo, 'examples', 'lab');
        cpSync(path.join(repo, 'examples'), workspace, { recursive: true, filter: (src) => src !== lab });
        console.log(`      created the workspace ${workspace} (a copy of examples/ without the lab's exercises)`);
    }
    return workspace;
}

function startIde(phase, workspace) {
    const ideArgs = [
        path.join(repo, 'packages', 'ide-server', 'bin', 'maa-ide.js'),
        '--workspace',
        workspace,
        '--port',
        option('--port') ?? process.env.PORT ?? '3000',
        '--host',
        option('--host') ?? '127.0.0.1',
        ...(option('--session-idle') ? ['--session-idle', option('--session-idle')] : []),
    ];
    console.log(`${phase} IDE: node ${ideArgs.join(' ')}`);
    const ide = spawn(process.execPath, ideArgs, { cwd: repo, stdio: 'inherit' });
    // maa-ide stops its simulation sessions on SIGINT/SIGTERM; pass ours on and exit with it.
    for (const signal of ['SIGINT', 'SIGTERM']) process.on(signal, () => ide.kill(signal));
    ide.on('exit', (code, signal) => process.exit(code ?? (signal ? 0 : 1)));
}

if (!existsSync(path.join(repo, 'node_modules'))) fail('node_modules is missing; run "npm ci" first');
const verbose = args.includes('--verbose');
const builds = args.includes('--skip-build') ? 0 : readWorkspaces(repo).filter((w) => w.build).length;
const total = builds + 2;
if (builds > 0) await buildPhase(total, verbose);
await simulatorPhase(`[${builds + 1}/${total}]`, verbose);
startIde(`[${total}/${total}]`, prepareWorkspace());
