/**
 * The workbench shell: starts the VS Code services (monaco-vscode-api, classic mode with
 * Monarch), the language client on the language server Web Worker, and lays out explorer,
 * editor tabs, diagram and the bottom panel (Problems / Generate / Simulate).
 */
import './style.css';
import * as monaco from '@codingame/monaco-vscode-editor-api';
import type { OpenEditor } from '@codingame/monaco-vscode-editor-service-override';
import { LogLevel } from '@codingame/monaco-vscode-api';
import { MonacoLanguageClient } from 'monaco-languageclient';
import { MonacoVscodeApiWrapper } from 'monaco-languageclient/vscodeApiWrapper';
import EditorWorker from '@codingame/monaco-vscode-editor-api/esm/vs/editor/editor.worker.js?worker';
import { registerFileSystemOverlay, RegisteredFileSystemProvider } from '@codingame/monaco-vscode-files-service-override';
import { BrowserMessageReader, BrowserMessageWriter } from 'vscode-languageclient/browser.js';
import { DidChangeWatchedFilesNotification, FileChangeType } from 'vscode-languageserver-protocol';
import type { ActionMessage } from 'sprotty-protocol';
import { api, pathOf, uriOf, WORKSPACE_URI, type FileEntry } from './api.js';
import { parseTrace } from './diagram/trace.js';
import type { DiagramHost, DiagramView, Disposable, TextPosition, TextRange } from './contracts.js';
import { isModelFile, MODEL_LANGUAGE_IDS, registerLanguages } from './languages.js';
import { basename, byId, h } from './workbench/dom.js';
import { EditorArea } from './workbench/editors.js';
import { Explorer } from './workbench/explorer.js';
import { GeneratePanel } from './workbench/generate.js';
import { ProblemsPanel } from './workbench/problems.js';
import { QuickOpen } from './workbench/quickOpen.js';

/** The first file shown: the example's root component. */
const START_FILE = /(^|\/)ToastServiceRobot\.arc$/;

/** Timings and hooks for the e2e tests and the benchmark (`window.maaIde`). */
interface IdeHooks {
    timings: Record<string, number>;
    ready: boolean;
    diagramUpdates: number;
    editor?: monaco.editor.IStandaloneCodeEditor;
    open(path: string, range?: TextRange): Promise<void>;
    markers(): { path: string; severity: number; message: string; line: number }[];
    /** The current text of a workspace file's model (undefined when not loaded). */
    text(path: string): string | undefined;
    /** Selects the `occurrence`-th match of `needle` in the active editor (plus offset/length). */
    select(needle: string, options?: { occurrence?: number; offset?: number; length?: number }): boolean;
}
declare global {
    interface Window {
        maaIde: IdeHooks;
    }
}

const hooks: IdeHooks = {
    timings: { start: performance.now() },
    ready: false,
    diagramUpdates: 0,
    open: async () => undefined,
    markers: () =>
        monaco.editor.getModelMarkers({}).map((m) => ({
            path: pathOf(m.resource.toString()) ?? m.resource.toString(),
            severity: m.severity,
            message: m.message,
            line: m.startLineNumber,
        })),
    text: (path) => monaco.editor.getModel(monaco.Uri.parse(uriOf(path)))?.getValue(),
    select: (needle, options = {}) => {
        const editor = hooks.editor;
        const model = editor?.getModel();
        if (!editor || !model) return false;
        const matches = model.findMatches(needle, false, false, true, null, false);
        const match = matches[options.occurrence ?? 0];
        if (!match) return false;
        const start = model.modifyPosition(match.range.getStartPosition(), options.offset ?? 0);
        const end = model.modifyPosition(start, options.length ?? (options.offset === undefined ? needle.length : 0));
        editor.setSelection(monaco.Selection.fromPositions(start, end));
        editor.revealPositionInCenterIfOutsideViewport(start);
        editor.focus();
        return true;
    },
};
window.maaIde = hooks;

// ---------------------------------------------------------------------------------- status line
const statusMessage = byId('status-message');
function notify(severity: 'info' | 'warning' | 'error', message: string): void {
    statusMessage.textContent = message;
    statusMessage.className = `status-item status-${severity}`;
    if (severity !== 'info') console.warn(`[maa-ide] ${message}`);
}
const statusServer = byId('status-server');
function setServerStatus(text: string, state: 'starting' | 'ready' | 'error'): void {
    statusServer.textContent = text;
    statusServer.dataset.state = state;
}

