#!/usr/bin/env node
// `npm start`: the main job. Builds every package (the browser app included), sets up the
// simulator's Python environment, prepares the workspace (a copy of examples/ in
// .maa-workspace/, created once and then kept, so your edits survive restarts) and starts the
// IDE backend `maa-ide`, which prints the address to open: it holds a secret token made at each
// start (docs/ide.md "Access"; MAA_IDE_TOKEN in the environment fixes it).
//
//   npm start                              http://127.0.0.1:3000/?token=...
//   npm start -- --port 4000 --host 0.0.0.0
//   npm start -- --workspace ~/my-models   (any folder; not copied)
//   npm start -- --reset-workspace         (a fresh copy of examples/)
import { spawn, spawnSync } from 'node:child_process';
import { cpSync, existsSync, rmSync } from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';

const repo = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..');
const npm = process.platform === 'win32' ? 'npm.cmd' : 'npm';
const args = process.argv.slice(2);

if (args.includes('--help') || args.includes('-h')) {
    console.log(`Usage: npm start [-- options]

Builds the workbench, sets up the simulator (sim-server/.venv) and serves the browser IDE.
Options:
  --workspace DIR     the folder to edit (default: .maa-workspace, a copy of examples/)
  --reset-workspace   replace .maa-workspace with a fresh copy of examples/
  --port N            HTTP port (default 3000; 0 = any free port)
  --host H            address to serve on (default 127.0.0.1)
  --session-idle S    a simulation ends S seconds after its last client left (default 60)
  --skip-build        start without building (after a build of your own)
Open the URL maa-ide prints (it holds ?token=...; MAA_IDE_TOKEN=<token> fixes the token).`);
    process.exit(0);
}

function option(name) {
    const i = args.indexOf(name);
    return i >= 0 ? args[i + 1] : undefined;
}

function run(title, command, commandArgs) {
    console.log(`\n== ${title}: ${[command, ...commandArgs].join(' ')}`);
    const result = spawnSync(command, commandArgs, { cwd: repo, stdio: 'inherit' });
    if (result.error) {
        console.error(`start: could not start ${command}: ${result.error.message}`);
        process.exit(2);
    }
    if (result.status !== 0) {
        console.error(`\nstart: ${title} failed (exit ${result.status})`);
        process.exit(result.status ?? 2);
    }
}

if (!args.includes('--skip-build')) run('build', npm, ['run', 'build']);
run('simulator setup', 'bash', [path.join(repo, 'sim-server', 'scripts', 'setup_env.sh')]);

let workspace = option('--workspace');
if (workspace) {
    workspace = path.resolve(workspace);
    if (!existsSync(workspace)) {
        console.error(`start: the workspace folder ${workspace} does not exist`);
        process.exit(2);
    }
} else {
    workspace = path.join(repo, '.maa-workspace');
    if (args.includes('--reset-workspace')) rmSync(workspace, { recursive: true, force: true });
    if (!existsSync(workspace)) {
        cpSync(path.join(repo, 'examples'), workspace, { recursive: true });
        console.log(`\nstart: created the workspace ${workspace} (a copy of examples/)`);
    }
}

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
console.log(`\n== IDE: node ${ideArgs.join(' ')}`);
const ide = spawn(process.execPath, ideArgs, { cwd: repo, stdio: 'inherit' });
// maa-ide stops its simulation sessions on SIGINT/SIGTERM; pass ours on and exit with it.
for (const signal of ['SIGINT', 'SIGTERM']) process.on(signal, () => ide.kill(signal));
ide.on('exit', (code, signal) => process.exit(code ?? (signal ? 0 : 1)));
