// The diagram's extension side without an editor: the relay between webviews and the language
// server (real Sprotty action messages, and the real diagram server of the built language
// server over stdio: two webviews whose diagrams share one client id each get their own model,
// an edit of the model updates the diagram, the selection's trace leads back to the source), the
// cursor → component/automaton lookup on the server's real document symbols, the webview
// message checks, the page's CSP, and the icons in the manifest contributions.
import { type ChildProcessWithoutNullStreams, spawn } from 'node:child_process';
import { cpSync, existsSync, mkdtempSync, readFileSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import path from 'node:path';
import { fileURLToPath, pathToFileURL } from 'node:url';
import { LANGUAGE_FACTS } from '@maa/language-server/language-facts';
import {
    type ActionMessage,
    RequestModelAction,
    SelectAction,
    type SModelElement,
    type SModelRoot,
    SetModelAction,
} from 'sprotty-protocol';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import {
    createProtocolConnection,
    DidChangeTextDocumentNotification,
    DidOpenTextDocumentNotification,
    type DocumentSymbol,
    DocumentSymbolRequest,
    InitializedNotification,
    InitializeRequest,
    NotificationType,
    type ProtocolConnection,
    PublishDiagnosticsNotification,
    StreamMessageReader,
    StreamMessageWriter,
    SymbolKind,
} from 'vscode-languageserver-protocol/node.js';
import { contributions } from '../src/contributions.js';
import { iconFiles, languageIconOf } from '../src/diagram/contributions.js';
import { contentSecurityPolicy, newNonce, webviewHtml } from '../src/diagram/html.js';
import { highlightMessage, packServerAction, parseFromWebview, unpackServerAction } from '../src/diagram/protocol.js';
import { DiagramRelay } from '../src/diagram/relay.js';
import { componentAt, inAutomaton, packageOf, selectionSource, type SymbolNode, targetAt } from '../src/diagram/selection.js';

const repo = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..', '..', '..');
const serverMain = path.join(repo, 'packages', 'language-server', 'dist', 'node', 'main.js');
const DiagramAccept = new NotificationType<ActionMessage>('diagram/accept');
const DiagramDidClose = new NotificationType<string>('diagram/didClose');

/** A webview as the relay sees it: what was delivered to it, and a wait for the next delivery that matches. */
class FakeWebview {
    readonly delivered: ActionMessage[] = [];
    private waiters: Array<{ match: (m: ActionMessage) => boolean; resolve: (m: ActionMessage) => void }> = [];

    readonly deliver = (message: ActionMessage): void => {
        this.delivered.push(message);
        const hit = this.waiters.filter((w) => w.match(message));
        this.waiters = this.waiters.filter((w) => !w.match(message));
        for (const w of hit) w.resolve(message);
    };

    next(match: (m: ActionMessage) => boolean): Promise<ActionMessage> {
        const already = this.delivered.find(match);
        if (already) return Promise.resolve(already);
        return new Promise((resolve) => this.waiters.push({ match, resolve }));
    }
}

function requestModel(clientId: string, sourceUri: string, diagramType: string, component?: string): ActionMessage {
    const options: Record<string, string | boolean> = { diagramType, sourceUri, needsClientLayout: false, needsServerLayout: true };
    if (component) options['component'] = component;
    return { clientId, action: RequestModelAction.create(options) };
}

function rootOf(message: ActionMessage): SModelRoot & Record<string, unknown> {
    return (message.action as SetModelAction).newRoot as SModelRoot & Record<string, unknown>;
}

function* elements(e: SModelElement): Generator<SModelElement & Record<string, unknown>> {
    yield e as SModelElement & Record<string, unknown>;
    for (const c of e.children ?? []) yield* elements(c);
}

describe('the diagram relay', () => {
    it('gives the clients of different webviews their own server-side ids and delivers each answer to its webview only', () => {
        const relay = new DiagramRelay();
        const a = new FakeWebview();
        const b = new FakeWebview();
        relay.addPanel('p1', a.deliver);
        relay.addPanel('p2', b.deliver);
        // Both webviews mount their diagram first, so both Sprotty containers are `maa-diagram-1`.
        const requestA = requestModel('maa-diagram-1', 'file:///w/A.arc', 'maa-cc');
        const fromA = relay.toServer('p1', requestA);
        const fromB = relay.toServer('p2', requestModel('maa-diagram-1', 'file:///w/B.arc', 'maa-cc'));
        expect(fromA.clientId).not.toBe(fromB.clientId);
        expect(fromA.action).toEqual(requestA.action);
        expect(requestA.clientId).toBe('maa-diagram-1');

        const answer = SetModelAction.create({ type: 'graph', id: 'graph' }, { requestId: (fromB.action as RequestModelAction).requestId });
        expect(relay.fromServer({ clientId: fromB.clientId, action: answer })).toBe(true);
        expect(a.delivered).toEqual([]);
        expect(b.delivered).toEqual([{ clientId: 'maa-diagram-1', action: answer }]);
    });

    it('drops messages of unknown clients and closes the clients of a removed webview', () => {
        const relay = new DiagramRelay();
        const a = new FakeWebview();
        relay.addPanel('p1', a.deliver);
        const sent = relay.toServer('p1', {
            clientId: 'maa-diagram-1',
            action: SelectAction.create({ selectedElementsIDs: ['root.ctrl'] }),
        });
        expect(relay.fromServer({ clientId: 'other-front-end', action: SelectAction.create({}) })).toBe(false);
        expect(relay.removePanel('p1')).toEqual([sent.clientId]);
        expect(relay.fromServer({ clientId: sent.clientId, action: SelectAction.create({}) })).toBe(false);
        expect(a.delivered).toEqual([]);
        expect(() => relay.toServer('p1', sent)).toThrow(/no diagram webview/);
        expect(() => relay.addPanel('a/b', a.deliver)).toThrow();
    });
});

describe('the relay with the language server diagram server', () => {
    let tmp = '';
    let proc: ChildProcessWithoutNullStreams | undefined;
    let connection: ProtocolConnection;
    const relay = new DiagramRelay();
    const published = new Map<string, () => void>();

    beforeAll(async () => {
        if (!existsSync(serverMain)) throw new Error(`${serverMain} is missing: build the language server first`);
        tmp = mkdtempSync(path.join(tmpdir(), 'maa-vscode-diagram-'));
        cpSync(path.join(repo, 'examples', 'toast-service'), tmp, { recursive: true });
        proc = spawn(process.execPath, [serverMain, '--stdio'], { stdio: 'pipe' });
        connection = createProtocolConnection(new StreamMessageReader(proc.stdout), new StreamMessageWriter(proc.stdin));
        // The extension's wiring (src/diagram/index.ts): every diagram/accept goes through the relay.
        connection.onNotification(DiagramAccept, (m) => relay.fromServer(m));
        connection.onNotification(PublishDiagnosticsNotification.type, (p) => published.get(p.uri)?.());
        connection.onRequest('client/registerCapability', () => null);
        connection.onRequest('workspace/configuration', () => []);
        connection.listen();
        const root = pathToFileURL(tmp).toString();
        await connection.sendRequest(InitializeRequest.type, {
            processId: process.pid,
            rootUri: root,
            workspaceFolders: [{ uri: root, name: 'ws' }],
            capabilities: { textDocument: { documentSymbol: { hierarchicalDocumentSymbolSupport: true } } },
        });
        await connection.sendNotification(InitializedNotification.type, {});
    }, 120_000);

    afterAll(() => {
        connection?.dispose();
        if (proc && proc.exitCode === null && proc.signalCode === null) proc.kill();
        if (tmp) rmSync(tmp, { recursive: true, force: true });
    });

    it('routes models, updates after an edit, and leads a selection back to its source', async () => {
        const file = path.join(tmp, 'toast', 'Controller.arc');
        const uri = pathToFileURL(file).toString();
        const text = readFileSync(file, 'utf8');
        const checked = new Promise<void>((resolve) => published.set(uri, resolve));
        await connection.sendNotification(DidOpenTextDocumentNotification.type, {
            textDocument: { uri, languageId: 'arc', version: 1, text },
        });
        await checked;

        const cc = new FakeWebview();
        const automaton = new FakeWebview();
        relay.addPanel('w1', cc.deliver);
        relay.addPanel('w2', automaton.deliver);
        await connection.sendNotification(DiagramAccept, relay.toServer('w1', requestModel('maa-diagram-1', uri, 'maa-cc')));

        // Open Automaton View with the cursor on a state: the target from the server's real outline.
        const symbols = (await connection.sendRequest(DocumentSymbolRequest.type, { textDocument: { uri } })) as DocumentSymbol[];
        const cursor = { line: text.split('\n').findIndex((l) => l.includes('state Toasting;')), character: 10 };
        const target = targetAt(uri, symbols, cursor, text, SymbolKind.Class, true);
        expect(target).toEqual({ uri, component: 'toast.Controller', diagramType: 'maa-automaton' });
        await connection.sendNotification(
            DiagramAccept,
            relay.toServer('w2', requestModel('maa-diagram-1', uri, 'maa-automaton', target?.component)),
        );

        const ccModel = rootOf(await cc.next((m) => m.action.kind === 'setModel'));
        const automatonModel = rootOf(await automaton.next((m) => m.action.kind === 'setModel'));
        expect(cc.delivered.every((m) => m.clientId === 'maa-diagram-1')).toBe(true);
        expect(ccModel['component']).toBe('toast.Controller');
        expect(automatonModel).toMatchObject({ id: 'automaton:toast.Controller', component: 'toast.Controller' });
        const states = [...elements(automatonModel)].filter((e) => e.type === 'node:state').map((e) => e.id);
        expect(states).toEqual(expect.arrayContaining(['state:Idle', 'state:Toasting']));
        expect(cc.delivered.some((m) => m.action.kind === 'setModel' && rootOf(m) === automatonModel)).toBe(false);

        // Selection diagram → editor: the trace of a port leads to its declaration in the file.
        const port = [...elements(ccModel)].find((e) => typeof e['trace'] === 'string' && e.type === 'port');
        const source = selectionSource([String(port?.['trace'])]);
        expect(source?.uri).toBe(decodeURIComponent(uri));
        const line = text.split('\n')[source?.range.start.line ?? -1] ?? '';
        expect(line).toMatch(/\bport\b|\bin\b|\bout\b/);

        // The diagram follows the text: an edit brings an update to the architecture webview.
        const updated = cc.next((m) => m.action.kind === 'updateModel');
        await connection.sendNotification(DidChangeTextDocumentNotification.type, {
            textDocument: { uri, version: 2 },
            contentChanges: [{ text: text.replace('in int distance,', 'in int distance, in int extra,') }],
        });
        const ports = [...elements(rootOf(await updated))].map((e) => e.id);
        expect(ports.some((id) => id.endsWith('extra'))).toBe(true);

        // Closing a webview frees its diagram servers; the other keeps its own.
        for (const clientId of relay.removePanel('w2')) await connection.sendNotification(DiagramDidClose, clientId);
        expect(relay.panelIds()).toEqual(['w1']);
    }, 120_000);
});

describe('the cursor lookups', () => {
    const range = (a: number, b: number, c: number, d: number) => ({ start: { line: a, character: b }, end: { line: c, character: d } });
    const symbols: SymbolNode[] = [
        {
            name: 'Outer',
            kind: 5,
            range: range(2, 0, 20, 1),
            children: [
                { name: 'x', kind: 7, range: range(3, 2, 3, 10), children: [] },
                {
                    name: 'Inner',
                    kind: 5,
                    range: range(5, 2, 12, 3),
                    children: [{ name: 'automaton', kind: 3, range: range(6, 4, 11, 5), children: [] }],
                },
            ],
        },
    ];

    it('finds the innermost component, qualified by the package, and whether the cursor is in an automaton', () => {
        expect(componentAt(symbols, { line: 8, character: 6 }, 'demo', 5)).toBe('demo.Outer.Inner');
        expect(componentAt(symbols, { line: 3, character: 4 }, '', 5)).toBe('Outer');
        expect(componentAt(symbols, { line: 25, character: 0 }, 'demo', 5)).toBeUndefined();
        expect(inAutomaton(symbols, { line: 8, character: 6 })).toBe(true);
        expect(inAutomaton(symbols, { line: 5, character: 3 })).toBe(false);
        expect(targetAt('file:///a.arc', symbols, { line: 3, character: 4 }, 'package demo;', 5, true)).toBeUndefined();
        expect(targetAt('file:///a.arc', symbols, { line: 30, character: 0 }, '', 5, false)).toEqual({
            uri: 'file:///a.arc',
            diagramType: 'maa-cc',
        });
    });

    it('reads the package past comments', () => {
        expect(packageOf('/* package no; */\n// package nope;\npackage a.b.c;\ncomponent X {}')).toBe('a.b.c');
        expect(packageOf('component X {}')).toBe('');
    });

    it('takes the first selected element with a valid trace', () => {
        expect(selectionSource(['no trace', 'file:///w/a%20b.arc?1%3A2-3%3A4#/x'])).toEqual({
            uri: 'file:///w/a b.arc',
            range: range(1, 2, 3, 4),
        });
        expect(selectionSource(['file:///w/a.arc'])).toBeUndefined();
    });
});

describe('the webview messages and page', () => {
    it('accepts the webview messages of the protocol and nothing else', () => {
        const message: ActionMessage = { clientId: 'maa-diagram-1', action: SelectAction.create({ selectedElementsIDs: ['a'] }) };
        expect(parseFromWebview({ type: 'action', message })).toEqual({ type: 'action', message });
        expect(parseFromWebview({ type: 'ready' })).toEqual({ type: 'ready' });
        expect(parseFromWebview({ type: 'select', traces: ['t'] })).toEqual({ type: 'select', traces: ['t'] });
        expect(parseFromWebview({ type: 'saveSvg', svg: '<svg/>', fileName: 'a.svg' })).toMatchObject({ type: 'saveSvg' });
        for (const bad of [
            null,
            'ready',
            { type: 'action', message: { action: { kind: 'x' } } },
            { type: 'action', message: { clientId: 'c', action: {} } },
            { type: 'select', traces: [1] },
            { type: 'saveSvg', svg: 1, fileName: 'a' },
            { type: 'run', command: 'rm' },
        ]) {
            expect(parseFromWebview(bad)).toBeUndefined();
        }
    });

    it("carries a server model's root as JSON text beside its action, and other actions unchanged (issue 18)", () => {
        const root = {
            type: 'graph',
            id: 'g',
            revision: 3,
            children: [{ type: 'node:component', id: 'root.a', size: { width: 10, height: 5 } }],
        };
        for (const kind of ['setModel', 'updateModel']) {
            const message = { clientId: 'maa-diagram-1', action: { kind, newRoot: root, animate: true } } as unknown as ActionMessage;
            const packed = packServerAction(message);
            // the posted message holds no object tree of the model: the text is what is copied into the webview
            expect(packed.model).toBe(JSON.stringify(root));
            expect(packed.message.action).toEqual({ kind, animate: true });
            expect(packed.message.clientId).toBe('maa-diagram-1');
            // a message listener in the webview still sees which action it is
            expect(packed.message.action.kind).toBe(kind);
            expect(unpackServerAction(structuredClone(packed))).toEqual(message);
        }
        const select: ActionMessage = { clientId: 'maa-diagram-1', action: SelectAction.create({ selectedElementsIDs: ['a'] }) };
        expect(packServerAction(select)).toEqual({ type: 'action', message: select });
        expect(unpackServerAction({ type: 'action', message: select })).toBe(select);
    });

    it('turns the argument of maa.diagram.highlightTrace into the highlight message, undefined into clear, and rejects others', () => {
        const point = {
            component: 'toast.Controller',
            instancePath: 'ctrl',
            state: 'Serving',
            transition: { from: 'Toasting', to: 'Serving', index: 3 },
        };
        expect(highlightMessage(point)).toEqual({ type: 'highlight', highlight: point });
        expect(highlightMessage(undefined)).toEqual({ type: 'highlight' });
        expect(() => highlightMessage({ instancePath: 'ctrl' })).toThrow(/component/);
        expect(() => highlightMessage({ ...point, transition: { from: 'A', to: 'B', index: '3' } })).toThrow(/index/);
    });

    it('has a strict CSP: nothing by default, the script only with the nonce, no inline code', () => {
        const nonce = newNonce();
        expect(nonce).toMatch(/^[0-9a-f]{32}$/);
        expect(newNonce()).not.toBe(nonce);
        const csp = contentSecurityPolicy('https://res.example', nonce);
        expect(csp).toContain("default-src 'none'");
        expect(csp).toContain(`script-src 'nonce-${nonce}'`);
        expect(csp).not.toMatch(/unsafe-(inline|eval)/);
        const html = webviewHtml({
            cspSource: 'https://res.example',
            nonce,
            scriptUri: 'https://res.example/diagram.js',
            styleUri: 'https://res.example/diagram.css',
        });
        expect(html).toContain(`<script nonce="${nonce}" src="https://res.example/diagram.js"></script>`);
        expect(html.match(/<script/g)).toHaveLength(1);
        expect(html).toContain('id="maa-diagram-root"');
    });
});

describe('the diagram commands in the manifest', () => {
    it('show their buttons and palette entries on component files only, and only where an entry registered the diagram', () => {
        const menus = contributions(LANGUAGE_FACTS).contributes['menus'] as Record<string, Array<{ command: string; when: string }>>;
        const diagramEntries = Object.values(menus)
            .flat()
            .filter((m) => ['maa.openDiagram', 'maa.openAutomatonView', 'maa.exportDiagramSvg'].includes(m.command));
        expect(menus['editor/title']?.map((m) => m.command).filter((c) => c.startsWith('maa.open'))).toEqual([
            'maa.openDiagram',
            'maa.openAutomatonView',
        ]);
        for (const m of diagramEntries) expect(m.when, m.command).toMatch(/maa\.diagramAvailable|maa\.diagramOpen/);
        for (const m of diagramEntries.filter((e) => e.command !== 'maa.exportDiagramSvg')) expect(m.when).toMatch(/LangId == 'arc'/);
        expect(
            diagramEntries.filter((m) => m.command === 'maa.openAutomatonView').every((m) => m.when.includes('maa.cursorInAutomaton')),
        ).toBe(true);
    });
});

describe('the language icons', () => {
    it('gives every file language of the family a light and a dark icon, written with the manifest', () => {
        const c = contributions(LANGUAGE_FACTS);
        const languages = c.contributes['languages'] as Array<{ id: string; icon: { light: string; dark: string } }>;
        const files = new Map(c.files.map((f) => [`./${f.path}`, f.content]));
        const fileLanguages = LANGUAGE_FACTS.languages.filter((l) => l.kind === 'file');
        expect(languages.map((l) => l.id)).toEqual(fileLanguages.map((l) => l.id));
        for (const l of languages) {
            for (const icon of [l.icon.light, l.icon.dark]) {
                const svg = files.get(icon);
                expect(typeof svg, icon).toBe('string');
                expect(String(svg)).toMatch(
                    /^<svg xmlns="http:\/\/www\.w3\.org\/2000\/svg" width="16" height="16" viewBox="0 0 16 16">.*<\/svg>\n$/s,
                );
            }
            expect(files.get(l.icon.light)).not.toBe(files.get(l.icon.dark));
        }
        // A language the family gains later gets a page with its extension.
        const later = languageIconOf({ id: 'newlang', fileExtensions: ['.nl'] });
        const svg = iconFiles([{ id: 'newlang', fileExtensions: ['.nl'] }]).find((f) => `./${f.path}` === later.light)?.content;
        expect(svg).toContain('>nl</text>');
    });
});
