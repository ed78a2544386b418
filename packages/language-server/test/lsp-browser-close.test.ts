// Closing documents in the browser IDE: the language server of the Web Worker entry (started
// in-process on a MessageChannel, the workspace over the backend's HTTP API). A document opened
// under a new name and closed without saving leaves the workspace when the backend's listing has
// no such file: its diagnostics are cleared and the document that used it is unresolved again. A
// document saved under its name before it is closed stays (the listing is asked afresh).
import { mkdirSync, mkdtempSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { MessageChannel } from 'node:worker_threads';
import { URI } from 'langium';
import { afterAll, beforeAll, describe, expect, test, vi } from 'vitest';
import {
    BrowserMessageReader,
    BrowserMessageWriter,
    createProtocolConnection,
    type Diagnostic,
    type ProtocolConnection,
} from 'vscode-languageserver-protocol/browser.js';
import { startBrowserLanguageServer, type BrowserLanguageServer } from '../src/browser/server.js';
import { serveWorkspace, type WorkspaceServer } from './browser-helpers.js';

const WS = 'file:///workspace/p';
const USER = `${WS}/User.arc`;

let dir = '';
let http: WorkspaceServer | undefined;
let channel: MessageChannel | undefined;
let connection: ProtocolConnection;
let server: BrowserLanguageServer;
const published: Array<{ uri: string; diagnostics: Diagnostic[] }> = [];
let wake: () => void = () => undefined;

const latest = (uri: string): Diagnostic[] | undefined => published.filter((p) => p.uri === uri).at(-1)?.diagnostics;
const codes = (uri: string): string[] => (latest(uri) ?? []).map((d) => String(d.code));
const has = (uri: string): boolean => server.family.shared.workspace.LangiumDocuments.hasDocument(URI.parse(uri));

async function until<T>(what: string, probe: () => T | undefined, timeout = 60_000): Promise<T> {
    const deadline = Date.now() + timeout;
    for (;;) {
        const v = probe();
        if (v !== undefined) return v;
        if (Date.now() > deadline) throw new Error(`timed out waiting for ${what}; published: ${JSON.stringify(published.slice(-4))}`);
        // Woken by the next notification; the timer only bounds a wait for a condition on state.
        await new Promise<void>((r) => {
            wake = r;
            setTimeout(r, 250);
        });
    }
}

/** Waits until the close handler has asked the backend's listing about a document, and returns its answer. */
async function closeAndAsk(uri: string): Promise<boolean> {
    const exists = vi.spyOn(server.fileSystem, 'exists');
    try {
        await connection.sendNotification('textDocument/didClose', { textDocument: { uri } });
        const answer = await until(`the listing asked about ${uri}`, () => {
            const i = exists.mock.calls.findIndex(([u]) => u.toString() === uri);
            return i >= 0 ? (exists.mock.results[i]!.value as Promise<boolean>) : undefined;
        });
        return await answer;
    } finally {
        exists.mockRestore();
    }
}

beforeAll(async () => {
    dir = mkdtempSync(join(tmpdir(), 'maa-browser-close-'));
    mkdirSync(join(dir, 'p'));
    writeFileSync(join(dir, 'p', 'A.arc'), 'package p;\n\ncomponent A {\n  port in int x;\n}\n');
    writeFileSync(join(dir, 'p', 'User.arc'), 'package p;\n\ncomponent User {\n  Fresh f;\n}\n');
    http = await serveWorkspace(dir);
    channel = new MessageChannel();
    server = startBrowserLanguageServer(channel.port2 as unknown as ConstructorParameters<typeof BrowserMessageReader>[0], {
        apiBase: http.url,
    });
    const port = channel.port1 as unknown as ConstructorParameters<typeof BrowserMessageReader>[0];
    connection = createProtocolConnection(new BrowserMessageReader(port), new BrowserMessageWriter(port));
    connection.onNotification('textDocument/publishDiagnostics', (p: { uri: string; diagnostics: Diagnostic[] }) => {
        published.push(p);
        wake();
    });
    connection.listen();
    await connection.sendRequest('initialize', {
        processId: null,
        rootUri: 'file:///workspace/',
        workspaceFolders: [{ uri: 'file:///workspace/', name: 'workspace' }],
        capabilities: {},
    });
    await connection.sendNotification('initialized', {});
    await until('the workspace build', () => latest(USER));
});

afterAll(async () => {
    connection?.dispose();
    channel?.port1.close();
    channel?.port2.close();
    await http?.close();
    if (dir) rmSync(dir, { recursive: true, force: true });
});

describe('closing documents in the browser language server', () => {
    test('a document that the backend does not list is dropped when closed', async () => {
        expect(codes(USER)).toEqual(['arc/missing-component-type']);
        const before = server.family.shared.workspace.LangiumDocuments.all.count();
        const fresh = `${WS}/Fresh.arc`;
        await connection.sendNotification('textDocument/didOpen', {
            textDocument: { uri: fresh, languageId: 'arc', version: 1, text: 'package p;\n\ncomponent Fresh {\n  port in Missing m;\n}\n' },
        });
        await until('the errors of the unsaved document', () => (codes(fresh).includes('arc/unresolved-type') ? true : undefined));
        await until('User.arc linked to it', () => (!codes(USER).includes('arc/missing-component-type') ? true : undefined));

        expect(await closeAndAsk(fresh)).toBe(false);
        await until('its diagnostics cleared', () => (latest(fresh)?.length === 0 ? true : undefined));
        await until('User.arc unresolved again', () => (codes(USER).includes('arc/missing-component-type') ? true : undefined));
        expect(has(fresh)).toBe(false);
        expect(server.family.shared.workspace.LangiumDocuments.all.count()).toBe(before);
    });

    test('a document saved under its name before it is closed stays', async () => {
        const saved = `${WS}/Saved.arc`;
        const text = 'package p;\n\ncomponent Saved {\n}\n';
        await connection.sendNotification('textDocument/didOpen', { textDocument: { uri: saved, languageId: 'arc', version: 1, text } });
        await until('its diagnostics', () => latest(saved));
        // The listing was fetched before the save; the close asks the backend again.
        await server.fileSystem.stat(URI.parse(`${WS}/A.arc`));
        writeFileSync(join(dir, 'p', 'Saved.arc'), text);
        expect(await closeAndAsk(saved)).toBe(true);
        await new Promise((r) => setImmediate(r));
        expect(has(saved)).toBe(true);
    });
});
