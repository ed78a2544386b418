#!/usr/bin/env node
// `npm run release -- <version|major|minor|patch> [--out DIR] [--no-build] [--dry-run]`
// (docs/releasing.md): sets every public package's version and every workspace range on them to
// the new version, refreshes package-lock.json, builds, regenerates the generator golden files
// (their traces name the generators' version), and packs the public packages into
// DIR (default release/<version>/) in dependency order, with a list of the tarballs (publish.txt)
// in the order `npm publish` must follow. It publishes nothing: that needs registry credentials.
import { spawnSync } from 'node:child_process';
import { mkdirSync, writeFileSync } from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { dependencyOrder, nextVersion, packPackages, planBump, publicPackages, readWorkspace, sharedVersion } from './packages.mjs';

const repo = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..', '..');
const npm = process.platform === 'win32' ? 'npm.cmd' : 'npm';

function parseArgs(argv) {
    const options = { spec: undefined, out: undefined, build: true, dryRun: false };
    for (let i = 0; i < argv.length; i++) {
        const a = argv[i];
        if (a === '--out') options.out = argv[++i];
        else if (a === '--no-build') options.build = false;
        else if (a === '--dry-run') options.dryRun = true;
        else if (a.startsWith('-') || options.spec !== undefined) throw new Error(`unexpected argument '${a}'`);
        else options.spec = a;
    }
    if (options.spec === undefined)
        throw new Error('usage: npm run release -- <version|major|minor|patch> [--out DIR] [--no-build] [--dry-run]');
    return options;
}

function run(command, args) {
    console.log(`release: ${[command, ...args].join(' ')}`);
    const result = spawnSync(command, args, { cwd: repo, stdio: 'inherit' });
    if (result.status !== 0) throw new Error(`${command} ${args.join(' ')} exited with ${result.status ?? result.signal}`);
}

async function main() {
    const options = parseArgs(process.argv.slice(2));
    const packages = readWorkspace(repo);
    const current = sharedVersion(packages);
    const version = nextVersion(current, options.spec);
    const changes = planBump(packages, version);
    console.log(`release: ${current} -> ${version}; package.json files that change: ${changes.map((c) => c.dir).join(', ')}`);
    if (options.dryRun) return;
    for (const change of changes) writeFileSync(path.join(repo, change.dir, 'package.json'), change.text);
    run(npm, ['install', '--package-lock-only', '--no-audit', '--no-fund']);
    run(process.execPath, [path.join(repo, 'scripts', 'complete-lockfile.mjs')]);
    if (options.build) run(npm, ['run', 'build']);
    // the golden traces name the generators' package version (the only change the bump makes there)
    run(npm, ['run', 'golden:update', '-w', '@maa/generators-python']);
    const out = path.resolve(options.out ?? path.join(repo, 'release', version));
    mkdirSync(out, { recursive: true });
    const order = dependencyOrder(publicPackages(readWorkspace(repo))).map((p) => p.json.name);
    const packed = await packPackages(repo, order, out);
    const byName = new Map(packed.map((p) => [p.name, p]));
    writeFileSync(path.join(out, 'publish.txt'), `${order.map((n) => byName.get(n).filename).join('\n')}\n`);
    for (const name of order) {
        const p = byName.get(name);
        console.log(`  ${p.filename.padEnd(40)} ${(p.size / 1024).toFixed(0).padStart(6)} kB packed, ${p.files.length} files`);
    }
    console.log(`release: ${order.length} tarballs in ${out}; publish them in the order of publish.txt (docs/releasing.md)`);
}

main().catch((error) => {
    console.error(`release: ${error.message}`);
    process.exit(1);
});
