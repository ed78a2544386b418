#!/usr/bin/env node
// Builds the extension into dist/extension/ (the folder `vsce package` packs, see bin/package.mjs;
// `--out DIR` builds it elsewhere, as the .vsix test does):
//   out/extension.cjs   the extension (CommonJS, `vscode` external), bundled by esbuild
//   out/server/main.mjs the family's language server (@maa/language-server's Node entry), one ESM file
//   package.json        the manifest: package.json's identity plus the contributions generated from
//                       the language facts (src/contributions.ts)
//   syntaxes/, language-configuration.json, snippets/, README.md (docs/vscode.md), LICENSE
import { copyFileSync, existsSync, mkdirSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { createRequire } from 'node:module';
import path from 'node:path';
import { fileURLToPath, pathToFileURL } from 'node:url';
import { build } from 'esbuild';
import { bundleDiagramWebview } from './diagram-webview.mjs';
import { bundleWeb } from './web.mjs';

const pkgDir = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..');
const repo = path.resolve(pkgDir, '..', '..');
const outArg = process.argv.indexOf('--out');
const outDir = path.resolve(outArg > 0 ? process.argv[outArg + 1] : path.join(pkgDir, 'dist', 'extension'));
const require = createRequire(import.meta.url);
// `--web`: the web extension only (manifest, out/web/, grammars, snippets), as the browser IDE serves it.
const webOnly = process.argv.includes('--web');

/** The manifest fields of the extension (the workspace package.json stays an npm manifest). */
const IDENTITY = {
    name: 'maa',
    displayName: 'MontiArcAutomaton',
    publisher: 'maa-web',
    license: 'MIT',
    categories: ['Programming Languages', 'Snippets'],
    engines: { vscode: '^1.82.0' },
    main: './out/extension.cjs',
    // The web extension (VS Code for the Web, the browser IDE's workbench): bin/web.mjs.
    browser: './out/web/extension.js',
};

/** The language server's Node entry; a clear message when @maa/language-server is not built yet. */
function serverEntry() {
    const entry = path.join(path.dirname(require.resolve('@maa/language-server/package.json')), 'dist', 'node', 'main.js');
    if (!existsSync(entry)) {
        console.error(`vscode-extension: ${path.relative(repo, entry)} is missing; build the language server first (npm run build)`);
        process.exit(1);
    }
    return entry;
}

/** The simulate view: the webview's panel (@maa/simulate-view, browser IIFE and its CSS) and maa-ide's launcher (src/simulate). */
async function bundleSimulate(common) {
    await bundleSimulateWebview(common);
    await build({
        ...common,
        entryPoints: [path.join(pkgDir, 'src', 'simulate', 'backend-launcher.ts')],
        outfile: path.join(outDir, 'out', 'simulate', 'backend-launcher.mjs'),
        format: 'esm',
        target: 'node20',
    });
}

/** The simulate view's panel alone (the web entry opens it too, src/simulate/web.ts). */
async function bundleSimulateWebview(common) {
    await build({
        ...common,
        entryPoints: [require.resolve('@maa/simulate-view/vscode-webview')],
        outfile: path.join(outDir, 'out', 'webview', 'simulate.js'),
        platform: 'browser',
        format: 'iife',
        target: 'es2022',
    });
}

async function bundle() {
    if (webOnly) {
        // The web entry also opens the diagram webview (src/diagram), so the browser IDE serves its bundle too.
        await bundleWeb(outDir);
        await bundleDiagramWebview(outDir);
        await bundleSimulateWebview({ bundle: true, sourcemap: false, minify: true, legalComments: 'none', logLevel: 'warning' });
        return;
    }
    const common = {
        bundle: true,
        platform: 'node',
        target: 'node18',
        sourcemap: false,
        minify: true,
        legalComments: 'none',
        logLevel: 'warning',
    };
    await build({
        ...common,
        entryPoints: [path.join(pkgDir, 'src', 'extension.ts')],
        outfile: path.join(outDir, 'out', 'extension.cjs'),
        format: 'cjs',
        external: ['vscode'],
    });
    await bundleSimulate(common);
    await build({
        ...common,
        entryPoints: [serverEntry()],
        outfile: path.join(outDir, 'out', 'server', 'main.mjs'),
        format: 'esm',
        // CommonJS dependencies of the server call require(); an ES module has none of its own.
        banner: {
            js: "import { createRequire as __maaCreateRequire } from 'node:module'; const require = __maaCreateRequire(import.meta.url);",
        },
    });
    await bundleWeb(outDir);
    await bundleDiagramWebview(outDir);
}

/** Loads src/contributions.ts (TypeScript) by bundling it to a temporary ES module. */
async function loadContributions() {
    const tmp = path.join(outDir, '..', `.contributions-${process.pid}.mjs`);
    await build({
        entryPoints: [path.join(pkgDir, 'src', 'contributions.ts')],
        outfile: tmp,
        bundle: true,
        platform: 'node',
        format: 'esm',
        logLevel: 'warning',
    });
    const { contributions } = await import(pathToFileURL(tmp).href);
    rmSync(tmp, { force: true });
    const facts = JSON.parse(readFileSync(require.resolve('@maa/language-server/language-facts.json'), 'utf8'));
    return contributions(facts);
}

function writeJson(file, value) {
    mkdirSync(path.dirname(file), { recursive: true });
    writeFileSync(file, `${JSON.stringify(value, null, 2)}\n`);
}

async function main() {
    rmSync(outDir, { recursive: true, force: true });
    mkdirSync(outDir, { recursive: true });
    const [{ contributes, files, activationEvents, capabilities }] = await Promise.all([loadContributions(), bundle()]);
    const own = JSON.parse(readFileSync(path.join(pkgDir, 'package.json'), 'utf8'));
    writeJson(path.join(outDir, 'package.json'), {
        ...IDENTITY,
        version: own.version,
        description: own.description,
        capabilities,
        activationEvents,
        contributes,
    });
    for (const f of files) {
        // Text files (the icons' SVG) as they are, the rest as JSON.
        if (typeof f.content === 'string') {
            mkdirSync(path.dirname(path.join(outDir, f.path)), { recursive: true });
            writeFileSync(path.join(outDir, f.path), f.content);
        } else writeJson(path.join(outDir, f.path), f.content);
    }
    mkdirSync(path.join(outDir, 'snippets'), { recursive: true });
    for (const name of ['arc.json', 'arcapp.json']) copyFileSync(path.join(pkgDir, 'snippets', name), path.join(outDir, 'snippets', name));
    writeFileSync(path.join(outDir, 'README.md'), packagedReadme(readFileSync(path.join(repo, 'docs', 'vscode.md'), 'utf8')));
    copyFileSync(path.join(repo, 'LICENSE'), path.join(outDir, 'LICENSE'));
    console.log(`vscode-extension: built ${path.relative(repo, outDir)}`);
}

/**
 * docs/vscode.md as the .vsix's README, without its Screenshots section: vsce refuses relative
 * image links in a package without a public repository address.
 */
function packagedReadme(markdown) {
    return markdown.replace(/\n## Screenshots\n[\s\S]*?(?=\n## |$)/, '\n');
}

await main();
