// The language server over a real LSP connection (in the test process, on a folder of the file
// system): a document opened under a new name and closed without saving leaves the workspace
// (documents, index, diagnostics; dependents are rebuilt), files on disk stay; a feature that
// throws is answered with RequestFailed and logged once; a build that throws is logged and the
// server goes on.
import { mkdirSync, mkdtempSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { pathToFileURL } from 'node:url';
import { DocumentState, URI } from 'langium';
import { afterAll, beforeAll, describe, expect, test, vi } from 'vitest';
import {
    DefinitionRequest,
    DidChangeTextDocumentNotification,
    DidCloseTextDocumentNotification,
    DidOpenTextDocumentNotification,
    HoverRequest,
    LSPErrorCodes,
    ResponseError,
} from 'vscode-languageserver-protocol/node.js';
import { startInProcess, type InProcessServer } from './lsp-connection-helpers.js';

const A = `package p;

component A {
  port in int x;
}
`;

/** On disk; uses the component that only the unsaved document declares. */
const USER = `package p;

component User {
  Fresh f;
}
`;

/** Never saved: an error of its own and a dependency on A (on disk). */
const FRESH = `package p;

component Fresh {
  port in Missing m;
  A a;
}
`;

let dir = '';
let server: InProcessServer;
const uri = (name: string): string => pathToFileURL(join(dir, 'p', name)).toString();
const codes = (uriString: string): string[] => (server.latest(uriString) ?? []).map((d) => String(d.code));
const documentCount = (): number => server.family.shared.workspace.LangiumDocuments.all.count();

beforeAll(async () => {
    dir = mkdtempSync(join(tmpdir(), 'maa-lsp-lifecycle-'));
    mkdirSync(join(dir, 'p'));
    writeFileSync(join(dir, 'p', 'A.arc'), A);
    writeFileSync(join(dir, 'p', 'User.arc'), USER);
    server = await startInProcess(pathToFileURL(dir).toString());
});

afterAll(() => {
    server?.dispose();
    if (dir) rmSync(dir, { recursive: true, force: true });
});

describe('documents that were never saved', () => {
    test('are dropped when closed: diagnostics cleared, dependents rebuilt, document count back, errors never return', async () => {
        await server.until('the start-up diagnostics of User.arc', () => server.latest(uri('User.arc')));
        expect(codes(uri('User.arc'))).toEqual(['arc/missing-component-type']);
        const before = documentCount();

        const fresh = uri('Fresh.arc');
        await server.client.sendNotification(DidOpenTextDocumentNotification.type, {
            textDocument: { uri: fresh, languageId: 'arc', version: 1, text: FRESH },
        });
        await server.until('the errors of the unsaved document', () => (codes(fresh).includes('arc/unresolved-type') ? true : undefined));
        // It resolves A from disk and makes User's subcomponent type resolve.
        expect(codes(fresh)).not.toContain('arc/missing-component-type');
        await server.until('User.arc linked to the unsaved document', () =>
            !codes(uri('User.arc')).includes('arc/missing-component-type') ? true : undefined,
        );
        expect(documentCount()).toBe(before + 1);

        await server.client.sendNotification(DidCloseTextDocumentNotification.type, { textDocument: { uri: fresh } });
        await server.until('the diagnostics of the closed document cleared', () => (server.latest(fresh)?.length === 0 ? true : undefined));
        await server.until('User.arc unresolved again', () =>
            codes(uri('User.arc')).includes('arc/missing-component-type') ? true : undefined,
        );
        expect(documentCount()).toBe(before);
        expect(server.family.shared.workspace.LangiumDocuments.hasDocument(URI.parse(fresh))).toBe(false);

        // Edits of other files never bring its errors back.
        const mark = server.published.length;
        await server.client.sendNotification(DidOpenTextDocumentNotification.type, {
            textDocument: { uri: uri('A.arc'), languageId: 'arc', version: 1, text: A },
        });
        for (let version = 2; version <= 4; version++) {
            await server.client.sendNotification(DidChangeTextDocumentNotification.type, {
                textDocument: { uri: uri('A.arc'), version },
                contentChanges: [{ text: A.replace('int x', `int x${version}`) }],
            });
        }
        await server.until('the last edit of A.arc validated', () =>
            server.published.slice(mark).some((p) => p.uri === uri('A.arc')) &&
            server.family.shared.workspace.LangiumDocuments.getDocument(URI.parse(uri('A.arc')))
                ?.textDocument.getText()
                .includes('x4') &&
            server.family.shared.workspace.LangiumDocuments.getDocument(URI.parse(uri('A.arc')))!.state === DocumentState.Validated
                ? true
                : undefined,
        );
        expect(server.published.slice(mark).filter((p) => p.uri === fresh)).toEqual([]);
        expect(documentCount()).toBe(before);
    });

    test('a closed document that has a file stays in the workspace, with the text of its file', async () => {
        const a = uri('A.arc');
        const exists = vi.spyOn(server.family.shared.workspace.FileSystemProvider, 'exists');
        try {
            await server.client.sendNotification(DidCloseTextDocumentNotification.type, { textDocument: { uri: a } });
            // The close handler asks the file system; its answer decides.
            const asked = await server.until('the file system asked about A.arc', () => {
                const i = exists.mock.calls.findIndex(([u]) => u.toString() === a);
                return i >= 0 ? (exists.mock.results[i]!.value as Promise<boolean>) : undefined;
            });
            expect(await asked).toBe(true);
            await new Promise((r) => setImmediate(r));
            expect(server.family.shared.workspace.LangiumDocuments.hasDocument(URI.parse(a))).toBe(true);
            // It was closed with unsaved edits (`int x4`): the workspace goes back to the file's text.
            await server.until('A.arc back to the text on disk', () => {
                const doc = server.family.shared.workspace.LangiumDocuments.getDocument(URI.parse(a));
                return doc?.textDocument.getText() === A && doc.state === DocumentState.Validated ? true : undefined;
            });
        } finally {
            exists.mockRestore();
        }
    });
});

describe('features that throw', () => {
    test('a request whose feature throws is refused with RequestFailed (not an internal error), logged once; the next request is served', async () => {
        const user = uri('User.arc');
        await server.client.sendNotification(DidOpenTextDocumentNotification.type, {
            textDocument: { uri: user, languageId: 'arc', version: 1, text: USER.replace('Fresh f', 'Missing f') },
        });
        await server.until('User.arc with Missing', () =>
            (server.latest(user) ?? []).some((d) => d.message.includes('Missing')) ? true : undefined,
        );
        // A contribution with a bug: names that are not cross-references resolve through it.
        const resolvers = server.family.Arc.references.References.nameResolvers;
        const broken = (): never => {
            throw new Error('resolver bug');
        };
        resolvers.unshift(broken);
        try {
            const at = { textDocument: { uri: user }, position: { line: 3, character: 4 } };
            for (let i = 0; i < 3; i++) {
                const answer = server.client.sendRequest(DefinitionRequest.type, at);
                await expect(answer).rejects.toBeInstanceOf(ResponseError);
                await expect(answer).rejects.toMatchObject({
                    code: LSPErrorCodes.RequestFailed,
                    message: expect.stringContaining('resolver bug'),
                });
            }
            await server.until('the failure logged', () => (server.logs.some((l) => l.includes('resolver bug')) ? true : undefined));
            expect(server.logs.filter((l) => l.includes('resolver bug'))).toHaveLength(1);
        } finally {
            resolvers.splice(resolvers.indexOf(broken), 1);
        }
        const hover = await server.client.sendRequest(HoverRequest.type, {
            textDocument: { uri: user },
            position: { line: 2, character: 12 },
        });
        expect(JSON.stringify(hover)).toContain('User');
    });

    test('a build that throws is logged and the next edit is built and validated', async () => {
        const user = uri('User.arc');
        let armed = true;
        const listener = server.family.shared.workspace.DocumentBuilder.onBuildPhase(DocumentState.IndexedContent, () => {
            if (armed) {
                armed = false;
                throw new Error('build phase bug');
            }
        });
        try {
            await server.client.sendNotification(DidChangeTextDocumentNotification.type, {
                textDocument: { uri: user, version: 2 },
                contentChanges: [{ text: USER.replace('Fresh f', 'Other f') }],
            });
            await server.until('the build failure logged', () =>
                server.logs.some((l) => l.includes('build phase bug')) ? true : undefined,
            );
            await server.client.sendNotification(DidChangeTextDocumentNotification.type, {
                textDocument: { uri: user, version: 3 },
                contentChanges: [{ text: USER.replace('Fresh f', 'Third f') }],
            });
            await server.until('the next edit validated', () =>
                (server.latest(user) ?? []).some((d) => d.message.includes('Third')) ? true : undefined,
            );
        } finally {
            listener.dispose();
        }
    });
});
