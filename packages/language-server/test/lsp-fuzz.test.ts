// The fuzz corpus through the real language server (`node dist/node/main.js --stdio`, as editors
// start it): pathological models (10,000 levels of nesting, a file of a few MB), random bytes,
// truncations, token swaps and splices of the example's files, each opened under a new name or
// typed over an example file, followed by requests at random positions (completion, hover,
// definition, references, highlight, prepareRename, rename, formatting, code actions, semantic
// tokens, outline, folding). Asserted: the process never exits, no answer is an internal error
// (-32603), every request is answered within REQUEST_BOUND_MS, and diagnostics arrive for every
// case. The bounds are failure reasons, not benchmarks.
//
// Replay: MAA_FUZZ_SEED=<seed> [MAA_FUZZ_CASES=<n>] npx vitest run packages/language-server/test/lsp-fuzz.test.ts
// A failing case's text is written to <tmpdir>/maa-lsp-fuzz-failures/.
import { spawn, type ChildProcessWithoutNullStreams } from 'node:child_process';
import { cpSync, existsSync, mkdirSync, mkdtempSync, readdirSync, readFileSync, rmSync, statSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { dirname, join, relative, resolve, sep } from 'node:path';
import { fileURLToPath, pathToFileURL } from 'node:url';
import { afterAll, beforeAll, describe, expect, test } from 'vitest';
import {
    CodeActionRequest,
    CompletionRequest,
    createProtocolConnection,
    DefinitionRequest,
    DidChangeTextDocumentNotification,
    DidCloseTextDocumentNotification,
    DidOpenTextDocumentNotification,
    DocumentFormattingRequest,
    DocumentHighlightRequest,
    DocumentSymbolRequest,
    ErrorCodes,
    ExitNotification,
    FoldingRangeRequest,
    HoverRequest,
    InitializedNotification,
    InitializeRequest,
    LogMessageNotification,
    PrepareRenameRequest,
    PublishDiagnosticsNotification,
    ReferencesRequest,
    RenameRequest,
    ResponseError,
    LSPErrorCodes,
    SemanticTokensRequest,
    ShutdownRequest,
    StreamMessageReader,
    StreamMessageWriter,
    type Diagnostic,
    type Position,
    type ProtocolConnection,
} from 'vscode-languageserver-protocol/node.js';
import { corpus, pathologicalCases, Random, type FuzzCase, type SourceFile } from './lsp-fuzz-cases.js';

const here = dirname(fileURLToPath(import.meta.url));
const serverMain = resolve(here, '../dist/node/main.js');
const example = resolve(here, '../../../examples/toast-service');

const SEED = Number(process.env['MAA_FUZZ_SEED'] ?? 11);
const CASES = Number(process.env['MAA_FUZZ_CASES'] ?? 400);
const REQUESTS_PER_CASE = 3;
/** How long one request may take before it counts as unanswered (a loaded 2-core machine). */
const REQUEST_BOUND_MS = 30_000;
/** How long diagnostics of one case may take (the file of a few MB is checked in this time). */
const DIAGNOSTICS_BOUND_MS = 60_000;

let tmp = '';
let proc: ChildProcessWithoutNullStreams;
let connection: ProtocolConnection;
let stderr = '';
let exited: string | undefined;
const published = new Map<string, { count: number; diagnostics: Diagnostic[] }>();
let wake: () => void = () => undefined;

class FuzzFailure extends Error {}

/** Resolves with the value, or fails when the server exits or the bound passes. */
function bounded<T>(what: string, promise: Promise<T>, ms: number): Promise<T> {
    return new Promise<T>((resolvePromise, reject) => {
        const timer = setTimeout(() => reject(new FuzzFailure(`${what}: no answer within ${ms} ms`)), ms);
        const onExit = (): void => reject(new FuzzFailure(`${what}: the server exited (${exited ?? 'unknown'})`));
        proc.once('exit', onExit);
        if (exited) onExit();
        promise.then(resolvePromise, reject).finally(() => {
            clearTimeout(timer);
            proc.off('exit', onExit);
        });
    });
}

/** Waits for a diagnostics notification for a URI after the `seen`-th one. */
async function diagnosticsAfter(uri: string, seen: number, what: string): Promise<Diagnostic[]> {
    const deadline = Date.now() + DIAGNOSTICS_BOUND_MS;
    for (;;) {
        const p = published.get(uri);
        if (p && p.count > seen) return p.diagnostics;
        if (exited) throw new FuzzFailure(`${what}: the server exited (${exited})`);
        if (Date.now() > deadline) throw new FuzzFailure(`${what}: no diagnostics within ${DIAGNOSTICS_BOUND_MS} ms`);
        // Woken by the next notification; the timer only re-checks the deadline.
        await new Promise<void>((r) => {
            wake = r;
            setTimeout(r, 1000);
        });
    }
}

function modelFiles(dir: string): SourceFile[] {
    return readdirSync(dir).flatMap((name) => {
        const path = join(dir, name);
        if (statSync(path).isDirectory()) return modelFiles(path);
        return /\.(arc|cd|ra|arcapp)$/.test(name)
            ? [{ path: relative(example, path).split(sep).join('/'), text: readFileSync(path, 'utf8') }]
            : [];
    });
}

/** Line starts of a text, for positions at offsets. */
function positionAt(text: string, offset: number): Position {
    let line = 0;
    let start = 0;
    for (let i = text.indexOf('\n'); i >= 0 && i < offset; i = text.indexOf('\n', i + 1)) {
        line++;
        start = i + 1;
    }
    return { line, character: offset - start };
}

const NEW_NAMES = ['renamed', 'x2', '', 'a b', '1abc', 'component', 'state', 'ä', '$ok_1'];

/** One request of a random kind at a random position (sometimes past the end of the text). */
function randomRequest(
    random: Random,
    uri: string,
    text: string,
    diagnostics: Diagnostic[],
): { name: string; send: () => Promise<unknown> } {
    const offset = random.next() < 0.05 ? text.length + 10 : random.int(text.length + 1);
    const position = random.next() < 0.03 ? { line: 100_000, character: 3 } : positionAt(text, Math.min(offset, text.length));
    const textDocument = { uri };
    const at = `${position.line + 1}:${position.character + 1}`;
    const kinds: Array<{ name: string; send: () => Promise<unknown> }> = [
        { name: `completion at ${at}`, send: () => connection.sendRequest(CompletionRequest.type, { textDocument, position }) },
        { name: `hover at ${at}`, send: () => connection.sendRequest(HoverRequest.type, { textDocument, position }) },
        { name: `definition at ${at}`, send: () => connection.sendRequest(DefinitionRequest.type, { textDocument, position }) },
        {
            name: `references at ${at}`,
            send: () =>
                connection.sendRequest(ReferencesRequest.type, {
                    textDocument,
                    position,
                    context: { includeDeclaration: random.next() < 0.5 },
                }),
        },
        {
            name: `documentHighlight at ${at}`,
            send: () => connection.sendRequest(DocumentHighlightRequest.type, { textDocument, position }),
        },
        { name: `prepareRename at ${at}`, send: () => connection.sendRequest(PrepareRenameRequest.type, { textDocument, position }) },
        (() => {
            const newName = random.pick(NEW_NAMES);
            return {
                name: `rename at ${at} to '${newName}'`,
                send: () => connection.sendRequest(RenameRequest.type, { textDocument, position, newName }),
            };
        })(),
        {
            name: 'formatting',
            send: () =>
                connection.sendRequest(DocumentFormattingRequest.type, { textDocument, options: { tabSize: 2, insertSpaces: true } }),
        },
        {
            name: `codeAction at ${at}`,
            send: () =>
                connection.sendRequest(CodeActionRequest.type, {
                    textDocument,
                    range: { start: position, end: position },
                    context: { diagnostics: diagnostics.slice(0, 5) },
                }),
        },
        { name: 'semanticTokens', send: () => connection.sendRequest(SemanticTokensRequest.type, { textDocument }) },
        { name: 'documentSymbol', send: () => connection.sendRequest(DocumentSymbolRequest.type, { textDocument }) },
        { name: 'foldingRange', send: () => connection.sendRequest(FoldingRangeRequest.type, { textDocument }) },
    ];
    return random.pick(kinds);
}

beforeAll(async () => {
    if (!existsSync(serverMain)) throw new Error(`${serverMain} is missing: run 'npx tsc -b packages/language-server' first`);
    tmp = mkdtempSync(join(tmpdir(), 'maa-lsp-fuzz-'));
    cpSync(example, join(tmp, 'toast-service'), { recursive: true });
    proc = spawn(process.execPath, [serverMain, '--stdio'], { stdio: 'pipe' });
    proc.stderr.on('data', (chunk: Buffer) => {
        stderr = (stderr + chunk.toString()).slice(-20_000);
    });
    proc.on('exit', (code, signal) => {
        exited = `code ${code}, signal ${signal}`;
        wake();
    });
    connection = createProtocolConnection(new StreamMessageReader(proc.stdout), new StreamMessageWriter(proc.stdin));
    connection.onNotification(PublishDiagnosticsNotification.type, (p) => {
        const before = published.get(p.uri)?.count ?? 0;
        published.set(p.uri, { count: before + 1, diagnostics: p.diagnostics });
        wake();
    });
    // The server's console goes to the client's log: kept with stderr for failure messages.
    connection.onNotification(LogMessageNotification.type, (p) => {
        stderr = `${stderr + p.message}\n`.slice(-20_000);
    });
    // Requests of the server to the client (none with the capabilities sent, but answered if any).
    connection.onRequest('client/registerCapability', () => null);
    connection.onRequest('workspace/configuration', () => []);
    connection.listen();
    const root = pathToFileURL(tmp).toString();
    await connection.sendRequest(InitializeRequest.type, {
        processId: process.pid,
        rootUri: root,
        workspaceFolders: [{ uri: root, name: 'fuzz' }],
        capabilities: {},
    });
    await connection.sendNotification(InitializedNotification.type, {});
});

afterAll(async () => {
    if (connection && !exited) {
        await bounded('shutdown', connection.sendRequest(ShutdownRequest.type), REQUEST_BOUND_MS).catch(() => undefined);
        await connection.sendNotification(ExitNotification.type).catch(() => undefined);
    }
    connection?.dispose();
    if (proc && proc.exitCode === null) proc.kill();
    if (tmp) rmSync(tmp, { recursive: true, force: true });
});

describe('the language server under fuzzed input', () => {
    test(`${CASES} mutated and the pathological models with ${REQUESTS_PER_CASE} random requests each (seed ${SEED})`, async () => {
        const started = performance.now();
        const random = new Random(SEED);
        const sources = modelFiles(example);
        const cases = corpus(random, sources, CASES);
        const failures: string[] = [];
        const answers = new Map<string, number>();
        const count = (kind: string): void => {
            answers.set(kind, (answers.get(kind) ?? 0) + 1);
        };
        let lateRequests = 0;
        const versions = new Map<string, number>();
        const openExamples = new Set<string>();
        const fail = (index: number, c: FuzzCase, request: string, problem: string): void => {
            const dir = join(tmpdir(), 'maa-lsp-fuzz-failures');
            mkdirSync(dir, { recursive: true });
            const file = join(dir, `seed-${SEED}-case-${index}.${c.ext}`);
            writeFileSync(file, c.text);
            failures.push(`seed ${SEED}, case ${index} (${c.description}; text in ${file}), ${request}: ${problem}`);
        };
        const durations: Array<{ ms: number; what: string }> = [];
        const refused: string[] = [];
        const pathological: string[] = [];
        const pathologicalCount = pathologicalCases().length;
        for (const [index, c] of cases.entries()) {
            if (exited || failures.length >= 10) break;
            const caseStarted = performance.now();
            // Half of the cases are typed over an example file (its dependents are rebuilt against
            // the broken text); the others are opened under a new name and closed again.
            const sameLanguage = sources.filter((s) => s.path.endsWith(`.${c.ext}`));
            const overExample = sameLanguage.length > 0 && random.next() < 0.5;
            const uri = overExample
                ? pathToFileURL(join(tmp, 'toast-service', random.pick(sameLanguage).path)).toString()
                : pathToFileURL(join(tmp, 'toast-service', 'toast', `Fuzz${index}.${c.ext}`)).toString();
            const seen = published.get(uri)?.count ?? 0;
            const version = (versions.get(uri) ?? 0) + 1;
            versions.set(uri, version);
            if (overExample && openExamples.has(uri)) {
                await connection.sendNotification(DidChangeTextDocumentNotification.type, {
                    textDocument: { uri, version },
                    contentChanges: [{ text: c.text }],
                });
            } else {
                await connection.sendNotification(DidOpenTextDocumentNotification.type, {
                    textDocument: { uri, languageId: c.ext, version, text: c.text },
                });
                if (overExample) openExamples.add(uri);
            }
            let diagnostics: Diagnostic[] = [];
            try {
                diagnostics = await diagnosticsAfter(uri, seen, 'diagnostics');
                if (index < pathologicalCount)
                    pathological.push(
                        `  ${c.description}: ${[...new Set(diagnostics.map((d) => String(d.code)))].slice(0, 4).join(', ') || 'no diagnostics'}`,
                    );
            } catch (e) {
                fail(index, c, 'diagnostics', (e as Error).message);
                continue;
            }
            for (let r = 0; r < REQUESTS_PER_CASE; r++) {
                const request = randomRequest(random, uri, c.text, diagnostics);
                try {
                    await bounded(request.name, request.send(), REQUEST_BOUND_MS);
                    count('result');
                } catch (e) {
                    if (e instanceof ResponseError) {
                        count(`error ${e.code}`);
                        if (e.code === ErrorCodes.InternalError) fail(index, c, request.name, `internal error -32603: ${e.message}`);
                        // A refusal of a feature that threw (guarded): allowed, but reported.
                        if (
                            e.code === LSPErrorCodes.RequestFailed &&
                            !e.message.includes('not a valid name') &&
                            !e.message.includes('cannot be renamed')
                        ) {
                            refused.push(`case ${index} (${c.description.slice(0, 80)}), ${request.name}: ${e.message.split('\n')[0]}`);
                        }
                    } else {
                        fail(index, c, request.name, (e as Error).message);
                    }
                }
            }
            if (!overExample) {
                await connection.sendNotification(DidCloseTextDocumentNotification.type, { textDocument: { uri } });
                // A request that races the close (the document is being dropped) still gets an answer.
                if (random.next() < 0.2) {
                    const late = randomRequest(random, uri, c.text, []);
                    await bounded(`${late.name} after close`, late.send(), REQUEST_BOUND_MS).then(
                        () => count('result'),
                        (e: unknown) => {
                            if (!(e instanceof ResponseError)) fail(index, c, `${late.name} after close`, (e as Error).message);
                            else if (e.code === ErrorCodes.InternalError)
                                fail(index, c, `${late.name} after close`, `internal error -32603: ${e.message}`);
                            else count(`error ${e.code}`);
                        },
                    );
                    lateRequests++;
                }
            }
            durations.push({ ms: Math.round(performance.now() - caseStarted), what: `case ${index} (${c.description.slice(0, 80)})` });
        }
        if (exited) failures.push(`seed ${SEED}: the server exited (${exited})`);
        console.info(
            `lsp fuzz, seed ${SEED}: ${cases.length} cases in ${Math.round(performance.now() - started)} ms; pathological cases:\n${pathological.join('\n')}`,
        );
        const summary = [...answers].map(([k, n]) => `${k}: ${n}`).join(', ');
        expect(failures, `${failures.join('\n')}\nanswers: ${summary}\nserver stderr (tail):\n${stderr.slice(-4000)}`).toEqual([]);
        expect(exited).toBeUndefined();
        // Every case got its requests answered (results or clean refusals).
        expect([...answers.values()].reduce((a, b) => a + b, 0)).toBe(cases.length * REQUESTS_PER_CASE + lateRequests);
        const slowest = durations
            .sort((a, b) => b.ms - a.ms)
            .slice(0, 3)
            .map((d) => `${d.what}: ${d.ms} ms`);
        console.info(`lsp fuzz answers: ${summary}; slowest cases (diagnostics and requests): ${slowest.join('; ')}`);
        if (refused.length > 0) console.info(`features that failed and were refused (RequestFailed):\n${refused.join('\n')}`);
    }, 600_000);
});
