import importMetaUrlPlugin from '@codingame/esbuild-import-meta-url-plugin';
import { existsSync, readFileSync } from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { defineConfig } from 'vite';

const here = path.dirname(fileURLToPath(import.meta.url));
const languageServer = path.resolve(here, '..', 'language-server');

/**
 * The worker imports `@maa/language-server/browser`. When the package does not export that
 * entry (yet), point it at the built module (or the source) of the browser entry directly.
 */
function languageServerBrowserAlias(): Record<string, string> {
    const pkg = JSON.parse(readFileSync(path.join(languageServer, 'package.json'), 'utf8')) as { exports?: Record<string, unknown> };
    if (pkg.exports && './browser' in pkg.exports) return {};
    const built = path.join(languageServer, 'dist', 'browser', 'main.js');
    return { '@maa/language-server/browser': existsSync(built) ? built : path.join(languageServer, 'src', 'browser', 'main.ts') };
}

export default defineConfig({
    base: './',
    resolve: {
        alias: languageServerBrowserAlias(),
        dedupe: ['vscode', '@codingame/monaco-vscode-api'],
    },
    optimizeDeps: {
        // monaco-vscode-api resolves its workers and assets with `new URL(..., import.meta.url)`.
        esbuildOptions: { plugins: [importMetaUrlPlugin] },
        include: ['vscode-languageclient/browser.js', 'vscode-languageserver-protocol', 'roslib'],
    },
    worker: { format: 'es' },
    build: {
        target: 'es2022',
        outDir: 'dist',
        emptyOutDir: true,
        chunkSizeWarningLimit: 12000,
        reportCompressedSize: false,
    },
    server: {
        proxy: {
            '/api': 'http://127.0.0.1:3000',
            '/sim': { target: 'http://127.0.0.1:3000', ws: true },
        },
    },
});
