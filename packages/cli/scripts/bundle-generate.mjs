#!/usr/bin/env node
// Build step of @maa/cli (after tsc): bundles the generation path of `maa-gen generate` (the
// language family's services, @maa/generator-core/node and Langium) with esbuild, like
// bundle-check.mjs does for `maa-gen check`: importing it takes ~0.2 s instead of ~1.1 s for the
// unbundled packages (issue 18 goal 3, `npm run bench:generate`).
//
// Generators are loaded at run time and import @maa/generator-core, the language packages and
// Langium themselves. A single-file bundle would give them a second copy of those modules (other
// classes for `instanceof`, another feature configuration of @maa/language-adl). So this bundle
// has one entry module per package a generator may import (code splitting: the code they share
// lies in chunks, once), and maa-gen redirects a generator's import of such a package to its
// entry here (src/generate-loader.ts, src/generate-hooks.ts): bundle and generators share one
// module graph. dist/generate-bundle/modules.json lists the entries; inputs.json the workspace
// modules inside (a bundle older than one of them is not used).
import { mkdirSync, rmSync, writeFileSync } from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { esbuildOrSkip, NODE_ESM, workspaceInputs } from './bundle-common.mjs';

const packageDir = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..');
const outdir = path.join(packageDir, 'dist', 'generate-bundle');

/** The packages (export paths) a generator may import at run time, each an entry of the bundle. */
const SHARED = [
    '@maa/generator-core',
    '@maa/generator-core/node',
    '@maa/generator-core/naming',
    '@maa/language-adl',
    '@maa/language-automata',
    '@maa/language-cd',
    '@maa/language-robotarm',
    '@maa/protocol',
    '@maa/protocol/formats',
    'langium',
    'langium/node',
];

/** What maa-gen itself imports besides the shared packages: the family's services (not the whole language server). */
const FAMILY = fileURLToPath(new URL('family.js', import.meta.resolve('@maa/language-server')));

const build = await esbuildOrSkip('bundle-generate', 'maa-gen generate will load the packages unbundled');

/** `@maa/generator-core/node` -> `maa-generator-core--node` (a file name). */
const entryName = (specifier) => specifier.replace(/^@/, '').replace(/\//, '-').replace(/\//g, '--');

rmSync(outdir, { recursive: true, force: true });
mkdirSync(outdir, { recursive: true });
const entries = SHARED.map((specifier) => ({ specifier, in: fileURLToPath(import.meta.resolve(specifier)), out: entryName(specifier) }));
const result = await build({
    entryPoints: [...entries.map((e) => ({ in: e.in, out: e.out })), { in: FAMILY, out: 'family' }],
    ...NODE_ESM,
    splitting: true,
    outdir,
    chunkNames: 'chunk-[hash]',
    absWorkingDir: packageDir,
});

const modules = Object.fromEntries(entries.map((e) => [e.specifier, `${e.out}.js`]));
writeFileSync(path.join(outdir, 'modules.json'), `${JSON.stringify({ family: 'family.js', modules }, null, 1)}\n`);
// The workspace modules inside the bundle (not those of node_modules), relative to the bundle's
// folder, so the loader can tell a bundle older than a rebuild of one of them.
const inputs = workspaceInputs(result.metafile, packageDir, outdir);
writeFileSync(path.join(outdir, 'inputs.json'), `${JSON.stringify({ inputs }, null, 1)}\n`);
const outputs = Object.keys(result.metafile.outputs).filter((o) => o.endsWith('.js'));
console.log(
    `bundle-generate: ${path.relative(packageDir, outdir)} (${Object.keys(result.metafile.inputs).length} modules in ${outputs.length} files)`,
);
