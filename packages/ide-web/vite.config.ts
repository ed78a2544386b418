import { execFile } from 'node:child_process';
import { readdirSync, writeFileSync } from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
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
        },
    };
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
