// The packaged extension: builds and packs the .vsix as `npm run package:vscode` does (into a
// temporary folder), unpacks it with `unzip`, checks the manifest (engines, main, contributes)
// and that every file it points at is in the package, and starts the language server from the
// unpacked files as VS Code would find it (`node <server> --stdio`): initialize, didOpen of a
// broken model, and the publishDiagnostics with an error that follows.
import { spawn, type ChildProcessWithoutNullStreams } from 'node:child_process';
import { once } from 'node:events';
import { existsSync, mkdirSync, mkdtempSync, readFileSync, rmSync, statSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import path from 'node:path';
import { fileURLToPath, pathToFileURL } from 'node:url';
import { LANGUAGE_FACTS } from '@maa/language-server/language-facts';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import {
    createProtocolConnection,
    DidOpenTextDocumentNotification,
    type Diagnostic,
    ExitNotification,
    InitializedNotification,
    InitializeRequest,
    PublishDiagnosticsNotification,
    ShutdownRequest,
    StreamMessageReader,
    StreamMessageWriter,
} from 'vscode-languageserver-protocol/node.js';

const pkgDir = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..');
const tmp = mkdtempSync(path.join(tmpdir(), 'maa-vsix-'));
const vsix = path.join(tmp, 'maa.vsix');
const unpacked = path.join(tmp, 'unpacked');
const ext = path.join(unpacked, 'extension');

/** Runs a command without blocking the worker; rejects with its output when it fails. */
function run(command: string, args: string[], cwd: string): Promise<void> {
    return new Promise((resolve, reject) => {
        const child = spawn(command, args, { cwd, stdio: ['ignore', 'pipe', 'pipe'] });
        let output = '';
        child.stdout.on('data', (d) => (output += String(d)));
        child.stderr.on('data', (d) => (output += String(d)));
        child.on('error', reject);
        child.on('exit', (code) =>
            code === 0 ? resolve() : reject(new Error(`${command} ${args.join(' ')} exited with ${code}:\n${output}`)),
        );
    });
}

interface Manifest {
    name: string;
    publisher: string;
    main: string;
    browser: string;
    engines: { vscode: string };
    activationEvents: string[];
    capabilities: { untrustedWorkspaces: { supported: string; restrictedConfigurations: string[] } };
    contributes: {
        languages: Array<{ id: string; extensions: string[]; configuration: string; icon: { light: string; dark: string } }>;
        grammars: Array<{ language: string; scopeName: string; path: string }>;
        snippets: Array<{ language: string; path: string }>;
        commands: Array<{ command: string; title: string }>;
        configuration: { properties: Record<string, { default: unknown }> };
    };
}

let manifest: Manifest;

beforeAll(async () => {
    // Built and packed in the temporary folder: the package's own dist/ is left alone.
    const built = path.join(tmp, 'extension');
    await run(process.execPath, [path.join(pkgDir, 'bin', 'build.mjs'), '--out', built], pkgDir);
    await run(process.execPath, [path.join(pkgDir, 'bin', 'package.mjs'), '--from', built, '--out', vsix], pkgDir);
    mkdirSync(unpacked);
    await run('unzip', ['-q', vsix, '-d', unpacked], tmp);
    manifest = JSON.parse(readFileSync(path.join(ext, 'package.json'), 'utf8')) as Manifest;
}, 240_000);

afterAll(() => rmSync(tmp, { recursive: true, force: true }));

describe('the .vsix', () => {
    it('is a VS Code extension package under 2.5 MB (docs/vscode.md says what takes the room)', () => {
        expect(existsSync(path.join(unpacked, 'extension.vsixmanifest'))).toBe(true);
        expect(statSync(vsix).size).toBeLessThan(2.5 * 1024 * 1024);
    });

    it("carries the repository's MIT license", () => {
        expect((manifest as unknown as { license: string }).license).toBe('MIT');
        const license = readFileSync(path.join(pkgDir, '..', '..', 'LICENSE'), 'utf8');
        expect(readFileSync(path.join(ext, 'LICENSE.txt'), 'utf8')).toBe(license); // vsce packs it as LICENSE.txt;
    });

    it('has a manifest with engines, main, activation and every file language of the family', () => {
        expect(manifest).toMatchObject({ name: 'maa', publisher: 'maa-web', main: './out/extension.cjs' });
        expect(manifest.engines.vscode).toMatch(/^\^1\.\d+\.\d+$/);
        const fileLanguages = LANGUAGE_FACTS.languages.filter((l) => l.kind === 'file');
        expect(manifest.contributes.languages.map((l) => [l.id, l.extensions])).toEqual(
            fileLanguages.map((l) => [l.id, [...l.fileExtensions]]),
        );
        expect(manifest.contributes.grammars.map((g) => g.language)).toEqual(fileLanguages.map((l) => l.id));
        expect(manifest.contributes.commands.map((c) => c.command)).toEqual([
            'maa.generate',
            'maa.showGeneratedCode',
            'maa.showModelElement',
            'maa.simulate.start',
            'maa.simulate.stop',
            'maa.simulate.reset',
            'maa.openDiagram',
            'maa.openAutomatonView',
            'maa.exportDiagramSvg',
        ]);
        expect(manifest.contributes.configuration.properties['maa.generate.outDir']?.default).toBe('generated');
        expect(manifest.activationEvents).toContain('onLanguage:arc');
        expect(manifest.capabilities.untrustedWorkspaces.restrictedConfigurations).toContain('maa.generate.command');
    });

    it('contains every file the manifest points at, and the language server', () => {
        const c = manifest.contributes;
        const files = [
            manifest.main,
            ...c.languages.map((l) => l.configuration),
            ...c.grammars.map((g) => g.path),
            ...c.snippets.map((s) => s.path),
            'out/server/main.mjs',
            // The web entry and its language server worker (bin/web.mjs).
            manifest.browser,
            'out/web/server.js',
        ];
        for (const f of files) expect(existsSync(path.join(ext, f)), f).toBe(true);
        for (const g of c.grammars) {
            const grammar = JSON.parse(readFileSync(path.join(ext, g.path), 'utf8')) as { scopeName: string };
            expect(grammar.scopeName).toBe(g.scopeName);
        }
        expect(readFileSync(path.join(ext, manifest.main), 'utf8')).toContain('require("vscode")');
        expect(manifest.browser).toBe('./out/web/extension.js');
        expect(readFileSync(path.join(ext, manifest.browser), 'utf8')).toContain('require("vscode")');
    });
});

describe('the diagram in the .vsix', () => {
    it('contains the webview bundle, the editor title button and every language icon the manifest points at', () => {
        // The webview's script and stylesheet (bin/diagram-webview.mjs), the only files it may load.
        const script = readFileSync(path.join(ext, 'out', 'webview', 'diagram.js'), 'utf8');
        expect(script).toContain('acquireVsCodeApi');
        expect(script).not.toContain('require("vscode")');
        expect(readFileSync(path.join(ext, 'out', 'webview', 'diagram.css'), 'utf8')).toContain('.maa-diagram-toolbar');
        const c = manifest.contributes as Manifest['contributes'] & { menus: Record<string, Array<{ command: string; when?: string }>> };
        expect(c.menus['editor/title']?.map((m) => m.command)).toEqual(
            expect.arrayContaining(['maa.openDiagram', 'maa.openAutomatonView']),
        );
        for (const l of c.languages) {
            for (const icon of [l.icon.light, l.icon.dark]) {
                expect(existsSync(path.join(ext, icon)), icon).toBe(true);
                expect(readFileSync(path.join(ext, icon), 'utf8')).toMatch(/^<svg xmlns="http:\/\/www\.w3\.org\/2000\/svg"/);
            }
        }
        for (const theme of ['light', 'dark']) expect(existsSync(path.join(ext, 'icons', `diagram-${theme}.svg`))).toBe(true);
    });
});

describe('the simulate view in the .vsix', () => {
    it('offers the simulate commands in the palette of the desktop and the web (both entries register them)', () => {
        const palette =
            (manifest.contributes as { menus?: Record<string, Array<{ command: string; when?: string }>> }).menus?.['commandPalette'] ?? [];
        for (const command of ['maa.simulate.start', 'maa.simulate.stop', 'maa.simulate.reset']) {
            expect(palette.find((m) => m.command === command)?.when, command).toBeUndefined();
        }
    });

    it('contributes the simulate settings, restricted in untrusted workspaces', () => {
        const properties = manifest.contributes.configuration.properties;
        expect(properties['maa.simulate.node']?.default).toBe('node');
        expect(properties['maa.simulate.backend']?.default).toBe('');
        expect(manifest.capabilities.untrustedWorkspaces.restrictedConfigurations).toEqual(
            expect.arrayContaining(['maa.simulate.node', 'maa.simulate.backend']),
        );
    });

    it("contains the webview's panel bundle and stylesheet and maa-ide's launcher", () => {
        // The shared panel (@maa/simulate-view) with its webview entry, bundled for the browser.
        const script = readFileSync(path.join(ext, 'out', 'webview', 'simulate.js'), 'utf8');
        expect(script).toContain('simulate-root');
        expect(script).toContain('acquireVsCodeApi');
        expect(script).not.toContain('require("');
        expect(readFileSync(path.join(ext, 'out', 'webview', 'simulate.css'), 'utf8')).toContain('.maa-simulate');
        expect(readFileSync(path.join(ext, 'out', 'simulate', 'backend-launcher.mjs'), 'utf8')).toContain('SIGTERM');
    });
});

describe('the language server of the unpacked .vsix', () => {
    let child: ChildProcessWithoutNullStreams | undefined;
    afterAll(() => {
        if (child && child.exitCode === null && child.signalCode === null) child.kill();
    });

    it('starts with --stdio and publishes an error for a broken model', async () => {
        const ws = path.join(tmp, 'ws');
        mkdirSync(path.join(ws, 'demo'), { recursive: true });
        const text = 'package demo;\n\ncomponent Broken {\n  port in int x,\n       out int y;\n  x -> nowhere;\n';
        const file = path.join(ws, 'demo', 'Broken.arc');
        writeFileSync(file, text);
        const uri = pathToFileURL(file).toString();
        child = spawn(process.execPath, [path.join(ext, 'out', 'server', 'main.mjs'), '--stdio'], {
            cwd: ws,
            stdio: ['pipe', 'pipe', 'pipe'],
        });
        const client = createProtocolConnection(new StreamMessageReader(child.stdout), new StreamMessageWriter(child.stdin));
        const error = new Promise<Diagnostic>((resolve) => {
            client.onNotification(PublishDiagnosticsNotification.type, (p) => {
                const found = p.uri === uri ? p.diagnostics.find((d) => d.severity === 1) : undefined;
                if (found) resolve(found);
            });
        });
        client.onRequest('client/registerCapability', () => null);
        client.onRequest('workspace/configuration', () => []);
        client.listen();
        const root = pathToFileURL(ws).toString();
        const init = await client.sendRequest(InitializeRequest.type, {
            processId: process.pid,
            rootUri: root,
            workspaceFolders: [{ uri: root, name: 'ws' }],
            capabilities: {},
        });
        expect(init.capabilities.textDocumentSync).toBeDefined();
        await client.sendNotification(InitializedNotification.type, {});
        await client.sendNotification(DidOpenTextDocumentNotification.type, { textDocument: { uri, languageId: 'arc', version: 1, text } });
        const diagnostic = await error;
        expect(diagnostic.range.start.line).toBeGreaterThanOrEqual(2);
        expect(typeof diagnostic.code).toBe('string');

        const exited = once(child, 'exit');
        await client.sendRequest(ShutdownRequest.type);
        await client.sendNotification(ExitNotification.type);
        expect((await exited)[0]).toBe(0);
        client.dispose();
    }, 120_000);
});
