// `maa-gen lsp`: the family's language server behind the CLI, spoken to as an editor does, over
// stdio and over a socket on 127.0.0.1: initialize, didOpen of a broken model, and the
// publishDiagnostics with an error that follows; shutdown and exit end the stdio server with 0.
import { spawn, type ChildProcessWithoutNullStreams } from 'node:child_process';
import { once } from 'node:events';
import { connect, createServer, type AddressInfo, type Socket } from 'node:net';
import { networkInterfaces } from 'node:os';
import { pathToFileURL } from 'node:url';
import { afterEach, beforeAll, describe, expect, it } from 'vitest';
import {
    createProtocolConnection,
    DidOpenTextDocumentNotification,
    ExitNotification,
    InitializedNotification,
    InitializeRequest,
    PublishDiagnosticsNotification,
    ShutdownRequest,
    StreamMessageReader,
    StreamMessageWriter,
    type Diagnostic,
    type ProtocolConnection,
} from 'vscode-languageserver-protocol/node.js';
import { BIN, ModelDir, requireBuiltCli, runCli } from './helpers.js';

const BROKEN = `package demo;

component Broken {
  port in int x,
       out int y;
  x -> nowhere;
`;

const cleanups: Array<() => void> = [];
beforeAll(() => requireBuiltCli());
afterEach(() => {
    for (const c of cleanups.splice(0)) c();
});

function startLsp(args: string[], cwd: string): ChildProcessWithoutNullStreams {
    const child = spawn(process.execPath, [BIN, 'lsp', ...args], { cwd, stdio: ['pipe', 'pipe', 'pipe'] });
    cleanups.push(() => {
        // SIGTERM, not SIGKILL: maa-gen passes it on to the language server it started.
        child.stdin.end();
        if (child.exitCode === null && child.signalCode === null) child.kill('SIGTERM');
    });
    return child;
}

/** Initializes the server on `folder`, opens the broken model and resolves with its first error. */
async function firstErrorOfBrokenModel(client: ProtocolConnection, folder: ModelDir): Promise<Diagnostic> {
    const file = folder.write('demo/Broken.arc', BROKEN);
    const uri = pathToFileURL(file).toString();
    const error = new Promise<Diagnostic>((resolve) => {
        client.onNotification(PublishDiagnosticsNotification.type, (p) => {
            const found = p.uri === uri ? p.diagnostics.find((d) => d.severity === 1) : undefined;
            if (found) resolve(found);
        });
    });
    client.onRequest('client/registerCapability', () => null);
    client.onRequest('workspace/configuration', () => []);
    client.listen();
    const root = pathToFileURL(folder.dir).toString();
    await client.sendRequest(InitializeRequest.type, {
        processId: process.pid,
        rootUri: root,
        workspaceFolders: [{ uri: root, name: 'ws' }],
        capabilities: {},
    });
    await client.sendNotification(InitializedNotification.type, {});
    await client.sendNotification(DidOpenTextDocumentNotification.type, {
        textDocument: { uri, languageId: 'arc', version: 1, text: BROKEN },
    });
    return error;
}

function tempFolder(): ModelDir {
    const d = new ModelDir();
    cleanups.push(() => d.dispose());
    return d;
}

describe('maa-gen lsp --stdio', () => {
    it('publishes an error for a broken model, and exits 0 after shutdown and exit', async () => {
        const folder = tempFolder();
        const child = startLsp(['--stdio'], folder.dir);
        const client = createProtocolConnection(new StreamMessageReader(child.stdout), new StreamMessageWriter(child.stdin));
        cleanups.push(() => client.dispose());
        const error = await firstErrorOfBrokenModel(client, folder);
        expect(error.range.start.line).toBeGreaterThanOrEqual(2);
        expect(typeof error.code).toBe('string');

        const exited = once(child, 'exit');
        await client.sendRequest(ShutdownRequest.type);
        await client.sendNotification(ExitNotification.type);
        const [code] = await exited;
        expect(code).toBe(0);
    }, 120_000);

    it('without a flag speaks stdio as well', async () => {
        const folder = tempFolder();
        const child = startLsp([], folder.dir);
        const client = createProtocolConnection(new StreamMessageReader(child.stdout), new StreamMessageWriter(child.stdin));
        cleanups.push(() => client.dispose());
        const error = await firstErrorOfBrokenModel(client, folder);
        expect(error.severity).toBe(1);
    }, 120_000);
});

/** Resolves with the port `maa-gen lsp --socket 0` printed on stderr. */
async function listeningPort(child: ChildProcessWithoutNullStreams): Promise<{ host: string; port: number }> {
    let text = '';
    for await (const chunk of child.stderr) {
        text += String(chunk);
        const m = /listening on (\d+\.\d+\.\d+\.\d+):(\d+)/.exec(text);
        if (m) return { host: m[1]!, port: Number(m[2]) };
    }
    throw new Error(`maa-gen lsp ended without listening: ${text}`);
}

describe('maa-gen lsp --socket', () => {
    it('listens on 127.0.0.1 and serves a connection; SIGTERM stops it with 0', async () => {
        const folder = tempFolder();
        const child = startLsp(['--socket', '0'], folder.dir);
        const { host, port } = await listeningPort(child);
        expect(host).toBe('127.0.0.1');
        const socket: Socket = connect(port, '127.0.0.1');
        await once(socket, 'connect');
        cleanups.push(() => socket.destroy());
        const client = createProtocolConnection(new StreamMessageReader(socket), new StreamMessageWriter(socket));
        cleanups.push(() => client.dispose());
        const error = await firstErrorOfBrokenModel(client, folder);
        expect(error.severity).toBe(1);

        const exited = once(child, 'exit');
        child.kill('SIGTERM');
        const [code] = await exited;
        expect(code).toBe(0);
    }, 120_000);

    const external = Object.values(networkInterfaces())
        .flat()
        .find((a) => a !== undefined && a.family === 'IPv4' && !a.internal)?.address;
    it.skipIf(external === undefined)(
        'is not reachable on another interface of the machine',
        async () => {
            const child = startLsp(['--socket', '0'], tempFolder().dir);
            const { port } = await listeningPort(child);
            const socket = connect(port, external!);
            cleanups.push(() => socket.destroy());
            const [e] = (await once(socket, 'error')) as [NodeJS.ErrnoException];
            expect(e.code).toBe('ECONNREFUSED');
        },
        60_000,
    );

    it('refuses a port that is no number with exit 2', async () => {
        const r = await runCli(['lsp', '--socket', 'http'], tempFolder().dir);
        expect(r.code).toBe(2);
        expect(r.stderr).toContain('maa-gen: error: not a port number (0-65535): http');
    });

    it('a port in use exits 2 and says so', async () => {
        const taken = createServer();
        taken.listen(0, '127.0.0.1');
        await once(taken, 'listening');
        cleanups.push(() => taken.close());
        const port = (taken.address() as AddressInfo).port;
        const r = await runCli(['lsp', '--socket', String(port)], tempFolder().dir);
        expect(r.code).toBe(2);
        expect(r.stderr).toContain(`maa-gen: error: cannot listen on 127.0.0.1:${port} (EADDRINUSE)`);
    });

    it('refuses --stdio together with --socket with exit 2', async () => {
        const r = await runCli(['lsp', '--stdio', '--socket', '5000'], tempFolder().dir);
        expect(r.code).toBe(2);
        expect(r.stderr).toContain('--stdio and --socket exclude each other');
    });
});
