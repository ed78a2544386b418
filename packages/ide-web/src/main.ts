/**
 * The workbench shell: starts the VS Code services (monaco-vscode-api, classic mode with
 * Monarch), the language client on the language server Web Worker, and lays out explorer,
 * editor tabs, diagram and the bottom panel (Problems / Generate / Simulate).
 */
import './style.css';
// The services' and the language client's modules first: the packages load in the order they always did.
import { openEditorIn, startServices } from './workbench/services.js';
import { startLanguageClient } from './workbench/language-client.js';
import type { RegisteredFileSystemProvider } from '@codingame/monaco-vscode-files-service-override';
import type { MonacoLanguageClient } from 'monaco-languageclient';
import { DidChangeWatchedFilesNotification, FileChangeType } from 'vscode-languageserver-protocol';
import { api, type FileEntry, uriOf } from './api.js';
import type { TextPosition } from './contracts.js';
import { isModelFile } from './languages.js';
import { mountProblemsPanel, showPanel, wirePanelTabs } from './workbench/bottom-panel.js';
import { registerCommands } from './workbench/commands.js';
import { DiagramPane } from './workbench/diagram-pane.js';
import { basename, byId, h } from './workbench/dom.js';
import { EditorArea } from './workbench/editors.js';
import { Explorer } from './workbench/explorer.js';
import { GeneratePanel } from './workbench/generate.js';
import { hooks } from './workbench/hooks.js';
import { messageOf, notify, setServerStatus } from './workbench/status.js';

/** The first file shown: the example's root component. */
const START_FILE = /(^|\/)ToastServiceRobot\.arc$/;

hooks.timings.start = performance.now();
window.maaIde = hooks;
wirePanelTabs();

/** The editor area once it exists (VS Code's "open editor" goes through it). */
let editors: EditorArea | undefined;
let languageClient: MonacoLanguageClient | undefined;

/** The explorer and the editor area, with the status line, the diagram and the server following the active file. */
function createEditors(workspaceFiles: RegisteredFileSystemProvider, diagram: DiagramPane): { explorer: Explorer; area: EditorArea } {
    const explorer = new Explorer(byId('explorer'), (path) => void area.open(path));
    const cursorStatus = byId('status-cursor');
    const languageStatus = byId('status-language');
    let cursorTimer: ReturnType<typeof setTimeout> | undefined;
    const area: EditorArea = new EditorArea(byId('editor-tabs'), byId('editor'), workspaceFiles, {
        onActiveChanged: (path) => {
            explorer.select(path);
            languageStatus.textContent = path ? (area.editor.getModel()?.getLanguageId() ?? '') : '';
            document.title = path ? `${basename(path)} — MontiArcAutomaton` : 'MontiArcAutomaton';
            diagram.showComponent(path);
        },
        onCursor: (path, position) => {
            cursorStatus.textContent = `Ln ${position.lineNumber}, Col ${position.column}`;
            // Debounced: the diagram follows the cursor once it rests.
            if (cursorTimer) clearTimeout(cursorTimer);
            cursorTimer = setTimeout(() => {
                const p: TextPosition = { line: position.lineNumber - 1, character: position.column - 1 };
                diagram.revealPosition(path, p);
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
    return { explorer, area };
}

function mountGeneratePanel(area: EditorArea, workspacePaths: () => string[]): GeneratePanel {
    return new GeneratePanel(byId('generate-panel'), {
        openModel: (path, range) => void area.open(path, range),
        modelOf: (path) => area.model(path),
        notify,
        reveal: () => showPanel('generate'),
        workspacePaths,
    });
}

/** The workspace's files, its model files and the file to show first. */
interface Workspace {
    entries: FileEntry[];
    files: string[];
    modelFiles: string[];
    start: string | undefined;
}

/** Lists the workspace into the explorer and picks the start file. */
async function loadWorkspace(explorer: Explorer): Promise<Workspace> {
    const listing = await api.files();
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
    return { entries: listing.entries, files, modelFiles, start };
}

/** Starts the language client; a failure is reported, and the workbench goes on without it. */
async function startLanguageClientReporting(): Promise<void> {
    try {
        languageClient = await startLanguageClient();
    } catch (error) {
        setServerStatus('Language server: failed', 'error');
        notify('error', `The language server did not start: ${messageOf(error)}`);
    }
}

/** The start file first (interactive as soon as possible), then every model file (the language server sees the whole workspace). */
async function openModels(area: EditorArea, workspace: Workspace): Promise<void> {
    if (workspace.start) await area.open(workspace.start);
    hooks.timings.editor = performance.now();
    await Promise.all(
        workspace.modelFiles.map(async (path) => {
            try {
                await area.model(path);
            } catch (error) {
                notify('warning', messageOf(error));
            }
        }),
    );
}

/** The simulate panel (a chunk of its own: roslib and the plots load with it). */
async function mountSimulatePane(diagram: DiagramPane): Promise<void> {
    const simulateContainer = byId('simulate-panel');
    try {
        const { mountSimulatePanel } = await import('@maa/simulate-view');
        mountSimulatePanel(simulateContainer, { diagram: diagram.view, apps: () => api.apps(), notify });
    } catch (error) {
        simulateContainer.append(h('div', { class: 'empty' }, `The simulate panel failed: ${String(error)}`));
    }
}

async function main(): Promise<void> {
    const workspaceFiles = await startServices(openEditorIn(() => editors));
    hooks.timings.services = performance.now();

    const diagram = new DiagramPane();
    const { explorer, area } = createEditors(workspaceFiles, diagram);
    mountProblemsPanel(area);
    let workspaceEntries: FileEntry[] = [];
    const generate = mountGeneratePanel(area, () => workspaceEntries.map((e) => e.path));

    const workspace = await loadWorkspace(explorer);
    workspaceEntries = workspace.entries;

    // Language client first, so the documents' didOpen go to the server.
    await startLanguageClientReporting();
    hooks.timings.client = performance.now();

    await openModels(area, workspace);
    hooks.timings.models = performance.now();

    if (languageClient) await diagram.mount(languageClient, area);
    diagram.showComponent(area.activePath, true);
    hooks.timings.diagram = performance.now();

    await mountSimulatePane(diagram);
    registerCommands(area, generate, workspace.files);

    hooks.ready = true;
    hooks.timings.ready = performance.now();
    document.body.dataset.ready = 'true';
    notify('info', `Ready in ${Math.round(hooks.timings.ready - hooks.timings.start)} ms`);
}

main().catch((error: unknown) => {
    console.error(error);
    notify('error', `The workbench failed to start: ${messageOf(error)}`);
});
