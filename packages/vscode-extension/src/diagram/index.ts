/**
 * The diagram in VS Code: **MontiArc: Open Diagram** (also the editor title button of model
 * files), **MontiArc: Open Automaton View** (the cursor in an automaton) and **MontiArc: Export
 * Diagram as SVG**; the panel follows the active model file and the cursor, and the rest of the
 * extension pushes a simulation's live values and active states into it ({@link showLiveValues},
 * {@link showActiveStates}).
 */
import type { DiagramTarget } from '@maa/diagram-view/contracts';
import type { ActionMessage } from 'sprotty-protocol';
import * as vscode from 'vscode';
import { openOnStart } from './contributions.js';
import { type DiagramChannel, DiagramPanel } from './panel.js';
import { highlightMessage, type ToWebview } from './protocol.js';
import { DiagramRelay } from './relay.js';
import { inAutomaton, type SymbolNode, targetAt } from './selection.js';

/** What the diagram needs of the language client (vscode-languageclient's `LanguageClient` has it). */
export interface DiagramClient extends DiagramChannel {
    onNotification(method: string, handler: (params: ActionMessage) => void): vscode.Disposable;
}

/** The languages with diagrams (component files). */
const DIAGRAM_LANGUAGES = new Set(['arc']);
/** The context key of the Open Automaton View button and command. */
const IN_AUTOMATON = 'maa.cursorInAutomaton';
/** The context key of Export Diagram as SVG. */
const DIAGRAM_OPEN = 'maa.diagramOpen';

const relay = new DiagramRelay();
let panel: DiagramPanel | undefined;
/** The trace point highlighted last (a diagram opened later shows it too). */
let highlighted: Extract<ToWebview, { type: 'highlight' }> = { type: 'highlight' };

/** Values as a list of pairs, from a map or a plain object. */
function entries(values: ReadonlyMap<string, string> | Readonly<Record<string, string>>): Array<[string, string]> {
    return values instanceof Map ? [...values] : Object.entries(values);
}

/**
 * Shows live port values in the open diagram, by port path as the diagram names ports
 * (`"ctrl.arm"` → `"12"`); an empty map clears them. Returns false when no diagram is open.
 */
export function showLiveValues(values: ReadonlyMap<string, string> | Readonly<Record<string, string>>): boolean {
    panel?.post({ type: 'liveValues', values: entries(values) });
    return panel !== undefined;
}

/**
 * The command `maa.diagram.highlightTrace`: highlights a run's trace point in the open diagram
 * until the next one (`undefined` clears): the state and the transition taken in the automaton
 * view of `component`, the state chip of `instancePath` in C&C views (docs/vscode.md). Throws on
 * an argument that is not a highlight. Returns false when no diagram is open.
 */
export function highlightTrace(argument: unknown): boolean {
    highlighted = highlightMessage(argument);
    panel?.post(highlighted);
    return panel !== undefined;
}

/**
 * Marks the current automaton state (or mode) of each instance in the open diagram, by instance
 * path (`"ctrl"` → `"Toasting"`); an empty map clears them. Returns false when no diagram is open.
 */
export function showActiveStates(states: ReadonlyMap<string, string> | Readonly<Record<string, string>>): boolean {
    panel?.post({ type: 'activeStates', states: entries(states) });
    return panel !== undefined;
}

async function symbolsOf(document: vscode.TextDocument): Promise<SymbolNode[]> {
    const symbols = await vscode.commands.executeCommand<vscode.DocumentSymbol[] | undefined>(
        'vscode.executeDocumentSymbolProvider',
        document.uri,
    );
    // The provider answers with DocumentSymbols (hierarchical) for this server; SymbolInformation has no children.
    return (symbols ?? []).filter((s) => Array.isArray(s.children));
}

/** The diagram of the component (or automaton) at the editor's cursor. */
async function targetOf(editor: vscode.TextEditor, automaton: boolean): Promise<DiagramTarget | undefined> {
    const { document } = editor;
    const position = editor.selection.active;
    const symbols = await symbolsOf(document);
    return targetAt(
        document.uri.toString(),
        symbols,
        { line: position.line, character: position.character },
        document.getText(),
        vscode.SymbolKind.Class,
        automaton,
    );
}

function openPanel(context: vscode.ExtensionContext, client: DiagramClient): DiagramPanel {
    if (!panel) {
        panel = new DiagramPanel(context.extensionUri, relay, client, () => {
            panel = undefined;
            void vscode.commands.executeCommand('setContext', DIAGRAM_OPEN, false);
        });
        void vscode.commands.executeCommand('setContext', DIAGRAM_OPEN, true);
        if (highlighted.highlight) panel.post(highlighted);
    }
    return panel;
}

