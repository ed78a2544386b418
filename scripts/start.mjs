#!/usr/bin/env node
// `npm start`: the main job for now. Builds the workspace and checks the example models with
// `maa-gen check`. The browser IDE does not exist yet (a later issue); when it does, this
// script will serve it instead and print its address.
import { spawnSync } from 'node:child_process';
import { existsSync, readdirSync } from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';

const repo = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..');
const npm = process.platform === 'win32' ? 'npm.cmd' : 'npm';
const cli = path.join(repo, 'packages', 'cli', 'bin', 'maa-gen.js');

function run(command, args, shown = [command, ...args].join(' ')) {
  console.log(`\n$ ${shown}`);
  const result = spawnSync(command, args, { cwd: repo, stdio: 'inherit' });
  if (result.error) {
    console.error(`start: could not start ${command}: ${result.error.message}`);
    return 2;
  }
  return result.status ?? 2;
}

const buildStatus = run(npm, ['run', 'build']);
if (buildStatus !== 0) {
  console.error(`\nstart: the build failed (exit ${buildStatus})`);
  process.exit(buildStatus);
}

// Every folder directly under examples/ is one example project, i.e. one model root.
const examples = path.join(repo, 'examples');
const roots = existsSync(examples)
  ? readdirSync(examples, { withFileTypes: true })
      .filter((e) => e.isDirectory() && !e.name.startsWith('.'))
      .map((e) => path.join('examples', e.name))
  : [];

let status = 0;
if (roots.length > 0) {
  status = run(process.execPath, [cli, 'check', ...roots], `maa-gen check ${roots.join(' ')}`);
} else {
  console.log('\nstart: there is no example project under examples/ yet, so there is nothing to check.');
}

console.log(`
What runs today: the maa-gen CLI (${roots.length > 0 ? 'its result is above' : 'no examples to check yet'}).
  Check your own models:  node packages/cli/bin/maa-gen.js check <model-folder>...   (or: npx maa-gen check ...)
  Usage:                  node packages/cli/bin/maa-gen.js --help   (docs/cli.md)
The browser IDE is not built yet (it is a later issue). Once it exists, "npm start" will
serve it and print its local address here.`);
process.exit(status);