// ---------------------------------------------------------------------------------- bottom panel
type PanelTab = 'problems' | 'generate' | 'simulate';
function showPanel(tab: PanelTab): void {
    for (const button of document.querySelectorAll<HTMLElement>('.panel-tab'))
        button.classList.toggle('active', button.dataset.tab === tab);
    for (const view of document.querySelectorAll<HTMLElement>('.panel-view')) view.hidden = view.dataset.tab !== tab;
}
for (const button of document.querySelectorAll<HTMLElement>('.panel-tab')) {
    button.addEventListener('click', () => showPanel(button.dataset.tab as PanelTab));
}

// ---------------------------------------------------------------------------------- services
let editors: EditorArea | undefined;
let workspaceFiles: RegisteredFileSystemProvider | undefined;

const openEditor: OpenEditor = async (modelRef, options) => {
    const uri = modelRef.object.textEditorModel.uri.toString();
    const path = pathOf(uri);
    if (!path || !editors) return undefined;
    const selection =
        options && 'selection' in options
            ? (options as { selection?: { startLineNumber: number; startColumn: number; endLineNumber?: number; endColumn?: number } })
                  .selection
            : undefined;
    const range = selection
        ? {
              start: { line: selection.startLineNumber - 1, character: selection.startColumn - 1 },
              end: {
                  line: (selection.endLineNumber ?? selection.startLineNumber) - 1,
                  character: (selection.endColumn ?? selection.startColumn) - 1,
              },
          }
        : undefined;
    return await editors.open(path, range);
};

async function startServices(): Promise<void> {
    const wrapper = new MonacoVscodeApiWrapper({
        $type: 'classic',
        viewsConfig: { $type: 'EditorService', openEditorFunc: openEditor },
        logLevel: LogLevel.Warning,
        advanced: { enforceSemanticHighlighting: true },
        userConfiguration: {
            json: JSON.stringify({
                'workbench.colorTheme': 'Default Dark Modern',
                'editor.semanticHighlighting.enabled': true,
                'editor.guides.bracketPairsHorizontal': 'active',
                'editor.lightbulb.enabled': 'onCode',
            }),
        },
        // Monaco's own worker (diff, links, word-based suggestions), bundled by Vite.
        monacoWorkerFactory: () => {
            const environment: monaco.Environment = { getWorker: () => new EditorWorker() };
            (globalThis as { MonacoEnvironment?: monaco.Environment }).MonacoEnvironment = environment;
        },
    });
    await wrapper.start();
    // The workspace files for VS Code's file service (peek/references into files without a tab).
    workspaceFiles = new RegisteredFileSystemProvider(false);
    registerFileSystemOverlay(1, workspaceFiles);
    registerLanguages();
    monaco.editor.setTheme('vs-dark');
}

let languageClient: MonacoLanguageClient | undefined;

async function startLanguageClient(): Promise<MonacoLanguageClient> {
    setServerStatus('Language server: starting…', 'starting');
    const worker = new Worker(new URL('./worker.ts', import.meta.url), { type: 'module', name: 'maa-language-server' });
    worker.addEventListener('error', (e) => {
        setServerStatus('Language server: failed', 'error');
        notify('error', `The language server worker failed: ${e.message}`);
    });
    const client = new MonacoLanguageClient({
        name: 'MontiArcAutomaton',
        id: 'maa',
        clientOptions: {
            documentSelector: MODEL_LANGUAGE_IDS.map((language) => ({ scheme: 'file', language })),
            workspaceFolder: { index: 0, name: 'workspace', uri: monaco.Uri.parse('file:///workspace') },
            // The server reads the workspace over the backend API at this base (docs/ide.md).
            initializationOptions: { apiBase: new URL('.', document.baseURI).href.replace(/\/$/, '') },
            errorHandler: {
                error: () => ({ action: 1 /* Continue */ }),
                closed: () => ({ action: 1 /* DoNotRestart */ }),
            },
        },
        messageTransports: { reader: new BrowserMessageReader(worker), writer: new BrowserMessageWriter(worker) },
    });
    await client.start();
    setServerStatus('Language server: ready', 'ready');
    return client;
}

// ---------------------------------------------------------------------------------- diagram
/** The diagram until the real one is mounted (it is loaded as a chunk of its own), or when it failed. */
class NoDiagram implements DiagramView {
    show(): void {
        /* nothing */
    }
    revealPosition(): void {
        /* nothing */
    }
    exportSvg(): Promise<string> {
        return Promise.resolve('<svg xmlns="http://www.w3.org/2000/svg"/>');
    }
    setLiveValues(): void {
        /* nothing */
    }
    setActiveStates(): void {
        /* nothing */
    }
    onSelect(): Disposable {
        return { dispose: () => undefined };
    }
    dispose(): void {
        /* nothing */
    }
}

