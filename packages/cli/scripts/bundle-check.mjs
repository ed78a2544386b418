#!/usr/bin/env node
// Build step of @maa/cli (after tsc): bundles the checking path of `maa-gen check` (the
// language family's checkModelRoots and CheckInputError, with Langium, Chevrotain and every
// language package) into ONE module, dist/check-bundle.js, with esbuild. Node then loads one
// file instead of resolving, reading and compiling several hundred ES modules: importing the
// language services drops from ~650 ms to ~150 ms (issue 18, `npm run bench`).
//
// The bundle is an optimization only: `maa-gen check` falls back to `@maa/language-server` when
// it is missing or older than one of the workspace modules it holds (listed in
// dist/check-bundle.inputs.json; see src/check-loader.ts), so a rebuild of a language package
// without this one never runs stale checking code.
import { writeFileSync } from 'node:fs';
import { createRequire } from 'node:module';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { esbuildOrSkip, NODE_ESM, workspaceInputs } from './bundle-common.mjs';

const packageDir = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..');
const require = createRequire(path.join(packageDir, 'package.json'));
const serverDir = path.dirname(require.resolve('@maa/language-server/package.json'));
const outfile = path.join(packageDir, 'dist', 'check-bundle.js');

const build = await esbuildOrSkip('bundle-check', 'maa-gen check will load the language services unbundled');

const result = await build({
    stdin: {
        contents: [
            `export { checkModelRoots } from ${JSON.stringify(path.join(serverDir, 'dist', 'check.js'))};`,
            `export { CheckInputError } from '@maa/language-adl';`,
        ].join('\n'),
        resolveDir: serverDir,
        sourcefile: 'check-entry.js',
        loader: 'js',
    },
    ...NODE_ESM,
    outfile,
    absWorkingDir: packageDir,
});

// The workspace modules inside the bundle (not those of node_modules), relative to dist/, so the
// loader can tell a bundle older than a rebuild of one of them.
const inputs = workspaceInputs(result.metafile, packageDir, path.dirname(outfile), ['check-entry.js']);
writeFileSync(path.join(packageDir, 'dist', 'check-bundle.inputs.json'), `${JSON.stringify({ inputs }, null, 1)}\n`);
console.log(`bundle-check: ${path.relative(packageDir, outfile)} (${Object.keys(result.metafile.inputs).length} modules)`);
