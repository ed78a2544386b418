// Bundles the diagram webview's script (src/diagram/webview/main.ts: the shared @maa/diagram-view
// with Sprotty, inversify and their CSS) for the browser into out/webview/diagram.js (an IIFE,
// loaded by a nonce'd <script>) and out/webview/diagram.css (the stylesheets it imports). The
// webview may load nothing else: its localResourceRoots is out/webview (src/diagram/panel.ts).
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { build } from 'esbuild';

const pkgDir = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..');

export async function bundleDiagramWebview(outDir) {
    await build({
        entryPoints: [path.join(pkgDir, 'src', 'diagram', 'webview', 'main.ts')],
        outfile: path.join(outDir, 'out', 'webview', 'diagram.js'),
        bundle: true,
        platform: 'browser',
        format: 'iife',
        target: 'es2022',
        minify: true,
        sourcemap: false,
        legalComments: 'none',
        logLevel: 'warning',
        // The stylesheets' url() references (none today) would be inlined rather than loaded from elsewhere.
        loader: { '.svg': 'dataurl', '.png': 'dataurl', '.woff': 'dataurl', '.woff2': 'dataurl', '.ttf': 'dataurl' },
        define: { 'process.env.NODE_ENV': '"production"' },
    });
}
