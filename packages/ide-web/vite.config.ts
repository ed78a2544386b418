import importMetaUrlPlugin from '@codingame/esbuild-import-meta-url-plugin';
import { defineConfig } from 'vite';

export default defineConfig({
    base: './',
    resolve: {
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
