/**
 * The browser IDE's page (index.html): VS Code's own workbench from @codingame/monaco-vscode-api
 * (explorer, editors, quick open, command palette, keybindings, settings) over the workspace the
 * backend serves, with the MontiArc extension (packages/vscode-extension, its web entry)
 * registered and activated in it. The project's code here is only the glue: the file system
 * provider over the backend's API, loading the extension's files, and the hooks the e2e tests and
 * the benchmark read (`window.maaHost`). docs/ide.md, "How the page hosts the extension".
 */
import { initialize, LogLevel } from '@codingame/monaco-vscode-api';
import { ExtensionHostKind, registerExtension } from '@codingame/monaco-vscode-api/extensions';
import getBulkEditServiceOverride from '@codingame/monaco-vscode-bulk-edit-service-override';
import getConfigurationServiceOverride, { initUserConfiguration } from '@codingame/monaco-vscode-configuration-service-override';
import getDialogsServiceOverride from '@codingame/monaco-vscode-dialogs-service-override';
import * as monaco from '@codingame/monaco-vscode-editor-api';
import EditorWorker from '@codingame/monaco-vscode-editor-api/esm/vs/editor/editor.worker.js?worker';
import getExplorerServiceOverride from '@codingame/monaco-vscode-explorer-service-override';
import getExtensionsServiceOverride from '@codingame/monaco-vscode-extensions-service-override';
import { registerFileSystemOverlay } from '@codingame/monaco-vscode-files-service-override';
import getKeybindingsServiceOverride from '@codingame/monaco-vscode-keybindings-service-override';
import getLanguagesServiceOverride from '@codingame/monaco-vscode-languages-service-override';
import getLogServiceOverride from '@codingame/monaco-vscode-log-service-override';
import getMarkersServiceOverride from '@codingame/monaco-vscode-markers-service-override';
import getModelServiceOverride from '@codingame/monaco-vscode-model-service-override';
import getNotificationsServiceOverride from '@codingame/monaco-vscode-notifications-service-override';
import getOutputServiceOverride from '@codingame/monaco-vscode-output-service-override';
import getPreferencesServiceOverride from '@codingame/monaco-vscode-preferences-service-override';
import getSearchServiceOverride from '@codingame/monaco-vscode-search-service-override';
import getTestingServiceOverride from '@codingame/monaco-vscode-testing-service-override';
import getTextmateServiceOverride from '@codingame/monaco-vscode-textmate-service-override';
import TextMateWorker from '@codingame/monaco-vscode-textmate-service-override/worker?worker';
import getThemeServiceOverride from '@codingame/monaco-vscode-theme-service-override';
import getWorkingCopyServiceOverride from '@codingame/monaco-vscode-working-copy-service-override';
import getWorkbenchServiceOverride from '@codingame/monaco-vscode-workbench-service-override';
import * as vscode from 'vscode';
import 'vscode/localExtensionHost';
import { loadExtension } from './extension.js';
import { BackendFileSystem, WORKSPACE_ROOT } from './file-system.js';
import { registerExercisePanel } from './exercise-panel.js';
import { registerFileSearch } from './file-search.js';
import { startLabMode } from './lab.js';

/** The extension's id (publisher.name of its manifest). */
const EXTENSION_ID = 'maa-web.maa';
/** The first file shown: the example's root component, unless `?open=<path>` names another. */
const START_FILE = /(^|\/)ToastServiceRobot\.arc$/;

export interface HostHooks {
    timings: Record<string, number>;
    ready: boolean;
    /** The markers (diagnostics) of a workspace file, as the editor has them. */
    markers(path: string): { severity: number; message: string; line: number }[];
    /** Whether the language server has published diagnostics for the file (possibly none) since the page loaded. */
    checked(path: string): boolean;
    extensionActive(): boolean;
    /** Opens a workspace file in an editor (the benchmark). */
    open(path: string): Promise<void>;
    /** The code editor of the active text editor (the benchmark types into it). */
    activeEditor(): monaco.editor.ICodeEditor | undefined;
    /** Every marker of the workspace's files, with its path (the benchmark compares them). */
    allMarkers(): { path: string; severity: number; message: string; line: number }[];
    /** The code editor showing a workspace file, also while another part (a webview) has the focus (the e2e tests). */
    editorOf(path: string): monaco.editor.ICodeEditor | undefined;
    /** The current text of a workspace file's model, saved or not; undefined when no model has it (the e2e tests). */
    text(path: string): string | undefined;
}
declare global {
    interface Window {
        maaHost: HostHooks;
    }
}

