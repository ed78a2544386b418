#!/usr/bin/env node
// `npm run lint`: the house rules as tools. Biome lints and checks the formatting of the
// TypeScript and JavaScript (biome.json says which files), ruff lints and checks the formatting of
// the Python (sim-server, the generators' run-time environments and their tests). Changes nothing;
// `npm run format` applies the formatters. Sets up a Python venv that is missing (idempotent
// scripts). Exits non-zero when any linter finds something, after running them all.
// Usage: node scripts/lint.mjs [--fix]   (--fix: apply safe fixes and the formatters)
import { spawnSync } from 'node:child_process';
import { existsSync } from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';

const repo = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..');
const args = process.argv.slice(2);
if (args.includes('--help') || args.includes('-h')) {
    console.log(
        'usage: node scripts/lint.mjs [--fix]\n  checks TypeScript/JavaScript with Biome and Python with ruff; --fix applies safe fixes and formats',
    );
    process.exit(0);
}
const unknown = args.filter((a) => a !== '--fix');
if (unknown.length > 0) {
    console.error(`lint: unknown argument ${unknown[0]} (see --help)`);
    process.exit(2);
}
const fix = args.includes('--fix');

/** The Python trees, each linted with its venv's ruff and its own configuration. */
const PYTHON_TREES = [
    { dir: 'sim-server', setup: 'sim-server/scripts/setup_env.sh', python: 'sim-server/.venv/bin/python', config: [], paths: ['.'] },
    {
        dir: 'packages/generators-python',
        setup: 'packages/generators-python/scripts/setup_venv.sh',
        python: 'packages/generators-python/.venv/bin/python',
        config: ['--config', 'ruff.toml'],
        paths: ['rte/maa_timesync', 'test/python'],
    },
    {
        // copied into every generated ROS 2 package, or checked as such (test/ros2/ruff-generated.toml:
        // 120 columns), so formatted to 120 columns
        dir: 'packages/generators-python',
        setup: 'packages/generators-python/scripts/setup_venv.sh',
        python: 'packages/generators-python/.venv/bin/python',
        config: ['--config', 'ruff.toml', '--line-length', '120'],
        paths: ['rte/maa_behavior', 'rte/maa_ros2', 'test/ros2'],
    },
];

const failures = [];

function run(title, command, commandArgs, cwd = repo) {
    console.log(`\n=== lint: ${title}`);
    const result = spawnSync(command, commandArgs, { cwd, stdio: 'inherit' });
    const status = result.error ? 1 : (result.status ?? 1);
    if (result.error) console.error(`lint: could not start ${command}: ${result.error.message}`);
    if (status !== 0) failures.push(title);
    return status;
}

const biome = path.join(repo, 'node_modules', '.bin', 'biome');
if (!existsSync(biome)) {
    console.error('lint: Biome is missing; run "npm ci" first');
    process.exit(1);
}
if (fix) run('biome (fix and format)', biome, ['check', '--write']);
else run('biome', biome, ['ci', '--reporter=default']);

for (const tree of PYTHON_TREES) {
    if (!existsSync(path.join(repo, tree.python))) {
        if (run(`${tree.dir} (${tree.paths.join(', ')}): venv setup`, 'bash', [path.join(repo, tree.setup)]) !== 0) continue;
    }
    const python = path.join(repo, tree.python);
    const cwd = path.join(repo, tree.dir);
    if (fix) {
        run(
            `${tree.dir} (${tree.paths.join(', ')}): ruff check --fix`,
            python,
            ['-m', 'ruff', 'check', '--no-cache', '--fix', ...tree.config, ...tree.paths],
            cwd,
        );
        run(
            `${tree.dir} (${tree.paths.join(', ')}): ruff format`,
            python,
            ['-m', 'ruff', 'format', '--no-cache', ...tree.config, ...tree.paths],
            cwd,
        );
    } else {
        run(
            `${tree.dir} (${tree.paths.join(', ')}): ruff check`,
            python,
            ['-m', 'ruff', 'check', '--no-cache', ...tree.config, ...tree.paths],
            cwd,
        );
        run(
            `${tree.dir} (${tree.paths.join(', ')}): ruff format --check`,
            python,
            ['-m', 'ruff', 'format', '--no-cache', '--check', ...tree.config, ...tree.paths],
            cwd,
        );
    }
}

if (failures.length > 0) {
    console.error(`\nlint: ${failures.length} failed: ${failures.join('; ')}`);
    process.exit(1);
}
console.log('\nlint: clean');