async function openDiagram(context: vscode.ExtensionContext, client: DiagramClient, automaton: boolean, uri?: vscode.Uri): Promise<void> {
    const editor =
        uri && vscode.window.activeTextEditor?.document.uri.toString() !== uri.toString()
            ? await vscode.window.showTextDocument(uri, { preview: false })
            : vscode.window.activeTextEditor;
    if (!editor || !DIAGRAM_LANGUAGES.has(editor.document.languageId)) {
        void vscode.window.showInformationMessage('MontiArc: open a component file (.arc) to show its diagram.');
        return;
    }
    const target = await targetOf(editor, automaton);
    if (!target) {
        void vscode.window.showInformationMessage('MontiArc: the cursor is in no automaton of a component.');
        return;
    }
    openPanel(context, client).show(target);
}

/** The panel follows the active component file (architecture) and the cursor (selection). */
function followEditors(): vscode.Disposable[] {
    let symbolsPending: ReturnType<typeof setTimeout> | undefined;
    const updateAutomatonKey = (editor: vscode.TextEditor | undefined): void => {
        clearTimeout(symbolsPending);
        if (!editor || !DIAGRAM_LANGUAGES.has(editor.document.languageId)) {
            void vscode.commands.executeCommand('setContext', IN_AUTOMATON, false);
            return;
        }
        // Asked once the cursor rests: the outline is the language server's, over IPC.
        symbolsPending = setTimeout(() => {
            const p = editor.selection.active;
            void symbolsOf(editor.document).then((symbols) =>
                vscode.commands.executeCommand('setContext', IN_AUTOMATON, inAutomaton(symbols, { line: p.line, character: p.character })),
            );
        }, 200);
    };
    return [
        vscode.window.onDidChangeActiveTextEditor((editor) => {
            updateAutomatonKey(editor);
            const shown = panel?.current();
            if (!editor || !panel || !DIAGRAM_LANGUAGES.has(editor.document.languageId) || shown?.diagramType !== 'maa-cc') return;
            const uri = editor.document.uri.toString();
            if (shown.uri !== uri) panel.show({ uri, diagramType: 'maa-cc' });
        }),
        vscode.window.onDidChangeTextEditorSelection(({ textEditor, selections }) => {
            updateAutomatonKey(textEditor);
            const active = selections[0]?.active;
            if (!panel || !active || !DIAGRAM_LANGUAGES.has(textEditor.document.languageId)) return;
            panel.revealPosition(textEditor.document.uri.toString(), { line: active.line, character: active.character });
        }),
        { dispose: () => clearTimeout(symbolsPending) },
    ];
}

/** Registers the diagram's commands and the relay of the language server's `diagram/accept` notifications. */
export function registerDiagram(context: vscode.ExtensionContext, client: DiagramClient): void {
    void vscode.commands.executeCommand('setContext', 'maa.diagramAvailable', true);
    context.subscriptions.push(
        client.onNotification('diagram/accept', (message) => relay.fromServer(message)),
        vscode.commands.registerCommand('maa.openDiagram', (uri?: vscode.Uri) => openDiagram(context, client, false, uri)),
        vscode.commands.registerCommand('maa.openAutomatonView', (uri?: vscode.Uri) => openDiagram(context, client, true, uri)),
        vscode.commands.registerCommand('maa.diagram.highlightTrace', (argument?: unknown) => highlightTrace(argument)),
        vscode.commands.registerCommand('maa.exportDiagramSvg', () => {
            if (panel) panel.post({ type: 'exportSvg' });
            else void vscode.window.showInformationMessage('MontiArc: no diagram is open (MontiArc: Open Diagram).');
        }),
        ...followEditors(),
        { dispose: () => panel?.dispose() },
    );
    if (openOnStart((key) => vscode.workspace.getConfiguration().get(key)))
        context.subscriptions.push(openWithFirstComponent(context, client));
}

/**
 * `maa.diagram.openOnStart`: the diagram of the first component file shown, now or when one is
 * (once; a diagram the user closes stays closed).
 */
function openWithFirstComponent(context: vscode.ExtensionContext, client: DiagramClient): vscode.Disposable {
    const isComponent = (editor: vscode.TextEditor | undefined): editor is vscode.TextEditor =>
        editor !== undefined && DIAGRAM_LANGUAGES.has(editor.document.languageId);
    const open = (): void => void openDiagram(context, client, false);
    if (isComponent(vscode.window.activeTextEditor)) {
        open();
        return { dispose: () => undefined };
    }
    const waiting = vscode.window.onDidChangeActiveTextEditor((editor) => {
        if (!isComponent(editor)) return;
        waiting.dispose();
        open();
    });
    return waiting;
}