const hooks: HostHooks = {
    timings: { start: performance.now() },
    ready: false,
    markers: (path) =>
        monaco.editor.getModelMarkers({ resource: monaco.Uri.file(`${WORKSPACE_ROOT}/${path}`) }).map((m) => ({
            severity: m.severity,
            message: m.message,
            line: m.startLineNumber,
        })),
    checked: (path) => checked.has(`${WORKSPACE_ROOT}/${path}`),
    extensionActive: () => vscode.extensions.getExtension(EXTENSION_ID)?.isActive === true,
    open: async (path) => {
        await vscode.window.showTextDocument(vscode.Uri.file(`${WORKSPACE_ROOT}/${path}`), { preview: false });
    },
    activeEditor: () => {
        const uri = vscode.window.activeTextEditor?.document.uri.toString();
        return monaco.editor.getEditors().find((e) => e.getModel()?.uri.toString() === uri);
    },
    allMarkers: () =>
        monaco.editor
            .getModelMarkers({})
            .filter((m) => m.resource.path.startsWith(`${WORKSPACE_ROOT}/`))
            .map((m) => ({
                path: m.resource.path.slice(WORKSPACE_ROOT.length + 1),
                severity: m.severity,
                message: m.message,
                line: m.startLineNumber,
            })),
    editorOf: (path) => {
        const uri = monaco.Uri.file(`${WORKSPACE_ROOT}/${path}`).toString();
        const showing = monaco.editor.getEditors().filter((e) => e.getModel()?.uri.toString() === uri);
        return showing.find((e) => e.hasTextFocus()) ?? showing[0];
    },
    text: (path) => monaco.editor.getModel(monaco.Uri.file(`${WORKSPACE_ROOT}/${path}`))?.getValue(),
};
/** The files the language server has published diagnostics for (vscode.languages.onDidChangeDiagnostics, from main()). */
const checked = new Set<string>();
window.maaHost = hooks;

function startFile(files: string[]): string | undefined {
    const requested = new URLSearchParams(location.search).get('open') ?? undefined;
    const models = files.filter((f) => f.endsWith('.arc'));
    return (requested && files.includes(requested) ? requested : undefined) ?? models.find((p) => START_FILE.test(p)) ?? models[0];
}

async function startWorkbench(container: HTMLElement): Promise<void> {
    const extension = await loadExtension(new URL('.', document.baseURI));
    // Monaco's own worker and the TextMate tokenizer (the extension's grammars), bundled by Vite.
    const environment: monaco.Environment = {
        getWorker: (_moduleId, label) => (label === 'TextMateWorker' ? new TextMateWorker() : new EditorWorker()),
    };
    (globalThis as { MonacoEnvironment?: monaco.Environment }).MonacoEnvironment = environment;
    await initUserConfiguration(
        JSON.stringify({
            'workbench.colorTheme': 'Default Dark Modern',
            'workbench.startupEditor': 'none',
            'editor.semanticHighlighting.enabled': true,
            'editor.guides.bracketPairsHorizontal': 'active',
            // The start page shows the model and its diagram (the extension's setting, off in VS Code desktop).
            'maa.diagram.openOnStart': true,
        }),
    );
    await initialize(
        {
            ...getConfigurationServiceOverride(),
            ...getLogServiceOverride(),
            ...getModelServiceOverride(),
            ...getExtensionsServiceOverride({ enableWorkerExtensionHost: false }),
            ...getLanguagesServiceOverride(),
            ...getTextmateServiceOverride(),
            ...getThemeServiceOverride(),
            ...getWorkbenchServiceOverride(),
            ...getKeybindingsServiceOverride(),
            ...getExplorerServiceOverride(),
            ...getSearchServiceOverride(),
            ...getMarkersServiceOverride(),
            ...getNotificationsServiceOverride(),
            ...getDialogsServiceOverride(),
            ...getOutputServiceOverride(),
            ...getTestingServiceOverride(),
            ...getPreferencesServiceOverride(),
            // Workspace edits (rename, quick fixes across files) through VS Code's own bulk edit
            // service and working copies: files they change without an editor are saved too.
            ...getBulkEditServiceOverride(),
            ...getWorkingCopyServiceOverride(),
        },
        container,
        {
            workspaceProvider: {
                trusted: true,
                workspace: { folderUri: monaco.Uri.file(WORKSPACE_ROOT) },
                open: async () => false,
            },
            productConfiguration: { nameShort: 'MontiArcAutomaton', nameLong: 'MontiArcAutomaton for the web' },
            developmentOptions: { logLevel: LogLevel.Warning },
        },
    );
    await import('@codingame/monaco-vscode-theme-defaults-default-extension');
    const registered = registerExtension(extension.manifest, ExtensionHostKind.LocalProcess);
    for (const [file, url] of extension.files) registered.registerFileUrl(file, url.href);
    await registered.whenReady();
}

async function main(): Promise<void> {
    // Lab mode first (docs/lab.md): its CSRF token goes on every write, the exercise names the read-only files.
    const lab = await startLabMode();
    const files = await BackendFileSystem.load(lab?.readOnly);
    registerFileSystemOverlay(1, files);
    hooks.timings.files = performance.now();
    const container = document.getElementById('workbench');
    if (!container) throw new Error('index.html has no #workbench element');
    // Registered before the workbench starts, so the search provider is among the built-in extensions from the start.
    const searching = registerFileSearch(WORKSPACE_ROOT, () => files.files());
    await startWorkbench(container);
    await searching;
    if (lab) await registerExercisePanel(lab.exercise, WORKSPACE_ROOT);
    hooks.timings.services = performance.now();
    vscode.languages.onDidChangeDiagnostics((e) => {
        for (const uri of e.uris) checked.add(uri.path);
    });
    const start = startFile(files.files());
    if (start) await hooks.open(start);
    hooks.timings.editor = performance.now();
    // Opening a model activates the extension (onLanguage); wait for it, so `ready` means the language server runs.
    await vscode.extensions.getExtension(EXTENSION_ID)?.activate();
    hooks.timings.client = performance.now();
    hooks.ready = true;
    hooks.timings.ready = performance.now();
    document.body.dataset.ready = 'true';
}

main().catch((error: unknown) => {
    console.error(error);
    document.body.dataset.failed = error instanceof Error ? error.message : String(error);
});
