// Bundles the dashboard page's script (web/dashboard/main.ts) into dist/web/dashboard.js with
// esbuild (one file for the browser; the server serves it as /lab-assets/dashboard.js).
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { build } from 'esbuild';

const pkg = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..');
await build({
    entryPoints: [path.join(pkg, 'web/dashboard/main.ts')],
    outfile: path.join(pkg, 'dist/web/dashboard.js'),
    bundle: true,
    format: 'iife',
    platform: 'browser',
    target: 'es2022',
    sourcemap: true,
    legalComments: 'none',
    logLevel: 'warning',
});
