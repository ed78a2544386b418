// The real language server process (`node dist/node/main.js --stdio`, as editors start it),
// spoken to over stdio with LSP: initialize, the workspace's diagnostics, didOpen ->
// publishDiagnostics with codes, completion inside an embedded automaton, hover, definition,
// formatting, code actions, shutdown. No mocks: the built server and the protocol library.
import { spawn, spawnSync, type ChildProcessWithoutNullStreams } from 'node:child_process';
import { existsSync, mkdirSync, mkdtempSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { dirname, join, resolve } from 'node:path';
import { fileURLToPath, pathToFileURL } from 'node:url';
import { afterAll, beforeAll, describe, expect, test } from 'vitest';
import {
    CodeActionRequest,
    CompletionRequest,
    DefinitionRequest,
    DidOpenTextDocumentNotification,
    DocumentFormattingRequest,
    ExitNotification,
    HoverRequest,
    InitializedNotification,
    InitializeRequest,
    PublishDiagnosticsNotification,
    ShutdownRequest,
    StreamMessageReader,
    StreamMessageWriter,
    createProtocolConnection,
    type CompletionItem,
    type CompletionList,
    type Diagnostic,
    type InitializeResult,
    type ProtocolConnection,
    type PublishDiagnosticsParams,
} from 'vscode-languageserver-protocol/node.js';

const here = dirname(fileURLToPath(import.meta.url));
const serverMain = resolve(here, '../dist/node/main.js');

const TYPES = `package toast.types;

classdiagram Types {
  enum ToasterCmd { START, STOP; }
}
`;

const CONTROLLER = `package toast;

import toast.types.*;

component Controller(int threshold = 30) {
  port in int distance,
       out ToasterCmd toaster;

  <<sync>> automaton {
    initial { toaster = ToasterCmd.STOP; } state Idle;
    Idle -> Idle [distance < threshold] / { toaster = ToasterCmd.START; };
  }
}
`;

/** The file as the editor has it: a naming problem, a missing state, and a guard being typed. */
const EDITED = `package toast;

import toast.types.*;

component Controller(int threshold = 30) {
  port in int distance,
       out ToasterCmd Toaster;

  <<sync>> automaton {
    initial { Toaster = ToasterCmd.STOP; } state Idle;
    Idle -> Busy [dist < threshold] / { Toaster = ToasterCmd.START; };
  }
}
`;

let tmp = '';
let proc: ChildProcessWithoutNullStreams;
let connection: ProtocolConnection;
let stderr = '';
const diagnostics = new Map<string, Diagnostic[]>();
const waiters: Array<() => void> = [];

function fileUri(path: string): string {
    return pathToFileURL(join(tmp, path)).toString();
}

/** Waits until the latest diagnostics published for a document satisfy a condition. */
async function diagnosticsFor(uri: string, until: (d: Diagnostic[]) => boolean, timeout = 30_000): Promise<Diagnostic[]> {
    const deadline = Date.now() + timeout;
    for (;;) {
        const d = diagnostics.get(uri);
        if (d && until(d)) return d;
        if (Date.now() > deadline) throw new Error(`no matching diagnostics for ${uri}: ${JSON.stringify(d)}\nserver stderr:\n${stderr}`);
        await new Promise<void>((r) => {
            waiters.push(r);
            setTimeout(r, 200);
        });
    }
}

beforeAll(() => {
    if (!existsSync(serverMain)) throw new Error(`${serverMain} is missing: run 'npm run build' first`);
    tmp = mkdtempSync(join(tmpdir(), 'maa-lsp-server-'));
    for (const [path, text] of Object.entries({ 'toast/types/Types.cd': TYPES, 'toast/Controller.arc': CONTROLLER })) {
        mkdirSync(dirname(join(tmp, path)), { recursive: true });
        writeFileSync(join(tmp, path), text);
    }
    proc = spawn(process.execPath, [serverMain, '--stdio'], { stdio: 'pipe' });
    proc.stderr.on('data', (chunk: Buffer) => {
        stderr += chunk.toString();
    });
    connection = createProtocolConnection(new StreamMessageReader(proc.stdout), new StreamMessageWriter(proc.stdin));
    connection.onNotification(PublishDiagnosticsNotification.type, (p: PublishDiagnosticsParams) => {
        diagnostics.set(p.uri, p.diagnostics);
        for (const w of waiters.splice(0)) w();
    });
    connection.listen();
});

afterAll(async () => {
    connection?.dispose();
    if (proc && proc.exitCode === null) proc.kill();
    if (tmp) rmSync(tmp, { recursive: true, force: true });
});

describe('maa-language-server command line', () => {
    test('--help, --version, and a missing transport', () => {
        const run = (...args: string[]) => spawnSync(process.execPath, [serverMain, ...args], { encoding: 'utf8' });
        const help = run('--help');
        expect(help.status).toBe(0);
        expect(help.stdout).toContain('Usage: maa-language-server (--stdio | --node-ipc | --socket=<port>)');
        expect(run('--version').stdout.trim()).toMatch(/^\d+\.\d+\.\d+/);
        const none = run();
        expect(none.status).toBe(2);
        expect(none.stderr).toContain('no transport given');
    });
});

describe('maa-language-server over stdio', () => {
    test('initialize announces the LSP features', async () => {
        const result: InitializeResult = await connection.sendRequest(InitializeRequest.type, {
            processId: process.pid,
            rootUri: pathToFileURL(tmp).toString(),
            workspaceFolders: [{ uri: pathToFileURL(tmp).toString(), name: 'ws' }],
            capabilities: { textDocument: { publishDiagnostics: { relatedInformation: true } } },
        });
        const c = result.capabilities;
        expect(c.completionProvider?.triggerCharacters).toContain('.');
        for (const feature of [
            'hoverProvider',
            'definitionProvider',
            'referencesProvider',
            'documentSymbolProvider',
            'foldingRangeProvider',
            'documentFormattingProvider',
            'documentRangeFormattingProvider',
            'codeActionProvider',
        ] as const) {
            expect(c[feature], feature).toBeTruthy();
        }
        expect(c.renameProvider).toEqual({ prepareProvider: true });
        const legend = (c.semanticTokensProvider as { legend: { tokenTypes: string[] } }).legend;
        expect(legend.tokenTypes).toEqual(
            expect.arrayContaining(['class', 'property', 'parameter', 'variable', 'enumMember', 'namespace']),
        );
        await connection.sendNotification(InitializedNotification.type, {});
    });

    test("the workspace's files are checked at start-up", async () => {
        const clean = await diagnosticsFor(fileUri('toast/Controller.arc'), () => true);
        expect(clean).toEqual([]);
    });

    test('didOpen -> publishDiagnostics with stable codes', async () => {
        const uri = fileUri('toast/Controller.arc');
        await connection.sendNotification(DidOpenTextDocumentNotification.type, {
            textDocument: { uri, languageId: 'arc', version: 1, text: EDITED },
        });
        const found = await diagnosticsFor(uri, (d) => d.length > 0);
        expect(found.map((d) => d.code).sort()).toEqual(['arc/naming-convention', 'automaton/missing-state', 'expr/unresolved-name']);
        const missing = found.find((d) => d.code === 'automaton/missing-state')!;
        expect(missing.range.start).toEqual({ line: 10, character: 12 });
        expect(missing.severity).toBe(1);
    });

    test("completion in a guard of the embedded automaton offers the component's ports", async () => {
        const uri = fileUri('toast/Controller.arc');
        const result = (await connection.sendRequest(CompletionRequest.type, {
            textDocument: { uri },
            position: { line: 10, character: 22 },
        })) as CompletionList | CompletionItem[];
        const items = Array.isArray(result) ? result : result.items;
        const labels = items.map((i) => i.label);
        expect(labels).toContain('distance');
        expect(labels).not.toContain('threshold'); // filtered: does not match `dist`
        const all = (await connection.sendRequest(CompletionRequest.type, {
            textDocument: { uri },
            position: { line: 10, character: 18 },
        })) as CompletionList;
        expect(all.items.map((i) => i.label)).toEqual(expect.arrayContaining(['distance', 'threshold', 'Toaster']));
    });

    test('hover and go to definition across files', async () => {
        const uri = fileUri('toast/Controller.arc');
        const hover = await connection.sendRequest(HoverRequest.type, { textDocument: { uri }, position: { line: 10, character: 63 } });
        // `START` in `ToasterCmd.START`: a member access, resolved through the expression typer.
        expect(JSON.stringify(hover?.contents)).toContain('Constant of enumeration `ToasterCmd`');
        const links = (await connection.sendRequest(DefinitionRequest.type, {
            textDocument: { uri },
            position: { line: 10, character: 63 },
        })) as Array<{ targetUri: string }>;
        expect(links.map((l) => l.targetUri)).toEqual([fileUri('toast/types/Types.cd')]);
    });

    test('code actions for the published diagnostics; formatting', async () => {
        const uri = fileUri('toast/Controller.arc');
        const d = await diagnosticsFor(uri, (x) => x.length > 0);
        const actions = (await connection.sendRequest(CodeActionRequest.type, {
            textDocument: { uri },
            range: d[0]!.range,
            context: { diagnostics: d },
        })) as Array<{ title: string }>;
        expect(actions.map((a) => a.title)).toEqual(expect.arrayContaining(["Rename 'Toaster' to 'toaster'", "Create state 'Busy'"]));
        const edits = await connection.sendRequest(DocumentFormattingRequest.type, {
            textDocument: { uri },
            options: { tabSize: 4, insertSpaces: true },
        });
        expect(edits).toEqual([]);
    });

    test('shutdown and exit end the process', async () => {
        await connection.sendRequest(ShutdownRequest.type);
        const exited = new Promise<number | null>((r) => proc.once('exit', (code) => r(code)));
        await connection.sendNotification(ExitNotification.type);
        expect(await exited).toBe(0);
    });
});
