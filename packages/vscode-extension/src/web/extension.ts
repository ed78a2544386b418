/**
 * The extension's web entry (the manifest's `browser`, bundled to CommonJS with `vscode`
 * external), which the browser IDE runs: the family's language server in a Web Worker
 * (`out/web/server.js`, the `@maa/language-server/browser` entry) over
 * `vscode-languageclient/browser`, and everything that runs programs through the browser IDE's
 * backend at the page's origin (web/backend.ts) instead of the CLI: Generate, Show Generated
 * Code, the stream tests, the simulation. The desktop entry is ../extension.ts; what both do is
 * in the shared modules next to it.
 */
import * as vscode from 'vscode';
import { LanguageClient, type LanguageClientOptions } from 'vscode-languageclient/browser.js';
import { registerDiagram } from '../diagram/index.js';
import { generate } from '../generate-command.js';
import { type ContributedLanguage, watchedFiles } from '../model-files.js';
import { registerWebSimulate } from '../simulate/web.js';
import { registerStreamTests } from '../testing/controller.js';
import { WebStreamTestRunner } from '../testing/web-runner.js';
import { backendBase, backendRunner } from './backend.js';
import { registerGeneratedCode } from './generated-code.js';
import { startServerWorker } from './server-worker.js';

/** The file languages of the family, from the manifest (generated from the language facts). */
function modelLanguages(context: vscode.ExtensionContext): ContributedLanguage[] {
    const manifest = context.extension.packageJSON as { contributes?: { languages?: ContributedLanguage[] } };
    return manifest.contributes?.languages ?? [];
}

let client: LanguageClient | undefined;

async function startClient(
    context: vscode.ExtensionContext,
    languages: readonly ContributedLanguage[],
    apiBase: string,
): Promise<LanguageClient> {
    const worker = await startServerWorker(context.extensionUri);
    const clientOptions: LanguageClientOptions = {
        documentSelector: languages.map((l) => ({ language: l.id })),
        // Files created, saved or deleted in the workbench (the explorer, other editors) reach the server.
        synchronize: { fileEvents: vscode.workspace.createFileSystemWatcher(watchedFiles(languages)) },
        // The server reads the workspace over the backend API at this base (docs/ide.md).
        initializationOptions: { apiBase },
    };
    const c = new LanguageClient('maa', 'MontiArc Language Server', clientOptions, worker);
    await c.start();
    return c;
}

/** The workspace folder's path (`/workspace` in the browser IDE) and a file's path below it. */
function workspacePaths(): { root: string; relative: (file: string) => string } {
    const folder = vscode.workspace.workspaceFolders?.[0];
    return {
        root: folder?.uri.path ?? '/',
        relative: (file) => vscode.workspace.asRelativePath(vscode.Uri.file(file), false),
    };
}

export async function activate(context: vscode.ExtensionContext): Promise<void> {
    const languages = modelLanguages(context);
    void vscode.commands.executeCommand(
        'setContext',
        'maa.modelLanguages',
        languages.map((l) => l.id),
    );
    const apiBase = backendBase();
    const generated = vscode.languages.createDiagnosticCollection('maa-generate');
    const { root, relative } = workspacePaths();
    const runner = backendRunner(apiBase, root, relative);
    context.subscriptions.push(
        generated,
        vscode.commands.registerCommand('maa.generate', () => generate(runner, generated)),
    );
    registerTests(context, apiBase, root);
    context.subscriptions.push(registerWebSimulate(context, apiBase));
    registerGeneratedCode(context, apiBase);
    try {
        client = await startClient(context, languages, apiBase);
        // The diagram webview (src/diagram) talks to the same server through the client.
        registerDiagram(context, client);
    } catch (e) {
        void vscode.window.showErrorMessage(`MontiArc: the language server did not start: ${e instanceof Error ? e.message : String(e)}`);
    }
}

/**
 * The `.stream` tests in the Testing API, run through the backend's `POST /api/test`. A host
 * without VS Code's testing service (the browser IDE's workbench at monaco-vscode-api 25.1.2,
 * docs/ide.md) refuses the controller on its side and logs that; a host that throws here
 * instead does not stop the rest of the extension either.
 */
function registerTests(context: vscode.ExtensionContext, apiBase: string, root: string): void {
    try {
        context.subscriptions.push(...registerStreamTests(new WebStreamTestRunner(apiBase, root)));
    } catch (e) {
        console.warn(`MontiArc: no stream tests in this host (${e instanceof Error ? e.message : String(e)})`);
    }
}

export function deactivate(): Thenable<void> | undefined {
    return client?.stop();
}
