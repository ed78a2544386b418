// Typing in the browser IDE: the language server of the Web Worker entry (started in-process on a
// MessageChannel, the workspace over the backend's HTTP API), ToastServiceRobot.arc and every other
// model file open as in the IDE, its diagram shown, and quick successive edits, each followed by
// the outline request (`textDocument/documentSymbol`) that Monaco sends for sticky scroll, the
// breadcrumbs and the outline. A request must not read a document that a change has just reset
// below DocumentState.ComputedScopes: the outline's details resolve references (the type of each
// subcomponent), and doing that before the document is linked made Langium warn "Attempted
// reference resolution before document reached ComputedScopes state" on every keystroke, and
// filled the family's name index from the stale index of the edited file, so the application
// configuration (TR.arcapp) was linked to the component as it was before the change.
//
// The server's build is held (through an update listener, which the DocumentBuilder awaits) at
// the moment a keystroke has reset the document, so the request always meets the document in that
// state, as it does in the IDE whenever the keystrokes are faster than the builds.
import { cpSync, mkdtempSync, readFileSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { MessageChannel } from 'node:worker_threads';
import { DocumentState, URI, type AstNode, type LangiumDocument } from 'langium';
import { afterAll, beforeAll, describe, expect, test, vi, type MockInstance } from 'vitest';
import {
    BrowserMessageReader,
    BrowserMessageWriter,
    createProtocolConnection,
    type Diagnostic,
    type DocumentSymbol,
    type ProtocolConnection,
} from 'vscode-languageserver-protocol/browser.js';
import { startBrowserLanguageServer, type BrowserLanguageServer } from '../src/browser/server.js';
import { serveWorkspace, type WorkspaceServer } from './browser-helpers.js';
import { EXAMPLE, exampleFiles } from './diagram-helpers.js';

const WS = 'file:///workspace/toast-service';
const ROBOT = `${WS}/toast/ToastServiceRobot.arc`;
const APP = `${WS}/TR.arcapp`;
const STALE_WARNING = 'Attempted reference resolution before document reached ComputedScopes state';

let dir = '';
let http: WorkspaceServer | undefined;
let channel: MessageChannel | undefined;
let connection: ProtocolConnection | undefined;
let server: BrowserLanguageServer;
let warn: MockInstance<typeof console.warn>;
const warnings: string[] = [];
const diagnostics = new Map<string, Diagnostic[]>();
const diagramActions: string[] = [];
let text = '';
let version = 1;

/** While closed, holds the server's update of ToastServiceRobot.arc after its reset, before its build. */
const gate = {
    closed: false,
    /** Called by the server's update listener once it holds an update. */
    entered: (): void => undefined,
    /** Lets the held update go on. */
    open: (): void => undefined,
};

function client(): ProtocolConnection {
    if (!connection) throw new Error('no connection');
    return connection;
}

async function until<T>(what: string, probe: () => T | undefined, timeout = 60_000): Promise<T> {
    const deadline = Date.now() + timeout;
    for (;;) {
        const v = probe();
        if (v !== undefined) return v;
        if (Date.now() > deadline) throw new Error(`timed out waiting for ${what}`);
        await new Promise((r) => setTimeout(r, 20));
    }
}

function robotDocument(): LangiumDocument {
    const doc = server.family.shared.workspace.LangiumDocuments.getDocument(URI.parse(ROBOT));
    if (!doc) throw new Error('no ToastServiceRobot.arc');
    return doc;
}

/**
 * One keystroke: the change, and the outline request while the server has reset the document
 * for that change and not rebuilt it yet. Resolves with the outline.
 */
async function keystroke(change: (text: string) => string): Promise<DocumentSymbol[]> {
    const entered = new Promise<void>((r) => {
        gate.entered = r;
    });
    gate.closed = true;
    text = change(text);
    await client().sendNotification('textDocument/didChange', {
        textDocument: { uri: ROBOT, version: ++version },
        contentChanges: [{ text }],
    });
    await entered;
    expect(robotDocument().state).toBe(DocumentState.Changed);
    const outline = client().sendRequest('textDocument/documentSymbol', { textDocument: { uri: ROBOT } }) as Promise<DocumentSymbol[]>;
    // The server handles messages in order: once an unknown request is answered, the outline
    // request has been received and waits for the document state its handler requires.
    await client()
        .sendRequest('maa/test-barrier')
        .catch(() => undefined);
    gate.closed = false;
    gate.open();
    return outline;
}

function symbolsNamed(symbols: readonly DocumentSymbol[], name: string): DocumentSymbol[] {
    return symbols.flatMap((s) => [...(s.name === name ? [s] : []), ...symbolsNamed(s.children ?? [], name)]);
}

/** The component TR.arcapp is linked to, and the component ToastServiceRobot.arc has now. */
function applicationTarget(): { linked: AstNode | undefined; current: AstNode | undefined } {
    const app = server.family.shared.workspace.LangiumDocuments.getDocument(URI.parse(APP))!;
    const root = app.parseResult.value as AstNode & { application?: { component: { ref?: AstNode } } };
    return {
        linked: root.application?.component.ref,
        current: (robotDocument().parseResult.value as AstNode & { component?: AstNode }).component,
    };
}

beforeAll(async () => {
    dir = mkdtempSync(join(tmpdir(), 'maa-typing-'));
    cpSync(EXAMPLE, join(dir, 'toast-service'), { recursive: true });
    http = await serveWorkspace(dir);
    channel = new MessageChannel();
    server = startBrowserLanguageServer(channel.port2 as unknown as ConstructorParameters<typeof BrowserMessageReader>[0], {
        apiBase: http.url,
    });
    server.family.shared.workspace.DocumentBuilder.onUpdate(async (changed) => {
        if (!gate.closed || !changed.some((u) => u.toString() === ROBOT)) return;
        const held = new Promise<void>((r) => {
            gate.open = r;
        });
        gate.entered();
        await held;
    });
    const port = channel.port1 as unknown as ConstructorParameters<typeof BrowserMessageReader>[0];
    connection = createProtocolConnection(new BrowserMessageReader(port), new BrowserMessageWriter(port));
    connection.onNotification('textDocument/publishDiagnostics', (p: { uri: string; diagnostics: Diagnostic[] }) => {
        diagnostics.set(p.uri, p.diagnostics);
    });
    connection.onNotification('diagram/accept', (m: { action: { kind: string } }) => {
        diagramActions.push(m.action.kind);
    });
    connection.listen();

    await connection.sendRequest('initialize', {
        processId: null,
        rootUri: 'file:///workspace/',
        workspaceFolders: [{ uri: 'file:///workspace/', name: 'workspace' }],
        capabilities: {},
        initializationOptions: { apiBase: http.url },
    });
    await connection.sendNotification('initialized', {});
    await until('the workspace build', () => diagnostics.get(ROBOT) && diagnostics.get(APP));

    // As the IDE: every model file open in the editor, the robot's diagram shown.
    text = readFileSync(join(dir, 'toast-service', 'toast', 'ToastServiceRobot.arc'), 'utf8');
    await connection.sendNotification('textDocument/didOpen', { textDocument: { uri: ROBOT, languageId: 'arc', version, text } });
    for (const [path, content] of Object.entries(exampleFiles(join(dir, 'toast-service')))) {
        const uri = `${WS}/${path}`;
        if (uri === ROBOT) continue;
        await connection.sendNotification('textDocument/didOpen', {
            textDocument: { uri, languageId: path.substring(path.lastIndexOf('.') + 1), version: 1, text: content },
        });
    }
    await connection.sendNotification('diagram/accept', {
        clientId: 'diagram-1',
        action: { kind: 'requestModel', requestId: 'r1', options: { diagramType: 'maa-cc', sourceUri: ROBOT, needsClientLayout: false } },
    });
    await until('the diagram', () => (diagramActions.includes('setModel') ? true : undefined));
    await server.family.shared.workspace.DocumentBuilder.waitUntil(DocumentState.Validated, URI.parse(APP));

    warn = vi.spyOn(console, 'warn').mockImplementation((...args: unknown[]) => {
        // The stack says which code resolved the reference.
        warnings.push(`${args.map(String).join(' ')}\n${new Error('stack').stack ?? ''}`);
    });
});

afterAll(async () => {
    warn?.mockRestore();
    connection?.dispose();
    channel?.port1.close();
    channel?.port2.close();
    await http?.close();
    if (dir) rmSync(dir, { recursive: true, force: true });
});

describe('typing in ToastServiceRobot.arc (browser language server, diagram open)', () => {
    test('a comment typed after "ArmController arm;": the outline waits for the linked document, the application links to the new component', async () => {
        const after = 'ArmController arm;';
        let outline: DocumentSymbol[] = [];
        for (const ch of ' // the arm') {
            outline = await keystroke((t) => t.replace(/ArmController arm;[^\n]*/, (line) => line + ch));
        }
        expect(text).toContain(`${after} // the arm\n`);
        expect(warnings.filter((w) => w.includes(STALE_WARNING))).toEqual([]);
        // The outline of the edited text, with the subcomponents' types.
        expect(symbolsNamed(outline, 'arm').map((s) => s.detail)).toEqual(['ArmController']);
        expect(symbolsNamed(outline, 'ctrl').map((s) => s.detail)).toEqual(['Controller']);
        // TR.arcapp is relinked after each change of its root component: to the component of
        // the current text, not the one of the previous keystroke.
        await server.family.shared.workspace.DocumentBuilder.waitUntil(DocumentState.Validated, URI.parse(APP));
        const target = applicationTarget();
        expect(target.linked !== undefined, 'TR.arcapp resolves its component').toBe(true);
        // (Compared by identity: a diff of two ASTs would print the whole workspace.)
        expect(target.linked === target.current, 'TR.arcapp is linked to the component of the current text').toBe(true);
        // Diagnostics and the diagram follow the edits.
        await until('diagnostics of the edited robot', () => (robotDocument().state === DocumentState.Validated ? true : undefined));
        expect(diagnostics.get(ROBOT)).toEqual([]);
        expect(diagnostics.get(APP)).toEqual([]);
        await until('a diagram update', () => (diagramActions.includes('updateModel') ? true : undefined));
    });

    test('a subcomponent typed on a new line (its type unresolved while typing): no resolution before the document is linked', async () => {
        warnings.length = 0;
        let outline: DocumentSymbol[] = [];
        const line = /ArmController arm;[^\n]*/.exec(text)![0];
        let typed = '';
        for (const ch of '\n  ArmC spare;') {
            outline = await keystroke((t) => t.replace(line + typed, line + typed + ch));
            typed += ch;
        }
        expect(text).toContain(`${line}\n  ArmC spare;\n\n`);
        expect(warnings.filter((w) => w.includes(STALE_WARNING))).toEqual([]);
        expect(symbolsNamed(outline, 'spare').map((s) => s.detail)).toEqual(['ArmC']);
        // The document is still checked as before: the type being typed is reported unresolved.
        const robot = await until('the unresolved type reported', () =>
            diagnostics.get(ROBOT)?.some((d) => d.code === 'arc/missing-component-type') ? diagnostics.get(ROBOT) : undefined,
        );
        expect(robot.map((d) => `${d.range.start.line + 1} ${d.code}`)).toEqual(['19 arc/missing-component-type']);
        await server.family.shared.workspace.DocumentBuilder.waitUntil(DocumentState.Validated, URI.parse(APP));
        const target = applicationTarget();
        expect(target.linked === target.current, 'TR.arcapp is linked to the component of the current text').toBe(true);
    });
});