/** The workspace file and range a langium-sprotty trace points to (see diagram/trace.ts for the format). */
function traceTarget(trace: string): { path: string; range: TextRange } | undefined {
    const parsed = parseTrace(trace);
    // parseTrace decodes the URI already: take the path as it is, without a second decoding.
    if (!parsed?.uri.startsWith(WORKSPACE_URI)) return undefined;
    return { path: parsed.uri.slice(WORKSPACE_URI.length), range: parsed.range };
}

async function mountDiagramPane(client: MonacoLanguageClient, area: EditorArea): Promise<DiagramView> {
    const container = byId('diagram-container');
    const { mountDiagram } = await import('./diagram/index.js');
    const host: DiagramHost = {
        sendDiagramMessage: (message: ActionMessage) => void client.sendNotification('diagram/accept', message),
        onDiagramMessage: (handler) => {
            const disposable = client.onNotification('diagram/accept', (message: ActionMessage) => {
                hooks.diagramUpdates++;
                handler(message);
            });
            return { dispose: () => disposable.dispose() };
        },
        revealTrace: (trace) => {
            const target = traceTarget(trace);
            if (target) void area.open(target.path, target.range, false);
        },
    };
    return mountDiagram(container, host);
}

// ---------------------------------------------------------------------------------- main
async function main(): Promise<void> {
    await startServices();
    hooks.timings.services = performance.now();

    const explorer = new Explorer(byId('explorer'), (path) => void area.open(path));
    let workspaceEntries: FileEntry[] = [];
    const cursorStatus = byId('status-cursor');
    const languageStatus = byId('status-language');
    let diagram: DiagramView = new NoDiagram();
    let shownDiagram: string | undefined;

    /** Shows the architecture of the active component file (the diagram's own switch shows its automaton). */
    function updateDiagram(path: string | undefined, force = false): void {
        if (!path?.endsWith('.arc')) return;
        if (path === shownDiagram && !force) return;
        shownDiagram = path;
        diagram.show({ uri: uriOf(path), diagramType: 'maa-cc' });
    }

    let cursorTimer: ReturnType<typeof setTimeout> | undefined;
    const area: EditorArea = new EditorArea(byId('editor-tabs'), byId('editor'), workspaceFiles, {
        onActiveChanged: (path) => {
            explorer.select(path);
            languageStatus.textContent = path ? (area.editor.getModel()?.getLanguageId() ?? '') : '';
            document.title = path ? `${basename(path)} — MontiArcAutomaton` : 'MontiArcAutomaton';
            updateDiagram(path);
        },
        onCursor: (path, position) => {
            cursorStatus.textContent = `Ln ${position.lineNumber}, Col ${position.column}`;
            if (cursorTimer) clearTimeout(cursorTimer);
            cursorTimer = setTimeout(() => {
                const p: TextPosition = { line: position.lineNumber - 1, character: position.column - 1 };
                if (path.endsWith('.arc')) diagram.revealPosition(uriOf(path), p);
            }, 120);
        },
        onSaved: (path) => {
            notify('info', `Saved ${path}`);
            void languageClient?.sendNotification(DidChangeWatchedFilesNotification.type, {
                changes: [{ uri: uriOf(path), type: FileChangeType.Changed }],
            });
        },
    });
    editors = area;
    hooks.editor = area.editor;
    hooks.open = async (path, range) => {
        await area.open(path, range);
    };

    const problems = new ProblemsPanel(byId('problems'), (path, range) => void area.open(path, range));
    const problemsCount = byId('problems-count');
    const statusProblems = byId('status-problems');
    problems.onCounts((c) => {
        problemsCount.textContent = String(c.errors + c.warnings);
        problemsCount.hidden = c.errors + c.warnings === 0;
        statusProblems.replaceChildren(
            h('span', { class: 'severity-icon error' }),
            ` ${c.errors} `,
            h('span', { class: 'severity-icon warning' }),
            ` ${c.warnings}`,
        );
    });
    statusProblems.addEventListener('click', () => showPanel('problems'));

    const generate = new GeneratePanel(byId('generate-panel'), {
        openModel: (path, range) => void area.open(path, range),
        modelOf: (path) => area.model(path),
        notify,
        reveal: () => showPanel('generate'),
        workspacePaths: () => workspaceEntries.map((e) => e.path),
    });

    // The workspace: list, load every model file (the language server sees the whole workspace).
    const listing = await api.files();
    workspaceEntries = listing.entries;
    explorer.setEntries(listing.root, listing.entries);
    const files = listing.entries.filter((e) => e.type === 'file').map((e) => e.path);
    const modelFiles = files.filter(isModelFile);
    // `?open=<path>` opens that file first (links, the benchmark).
    const requested = new URLSearchParams(location.search).get('open') ?? undefined;
    const start =
        (requested && files.includes(requested) ? requested : undefined) ??
        modelFiles.find((p) => START_FILE.test(p)) ??
        modelFiles.find((p) => p.endsWith('.arc')) ??
        files[0];

    // Language client first, so the documents' didOpen go to the server.
    try {
        languageClient = await startLanguageClient();
    } catch (error) {
        setServerStatus('Language server: failed', 'error');
        notify('error', `The language server did not start: ${error instanceof Error ? error.message : String(error)}`);
    }
    hooks.timings.client = performance.now();

    // The start file first (interactive as soon as possible), then the rest of the models.
    if (start) await area.open(start);
    hooks.timings.editor = performance.now();
    await Promise.all(
        modelFiles.map(async (path) => {
            try {
                await area.model(path);
            } catch (error) {
                notify('warning', error instanceof Error ? error.message : String(error));
            }
        }),
    );
    hooks.timings.models = performance.now();

    if (languageClient) {
        try {
            diagram = await mountDiagramPane(languageClient, area);
            diagram.onSelect((traces) => {
                const target = traces.map(traceTarget).find((t) => t !== undefined);
                if (target) void area.open(target.path, target.range, false);
            });
        } catch (error) {
            notify('error', `The diagram failed: ${error instanceof Error ? error.message : String(error)}`);
        }
    }
    updateDiagram(area.activePath, true);
    hooks.timings.diagram = performance.now();

    // The simulate panel (a chunk of its own: roslib and the plots load with it).
    const simulateContainer = byId('simulate-panel');
    try {
        const { mountSimulatePanel } = await import('./simulate/index.js');
        mountSimulatePanel(simulateContainer, { diagram, apps: () => api.apps(), notify });
    } catch (error) {
        simulateContainer.append(h('div', { class: 'empty' }, `The simulate panel failed: ${String(error)}`));
    }

    // Commands and shortcuts.
    area.editor.addAction({
        id: 'maa.showGeneratedCode',
        label: 'Show Generated Code',
        contextMenuGroupId: 'navigation',
        contextMenuOrder: 9,
        keybindings: [monaco.KeyMod.CtrlCmd | monaco.KeyMod.Alt | monaco.KeyCode.KeyG],
        run: (editor) => {
            const path = area.activePath;
            const position = editor.getPosition();
            if (path && position) void generate.showGeneratedFor(path, { line: position.lineNumber - 1, character: position.column - 1 });
        },
    });
    area.editor.addAction({
        id: 'maa.save',
        label: 'File: Save',
        keybindings: [monaco.KeyMod.CtrlCmd | monaco.KeyCode.KeyS],
        run: () => save(),
    });
    const quickOpen = new QuickOpen(
        () => files,
        (path) => void area.open(path),
    );
    function save(): void {
        area.save().catch((error: unknown) => notify('error', error instanceof Error ? error.message : String(error)));
    }
    // Capture phase on the window, and the event stops here: VS Code's keybinding service binds
    // the same keys (Ctrl+P opens its own quick input, Ctrl+S its save) and must not see them too.
    window.addEventListener(
        'keydown',
        (e) => {
            const mod = e.ctrlKey || e.metaKey;
            const key = e.key.toLowerCase();
            let handled = true;
            if (mod && !e.shiftKey && key === 's') save();
            else if (mod && !e.shiftKey && key === 'p') quickOpen.show();
            else if (mod && e.shiftKey && key === 'm') showPanel('problems');
            else if (e.altKey && key === 'w' && area.activePath) area.close(area.activePath);
            else handled = false;
            if (handled) {
                e.preventDefault();
                e.stopImmediatePropagation();
            }
        },
        true,
    );
    window.addEventListener('beforeunload', (e) => {
        if (area.openPaths().some((p) => area.isDirty(p))) e.preventDefault();
    });

    hooks.ready = true;
    hooks.timings.ready = performance.now();
    document.body.dataset.ready = 'true';
    notify('info', `Ready in ${Math.round(hooks.timings.ready - hooks.timings.start)} ms`);
}

main().catch((error: unknown) => {
    console.error(error);
    notify('error', `The workbench failed to start: ${error instanceof Error ? error.message : String(error)}`);
});
