import { execFile } from 'node:child_process';
import { readdirSync, writeFileSync } from 'node:fs';
import { readFile, stat, writeFile } from 'node:fs/promises';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { promisify } from 'node:util';
import { brotliCompress, constants, gzip } from 'node:zlib';
import importMetaUrlPlugin from '@codingame/esbuild-import-meta-url-plugin';
import { defineConfig, type Plugin } from 'vite';

const here = path.dirname(fileURLToPath(import.meta.url));

/** Every file below `dir`, relative and `/`-separated. */
function listFiles(dir: string, prefix = ''): string[] {
    return readdirSync(dir, { withFileTypes: true }).flatMap((e) =>
        e.isDirectory() ? listFiles(path.join(dir, e.name), `${prefix}${e.name}/`) : [`${prefix}${e.name}`],
    );
}

/**
 * The IDE (index.html, src/host/) loads the MontiArc extension's web build from
 * `dist/maa-extension/`: built here by the extension's own build (`--web`) after the bundle, with
 * `files.json` listing its files for the host to register.
 */
function maaExtension(): Plugin {
    return {
        name: 'maa-extension',
        apply: 'build',
        async closeBundle() {
            const out = path.join(here, 'dist', 'maa-extension');
            const build = path.resolve(here, '..', 'vscode-extension', 'bin', 'build.mjs');
            await new Promise<void>((resolve, reject) =>
                execFile(process.execPath, [build, '--web', '--out', out], (error, _stdout, stderr) =>
                    error ? reject(new Error(`building the MontiArc web extension failed: ${stderr || error.message}`)) : resolve(),
                ),
            );
            writeFileSync(path.join(out, 'files.json'), `${JSON.stringify(listFiles(out), null, 1)}\n`);
            await precompress(path.join(here, 'dist'));
        },
    };
}

/** The text files maa-ide serves compressed (packages/ide-server/src/compression.ts, same list and threshold). */
const COMPRESSIBLE = /\.(html|m?js|cjs|css|json|map|svg|wasm|txt|xml|ttf|otf)$/i;

/**
 * Writes `<file>.br` (brotli, quality 9: within a few per cent of 11 in a fraction of its time) and
 * `<file>.gz` (gzip 9; what chromium asks for over plain http) beside every text file of the
 * build of at least 1 KiB: maa-ide serves these instead of compressing at request time.
 */
async function precompress(dist: string): Promise<void> {
    const brotli = promisify(brotliCompress);
    const gz = promisify(gzip);
    const files = listFiles(dist).filter((f) => COMPRESSIBLE.test(f));
    await Promise.all(
        files.map(async (f) => {
            const file = path.join(dist, f);
            if ((await stat(file)).size < 1024) return;
            const raw = await readFile(file);
            const params = { [constants.BROTLI_PARAM_QUALITY]: 9, [constants.BROTLI_PARAM_SIZE_HINT]: raw.length };
            await writeFile(`${file}.br`, await brotli(raw, { params }));
            await writeFile(`${file}.gz`, await gz(raw, { level: 9 }));
        }),
    );
}

export default defineConfig({
    base: './',
    plugins: [maaExtension()],
    resolve: {
        dedupe: ['vscode', '@codingame/monaco-vscode-api'],
    },
    optimizeDeps: {
        // monaco-vscode-api resolves its workers and assets with `new URL(..., import.meta.url)`.
        esbuildOptions: { plugins: [importMetaUrlPlugin] },
    },
    worker: { format: 'es' },
    build: {
        target: 'es2022',
        outDir: 'dist',
        emptyOutDir: true,
        chunkSizeWarningLimit: 12000,
        reportCompressedSize: false,
        // The IDE: the workbench host of the VS Code extension (index.html, docs/ide.md).
        rollupOptions: { input: { main: path.join(here, 'index.html') } },
    },
});
