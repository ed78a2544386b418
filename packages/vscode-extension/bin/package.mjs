#!/usr/bin/env node
// Packs dist/extension/ (bin/build.mjs) into dist/maa-<version>.vsix with @vscode/vsce, offline:
// --no-dependencies (the bundles carry every dependency), no marketplace call, no prompts.
// Usage: node bin/package.mjs [--from DIR] [--out FILE]   (DIR: the built extension, default dist/extension)
import { spawn } from 'node:child_process';
import { readFileSync, statSync } from 'node:fs';
import { createRequire } from 'node:module';
import path from 'node:path';
import { fileURLToPath } from 'node:url';

const pkgDir = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..');
const fromArg = process.argv.indexOf('--from');
const extDir = path.resolve(fromArg > 0 ? process.argv[fromArg + 1] : path.join(pkgDir, 'dist', 'extension'));
const require = createRequire(import.meta.url);

const manifest = JSON.parse(readFileSync(path.join(extDir, 'package.json'), 'utf8'));
const outArg = process.argv.indexOf('--out');
const out = path.resolve(outArg > 0 ? process.argv[outArg + 1] : path.join(pkgDir, 'dist', `${manifest.name}-${manifest.version}.vsix`));
const vsce = path.join(path.dirname(require.resolve('@vscode/vsce/package.json')), 'vsce');

const args = [
    vsce,
    'package',
    '--no-dependencies',
    '--no-update-package-json',
    '--no-git-tag-version',
    '--allow-missing-repository',
    '--out',
    out,
];
const child = spawn(process.execPath, args, { cwd: extDir, stdio: ['ignore', 'inherit', 'inherit'] });
child.on('exit', (code) => {
    if (code !== 0) {
        console.error(`vscode-extension: vsce exited with ${code}`);
        process.exit(code ?? 1);
    }
    console.log(`vscode-extension: ${path.relative(process.cwd(), out)} (${(statSync(out).size / 1024).toFixed(0)} kB)`);
});
