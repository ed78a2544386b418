/**
 * The extension's entry (bundled to CommonJS, `vscode` external): starts the family's language
 * server (the bundled `out/server/main.mjs`, Node IPC) and registers the commands. The logic lives in the
 * pure modules next to this one (settings, platforms, trace, generate-report); this file only
 * connects them to VS Code's API.
 */
import { execFile } from 'node:child_process';
import { existsSync, readFileSync } from 'node:fs';
import path from 'node:path';
import type { TraceFile } from '@maa/protocol';
import * as vscode from 'vscode';
import { LanguageClient, type LanguageClientOptions, type ServerOptions, TransportKind } from 'vscode-languageclient/node.js';
import { registerDiagram } from './diagram/index.js';
import { generate } from './generate-command.js';
import { type GenerateReport, parseGenerateReport } from './generate-report.js';
import type { GenerateRequest, GenerateRunner } from './generate-runner.js';
import {
    type ContributedLanguage,
    generateArgs,
    generateCommand,
    type MaaSettings,
    readSettings,
    serverStart,
    watchedFiles,
} from './settings.js';
import { registerDesktopStreamTests } from './testing/desktop.js';
import { registerSimulate } from './simulate/index.js';
import { generatedCodeAt, modelElementAt, platformDirOf } from './trace.js';

/** The file languages of the family, from the manifest (generated from the language facts). */
function modelLanguages(context: vscode.ExtensionContext): ContributedLanguage[] {
    const manifest = context.extension.packageJSON as { contributes?: { languages?: ContributedLanguage[] } };
    return manifest.contributes?.languages ?? [];
}

function settings(): MaaSettings {
    const config = vscode.workspace.getConfiguration();
    return readSettings((key) => config.get(key));
}

let client: LanguageClient | undefined;

function startClient(context: vscode.ExtensionContext, languages: readonly ContributedLanguage[]): LanguageClient {
    const start = serverStart(context.asAbsolutePath(path.join('out', 'server', 'main.mjs')), settings());
    const serverOptions: ServerOptions = {
        run: { ...start.run, transport: TransportKind.ipc },
        debug: { ...start.debug, transport: TransportKind.ipc },
    };
    const clientOptions: LanguageClientOptions = {
        documentSelector: languages.map((l) => ({ scheme: 'file', language: l.id })),
        synchronize: { fileEvents: vscode.workspace.createFileSystemWatcher(watchedFiles(languages)) },
    };
    const c = new LanguageClient('maa', 'MontiArc Language Server', serverOptions, clientOptions);
    void c.start();
    return c;
}

export function activate(context: vscode.ExtensionContext): void {
    const languages = modelLanguages(context);
    void vscode.commands.executeCommand(
        'setContext',
        'maa.modelLanguages',
        languages.map((l) => l.id),
    );
    client = startClient(context, languages);
    registerDiagram(context, client);
    const generated = vscode.languages.createDiagnosticCollection('maa-generate');
    context.subscriptions.push(
        generated,
        vscode.commands.registerCommand('maa.generate', () => generate(cliRunner, generated)),
        vscode.commands.registerCommand('maa.showGeneratedCode', showGeneratedCode),
        vscode.commands.registerCommand('maa.showModelElement', showModelElement),
    );
    context.subscriptions.push(registerSimulate(context));
    context.subscriptions.push(...registerDesktopStreamTests());
}

export function deactivate(): Thenable<void> | undefined {
    return client?.stop();
}

/** The desktop's GenerateRunner: `maa-gen generate … --format json` and its parsed report. */
const cliRunner: GenerateRunner = {
    run: (request, signal) => runCli(request, settings(), signal),
};

/** Runs `maa-gen generate … --format json` and parses its report. */
function runCli(request: GenerateRequest, s: MaaSettings, signal: AbortSignal): Promise<GenerateReport> {
    const folders = (vscode.workspace.workspaceFolders ?? []).map((f) => f.uri.fsPath);
    const command = generateCommand(s, folders, existsSync);
    return new Promise((resolve, reject) => {
        const child = execFile(
            command,
            generateArgs(request.appFile, request.platform, s),
            { cwd: path.dirname(request.appFile), maxBuffer: 64 * 1024 * 1024, shell: process.platform === 'win32' },
            (error, stdout, stderr) => {
                try {
                    resolve(parseGenerateReport(stdout, stderr));
                } catch (e) {
                    reject(error && !stdout ? new Error(`could not run ${command}: ${error.message}`) : e);
                }
            },
        );
        signal.addEventListener('abort', () => child.kill());
    });
}

/** Every trace file of the workspace with its platform folder. */
async function traceFiles(): Promise<Array<{ dir: string; trace: TraceFile }>> {
    const uris = await vscode.workspace.findFiles('**/.maa-trace.json', '**/node_modules/**');
    return uris.flatMap((uri) => {
        try {
            return [{ dir: path.dirname(uri.fsPath), trace: JSON.parse(readFileSync(uri.fsPath, 'utf8')) as TraceFile }];
        } catch {
            return [];
        }
    });
}

async function reveal(file: string, range: vscode.Range): Promise<void> {
    const editor = await vscode.window.showTextDocument(vscode.Uri.file(file), { preview: true });
    editor.selection = new vscode.Selection(range.start, range.end);
    editor.revealRange(range, vscode.TextEditorRevealType.InCenterIfOutsideViewport);
}

/** **Show Generated Code**: the generated lines of the model element at the cursor (a pick when several). */
async function showGeneratedCode(): Promise<void> {
    const editor = vscode.window.activeTextEditor;
    if (!editor) return;
    const pos = editor.selection.active;
    const hits = (await traceFiles()).flatMap(({ dir, trace }) =>
        generatedCodeAt(trace, dir, editor.document.uri.fsPath, { line: pos.line, character: pos.character }).map((g) => ({
            ...g,
            platform: trace.platform,
        })),
    );
    if (hits.length === 0) {
        void vscode.window.showInformationMessage('MontiArc: no generated code traced to this element (generate first).');
        return;
    }
    const chosen =
        hits.length === 1
            ? hits[0]
            : (
                  await vscode.window.showQuickPick(
                      hits.map((h) => ({
                          label: `${vscode.workspace.asRelativePath(h.file)}:${h.first + 1}`,
                          description: `${h.platform} · ${h.generator}`,
                          hit: h,
                      })),
                      { placeHolder: 'Generated code of this element' },
                  )
              )?.hit;
    if (chosen) await reveal(chosen.file, new vscode.Range(chosen.first, 0, chosen.last + 1, 0));
}

/** **Show Model Element**: the model element the generated line at the cursor comes from. */
async function showModelElement(): Promise<void> {
    const editor = vscode.window.activeTextEditor;
    if (!editor) return;
    const traces = await traceFiles();
    const dir = platformDirOf(
        editor.document.uri.fsPath,
        traces.map((t) => t.dir),
    );
    const trace = traces.find((t) => t.dir === dir)?.trace;
    const element = dir && trace ? modelElementAt(trace, dir, editor.document.uri.fsPath, editor.selection.active.line) : undefined;
    if (!element) {
        void vscode.window.showInformationMessage('MontiArc: this line is not traced to a model element.');
        return;
    }
    const r = element.range;
    await reveal(element.file, new vscode.Range(r.start.line, r.start.character, r.end.line, r.end.character));
}
