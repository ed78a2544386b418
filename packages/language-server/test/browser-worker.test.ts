// The browser entry (`@maa/language-server/browser`) as the IDE ships it: bundled by esbuild for
// the browser (which must need no Node built-in), then started as a worker (a Node worker
// thread whose `self` is a MessagePort, as a Web Worker's scope is) and spoken to with LSP over
// the port. The workspace comes from a stand-in of the backend's HTTP API: diagnostics of a
// broken file, cross-file references, generators of the .arcapp file and a diagram.
import { builtinModules } from 'node:module';
import { cpSync, mkdtempSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { dirname, join, resolve } from 'node:path';
import { fileURLToPath, pathToFileURL } from 'node:url';
import { MessageChannel, Worker, type MessagePort } from 'node:worker_threads';
import { build, type Plugin } from 'esbuild';
import { afterAll, beforeAll, describe, expect, test } from 'vitest';
import { serveWorkspace, type WorkspaceServer } from './browser-helpers.js';
import { EXAMPLE } from './diagram-helpers.js';

const here = dirname(fileURLToPath(import.meta.url));
const entry = resolve(here, '../src/browser/main.ts');
const NODE_BUILTINS = new Set([...builtinModules, ...builtinModules.map((m) => `node:${m}`)]);

/** Bundles the worker entry for browsers; records every Node built-in something asks for. */
async function bundle(): Promise<{ code: string; builtins: string[] }> {
    const builtins: string[] = [];
    const guard: Plugin = {
        name: 'no-node-builtins',
        setup(b) {
            b.onResolve({ filter: /.*/ }, (args) => {
                if (!NODE_BUILTINS.has(args.path)) return undefined;
                builtins.push(`${args.path} <- ${args.importer}`);
                return { path: args.path, external: true };
            });
        },
    };
    const result = await build({
        entryPoints: [entry],
        bundle: true,
        platform: 'browser',
        format: 'esm',
        write: false,
        logLevel: 'silent',
        plugins: [guard],
    });
    return { code: result.outputFiles[0]!.text, builtins };
}

let dir = '';
let server: WorkspaceServer;
let worker: Worker | undefined;
let port: MessagePort;
let bundled: { code: string; builtins: string[] };
const diagnostics = new Map<string, Array<{ code?: string; severity?: number; message: string }>>();
const notifications: Array<{ method: string; params: unknown }> = [];
const pending = new Map<number, (result: unknown) => void>();
let nextId = 0;
let changed: () => void = () => undefined;

function request(method: string, params: unknown): Promise<unknown> {
    const id = ++nextId;
    port.postMessage({ jsonrpc: '2.0', id, method, params });
    return new Promise((r) => pending.set(id, r));
}

function notify(method: string, params: unknown): void {
    port.postMessage({ jsonrpc: '2.0', method, params });
}

async function until<T>(what: string, probe: () => T | undefined, timeout = 60_000): Promise<T> {
    const deadline = Date.now() + timeout;
    for (;;) {
        const v = probe();
        if (v !== undefined) return v;
        if (Date.now() > deadline) throw new Error(`timed out waiting for ${what}; diagnostics for ${[...diagnostics.keys()].join(', ')}`);
        await new Promise<void>((r) => {
            changed = r;
            setTimeout(r, 200);
        });
    }
}

beforeAll(async () => {
    bundled = await bundle();
    dir = mkdtempSync(join(tmpdir(), 'maa-worker-'));
    cpSync(EXAMPLE, join(dir, 'toast-service'), { recursive: true });
    const controller = join(dir, 'toast-service', 'toast', 'Controller.arc');
    writeFileSync(controller, readFileSync(controller, 'utf8').replace('ToastColor.GOLDEN', 'ToastColor.GOLD'));
    const script = join(dir, 'worker.mjs');
    writeFileSync(script, bundled.code);
    const boot = join(dir, 'boot.mjs');
    // A Web Worker's scope: `self` is the port the page talks to; no `window`, no `document`.
    writeFileSync(
        boot,
        `import { workerData } from 'node:worker_threads';\nglobalThis.self = workerData.port;\nawait import(${JSON.stringify(pathToFileURL(script).href)});\n`,
    );
    server = await serveWorkspace(dir);

    const channel = new MessageChannel();
    port = channel.port1;
    port.on('message', (message: { id?: number; method?: string; params?: unknown; result?: unknown }) => {
        if (message.id !== undefined && message.method === undefined) {
            pending.get(message.id)?.(message.result);
            pending.delete(message.id);
        } else if (message.id !== undefined && message.method) {
            port.postMessage({ jsonrpc: '2.0', id: message.id, result: null }); // e.g. client/registerCapability
        } else if (message.method) {
            notifications.push({ method: message.method, params: message.params });
            if (message.method === 'textDocument/publishDiagnostics') {
                const p = message.params as { uri: string; diagnostics: Array<{ code?: string; severity?: number; message: string }> };
                diagnostics.set(p.uri, p.diagnostics);
            }
        }
        changed();
    });
    worker = new Worker(boot, { workerData: { port: channel.port2 }, transferList: [channel.port2] });
    worker.on('error', (e) => {
        throw e;
    });
});

afterAll(async () => {
    port?.close();
    await worker?.terminate();
    await server?.close();
    if (dir) rmSync(dir, { recursive: true, force: true });
});

describe('the browser entry', () => {
    test('bundles for browsers without any Node built-in', () => {
        expect(bundled.builtins).toEqual([]);
        expect(bundled.code.length).toBeGreaterThan(100_000);
    });

    test('runs as a worker: the workspace over HTTP, diagnostics, generators and a diagram', async () => {
        const init = (await request('initialize', {
            processId: null,
            rootUri: 'file:///workspace/',
            workspaceFolders: [{ uri: 'file:///workspace/', name: 'workspace' }],
            capabilities: {},
            initializationOptions: { apiBase: server.url },
        })) as { capabilities: Record<string, unknown> };
        expect(init.capabilities).toHaveProperty('completionProvider');
        notify('initialized', {});

        const ws = 'file:///workspace/toast-service';
        const controller = await until('the broken Controller', () => diagnostics.get(`${ws}/toast/Controller.arc`));
        expect(controller.map((d) => d.code)).toContain('expr/unresolved-name');
        // Every other file resolves across files (types, subcomponents) and has no problems,
        // which needs the model root of maa.json (package `toast` in folder toast/).
        const robot = await until('ToastServiceRobot', () => diagnostics.get(`${ws}/toast/ToastServiceRobot.arc`));
        expect(robot).toEqual([]);
        // The application's generators resolve against the bundled manifests.
        expect(await until('TR.arcapp', () => diagnostics.get(`${ws}/TR.arcapp`))).toEqual([]);
        expect(server.requests).toContain('/api/files');
        expect(server.requests).toContain('/api/file?path=toast-service%2Fmaa.json');

        notify('diagram/accept', {
            clientId: 'diagram-1',
            action: {
                kind: 'requestModel',
                requestId: 'r1',
                options: { diagramType: 'maa-cc', sourceUri: `${ws}/toast/ToastServiceRobot.arc`, needsClientLayout: false },
            },
        });
        const answer = await until(
            'the diagram',
            () =>
                notifications.find((n) => n.method === 'diagram/accept')?.params as
                    | {
                          clientId: string;
                          action: {
                              kind: string;
                              responseId?: string;
                              newRoot: { children: Array<{ id: string; children: Array<Record<string, unknown>> }> };
                          };
                      }
                    | undefined,
        );
        expect(answer.clientId).toBe('diagram-1');
        expect(answer.action.kind).toBe('setModel');
        expect(answer.action.responseId).toBe('r1');
        const ctrl = answer.action.newRoot.children[0]!.children.find((c) => c.id === 'root.ctrl')!;
        expect(ctrl).toMatchObject({ severity: 'error', behaviorKind: 'automaton' });
        expect(ctrl.position).toBeDefined(); // laid out by ELK inside the worker
    });
});
