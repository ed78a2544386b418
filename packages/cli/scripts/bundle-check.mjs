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

const packageDir = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..');
const require = createRequire(path.join(packageDir, 'package.json'));
const serverDir = path.dirname(require.resolve('@maa/language-server/package.json'));
const outfile = path.join(packageDir, 'dist', 'check-bundle.js');

let build;
try {
    ({ build } = await import('esbuild'));
} catch {
    // Without esbuild (a devDependency), maa-gen check loads @maa/language-server unbundled.
    console.warn('bundle-check: esbuild is not installed; maa-gen check will load the language services unbundled');
    process.exit(0);
}

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
    bundle: true,
    platform: 'node',
    format: 'esm',
    target: 'node20',
    outfile,
    absWorkingDir: packageDir,
    metafile: true,
    legalComments: 'none',
    logLevel: 'warning',
    // Some dependencies are CommonJS and call require(): give the ES module bundle one.
    banner: {
        js: "import { createRequire as __maaCreateRequire } from 'node:module';\nconst require = __maaCreateRequire(import.meta.url);",
    },
});

// The workspace modules inside the bundle (not those of node_modules), relative to dist/, so the
// loader can tell a bundle older than a rebuild of one of them.
const inputs = Object.keys(result.metafile.inputs)
    .filter((input) => input !== 'check-entry.js' && !input.split(/[\\/]/).includes('node_modules'))
    .map((input) => path.relative(path.dirname(outfile), path.resolve(packageDir, input)).split(path.sep).join('/'))
    .sort();
writeFileSync(path.join(packageDir, 'dist', 'check-bundle.inputs.json'), `${JSON.stringify({ inputs }, null, 1)}\n`);
console.log(`bundle-check: ${path.relative(packageDir, outfile)} (${Object.keys(result.metafile.inputs).length} modules)`);
