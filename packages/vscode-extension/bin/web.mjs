// The web extension's bundles (the manifest's `browser` entry), used by bin/build.mjs and by the
// browser IDE's build (packages/ide-web/vite.config.ts), which serves the extension to the
// workbench of its host page:
//   out/web/extension.js  src/web/extension.ts, CommonJS (VS Code's web extension host evaluates it
//                         as a CommonJS module), `vscode` external, browser platform
//   out/web/server.js     the family's language server for a Web Worker (@maa/language-server/browser),
//                         one classic script (the extension starts it from a blob URL)
import { createRequire } from 'node:module';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { build } from 'esbuild';

const pkgDir = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..');
const require = createRequire(import.meta.url);

/** @param {string} outDir the extension folder (the bundles go to its out/web/) */
export async function bundleWeb(outDir, { minify = true } = {}) {
    const common = {
        bundle: true,
        platform: 'browser',
        target: 'es2022',
        sourcemap: false,
        minify,
        legalComments: 'none',
        logLevel: 'warning',
    };
    await Promise.all([
        build({
            ...common,
            entryPoints: [path.join(pkgDir, 'src', 'web', 'extension.ts')],
            outfile: path.join(outDir, 'out', 'web', 'extension.js'),
            format: 'cjs',
            external: ['vscode'],
        }),
        build({
            ...common,
            entryPoints: [require.resolve('@maa/language-server/browser')],
            outfile: path.join(outDir, 'out', 'web', 'server.js'),
            format: 'iife',
        }),
    ]);
}
