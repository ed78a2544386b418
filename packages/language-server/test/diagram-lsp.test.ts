// The diagram server in the real language server process (`node dist/node/main.js --stdio`):
// `diagram/accept` with a RequestModelAction answers with a SetModelAction; an edit of another
// file of the shown component (didChange) brings an UpdateModelAction.
import { spawn, type ChildProcessWithoutNullStreams } from 'node:child_process';
import { cpSync, existsSync, mkdtempSync, readFileSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { dirname, join, resolve } from 'node:path';
import { fileURLToPath, pathToFileURL } from 'node:url';
import { afterAll, beforeAll, describe, expect, test } from 'vitest';
import {
    DidChangeTextDocumentNotification,
    DidOpenTextDocumentNotification,
    InitializedNotification,
    InitializeRequest,
    NotificationType,
    PublishDiagnosticsNotification,
    StreamMessageReader,
    StreamMessageWriter,
    createProtocolConnection,
    type ProtocolConnection,
} from 'vscode-languageserver-protocol/node.js';
import type { ActionMessage, SModelElement, SModelRoot } from 'sprotty-protocol';
import { allElements } from '../src/diagram/index.js';
import { EXAMPLE } from './diagram-helpers.js';

const serverMain = resolve(dirname(fileURLToPath(import.meta.url)), '../dist/node/main.js');
const DiagramAccept = new NotificationType<ActionMessage>('diagram/accept');

let tmp = '';
let proc: ChildProcessWithoutNullStreams;
let connection: ProtocolConnection;
let stderr = '';
const received: ActionMessage[] = [];
const published = new Set<string>();

async function until<T>(what: string, probe: () => T | undefined, timeout = 60_000): Promise<T> {
    const deadline = Date.now() + timeout;
    for (;;) {
        const v = probe();
        if (v !== undefined) return v;
        if (Date.now() > deadline)
            throw new Error(`timed out waiting for ${what}; got ${received.map((m) => m.action.kind).join(', ')}\n${stderr}`);
        await new Promise((r) => setTimeout(r, 100));
    }
}

function element(root: SModelRoot, id: string): SModelElement & Record<string, unknown> {
    const found = [...allElements(root)].find((e) => e.id === id);
    if (!found) throw new Error(`no element ${id}`);
    return found as SModelElement & Record<string, unknown>;
}

beforeAll(() => {
    if (!existsSync(serverMain)) throw new Error(`${serverMain} is missing: run 'npm run build' first`);
    tmp = mkdtempSync(join(tmpdir(), 'maa-diagram-lsp-'));
    cpSync(EXAMPLE, tmp, { recursive: true });
    proc = spawn(process.execPath, [serverMain, '--stdio'], { stdio: 'pipe' });
    proc.stderr.on('data', (chunk: Buffer) => {
        stderr += chunk.toString();
    });
    connection = createProtocolConnection(new StreamMessageReader(proc.stdout), new StreamMessageWriter(proc.stdin));
    connection.onNotification(DiagramAccept, (m) => {
        received.push(m);
    });
    connection.onNotification(PublishDiagnosticsNotification.type, (p) => {
        published.add(p.uri);
    });
    connection.listen();
});

afterAll(() => {
    connection?.dispose();
    if (proc && proc.exitCode === null) proc.kill();
    if (tmp) rmSync(tmp, { recursive: true, force: true });
});

describe('the diagram server of maa-language-server', () => {
    test('answers a model request and updates the diagram after an edit', async () => {
        const root = pathToFileURL(tmp).toString();
        await connection.sendRequest(InitializeRequest.type, {
            processId: process.pid,
            rootUri: root,
            workspaceFolders: [{ uri: root, name: 'ws' }],
            capabilities: {},
        });
        await connection.sendNotification(InitializedNotification.type, {});
        const source = pathToFileURL(join(tmp, 'toast/ToastServiceRobot.arc')).toString();
        await until('the start-up checks', () => (published.has(source) ? true : undefined));

        await connection.sendNotification(DiagramAccept, {
            clientId: 'c1',
            action: {
                kind: 'requestModel',
                requestId: 'req1',
                options: { diagramType: 'maa-cc', sourceUri: source, needsClientLayout: false },
            } as ActionMessage['action'],
        });
        const set = await until('setModel', () => received.find((m) => m.action.kind === 'setModel'));
        expect(set.clientId).toBe('c1');
        const model = set.action as unknown as { newRoot: SModelRoot; responseId: string };
        expect(model.responseId).toBe('req1');
        expect(model.newRoot).toMatchObject({ type: 'graph', component: 'toast.ToastServiceRobot' });
        expect(element(model.newRoot, 'root.ctrl')).toMatchObject({ behaviorKind: 'automaton' });
        expect(element(model.newRoot, 'root.ctrl').severity).toBeUndefined();
        expect(element(model.newRoot, 'root.ctrl').position).toBeDefined();

        const controller = pathToFileURL(join(tmp, 'toast/Controller.arc')).toString();
        const text = readFileSync(join(tmp, 'toast/Controller.arc'), 'utf8');
        await connection.sendNotification(DidOpenTextDocumentNotification.type, {
            textDocument: { uri: controller, languageId: 'arc', version: 1, text },
        });
        await connection.sendNotification(DidChangeTextDocumentNotification.type, {
            textDocument: { uri: controller, version: 2 },
            contentChanges: [{ text: text.replace('ToastColor.GOLDEN', 'ToastColor.GOLD') }],
        });
        const update = await until('an update marking ctrl', () =>
            received.find(
                (m) =>
                    m.action.kind === 'updateModel' &&
                    element((m.action as unknown as { newRoot: SModelRoot }).newRoot, 'root.ctrl').severity === 'error',
            ),
        );
        expect(update.clientId).toBe('c1');
        expect((update.action as unknown as { animate: boolean }).animate).toBe(true);
    });
});
