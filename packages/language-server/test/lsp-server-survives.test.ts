// The stdio server (`node dist/node/main.js --stdio`) survives an exception that nothing catches
// and a promise rejection that nothing handles, as a buggy feature would leave them outside a
// request: both are logged to the client and the server goes on answering. The failures are
// planted by a module preloaded with `--import` that throws from a timer once the server runs.
import { spawn, type ChildProcessWithoutNullStreams } from 'node:child_process';
import { existsSync, mkdtempSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { dirname, join, resolve } from 'node:path';
import { fileURLToPath, pathToFileURL } from 'node:url';
import { afterAll, describe, expect, test } from 'vitest';
import {
    createProtocolConnection,
    DidOpenTextDocumentNotification,
    DocumentSymbolRequest,
    InitializedNotification,
    InitializeRequest,
    LogMessageNotification,
    StreamMessageReader,
    StreamMessageWriter,
    type ProtocolConnection,
} from 'vscode-languageserver-protocol/node.js';

const here = dirname(fileURLToPath(import.meta.url));
const serverMain = resolve(here, '../dist/node/main.js');

/** Throws from a timer and leaves a rejection unhandled, once the test creates the flag file (the server is running by then). */
const PLANT = `
import { existsSync } from 'node:fs';
const flag = process.env.MAA_PLANT_FLAG;
const timer = setInterval(() => {
    if (!existsSync(flag)) return;
    clearInterval(timer);
    setTimeout(() => { throw new Error('planted uncaught exception'); }, 0);
    setTimeout(() => { void Promise.reject(new Error('planted unhandled rejection')); }, 0);
}, 50);
`;

let tmp = '';
let proc: ChildProcessWithoutNullStreams | undefined;
let connection: ProtocolConnection | undefined;

afterAll(() => {
    connection?.dispose();
    if (proc && proc.exitCode === null) proc.kill();
    if (tmp) rmSync(tmp, { recursive: true, force: true });
});

describe('maa-language-server over stdio', () => {
    test('logs an uncaught exception and an unhandled rejection and goes on serving', async () => {
        if (!existsSync(serverMain)) throw new Error(`${serverMain} is missing: run 'npx tsc -b packages/language-server' first`);
        tmp = mkdtempSync(join(tmpdir(), 'maa-lsp-survive-'));
        const plant = join(tmp, 'plant.mjs');
        const flag = join(tmp, 'go');
        writeFileSync(plant, PLANT);
        writeFileSync(join(tmp, 'A.arc'), 'component A {\n  port in int x;\n}\n');
        const server = spawn(process.execPath, ['--import', pathToFileURL(plant).href, serverMain, '--stdio'], {
            stdio: 'pipe',
            env: { ...process.env, MAA_PLANT_FLAG: flag },
        });
        proc = server;
        let exited: string | undefined;
        server.on('exit', (code, signal) => {
            exited = `code ${code}, signal ${signal}`;
        });
        const client = createProtocolConnection(new StreamMessageReader(server.stdout), new StreamMessageWriter(server.stdin));
        connection = client;
        const logs: string[] = [];
        let wake: () => void = () => undefined;
        client.onNotification(LogMessageNotification.type, (p) => {
            logs.push(p.message);
            wake();
        });
        client.listen();
        const root = pathToFileURL(tmp).toString();
        await client.sendRequest(InitializeRequest.type, {
            processId: process.pid,
            rootUri: root,
            workspaceFolders: [{ uri: root, name: 'ws' }],
            capabilities: {},
        });
        await client.sendNotification(InitializedNotification.type, {});

        writeFileSync(flag, '');
        const deadline = Date.now() + 60_000;
        while (
            !(logs.some((l) => l.includes('planted uncaught exception')) && logs.some((l) => l.includes('planted unhandled rejection')))
        ) {
            if (exited) throw new Error(`the server exited (${exited}); log:\n${logs.join('\n')}`);
            if (Date.now() > deadline) throw new Error(`the planted failures were not logged; log:\n${logs.join('\n')}`);
            await new Promise<void>((r) => {
                wake = r;
                setTimeout(r, 250);
            });
        }
        expect(logs.find((l) => l.includes('planted uncaught exception'))).toContain('uncaught exception (the server goes on)');
        expect(logs.find((l) => l.includes('planted unhandled rejection'))).toContain('unhandled rejection (the server goes on)');

        const uri = pathToFileURL(join(tmp, 'A.arc')).toString();
        await client.sendNotification(DidOpenTextDocumentNotification.type, {
            textDocument: { uri, languageId: 'arc', version: 1, text: 'component A {\n  port in int x;\n}\n' },
        });
        const outline = await client.sendRequest(DocumentSymbolRequest.type, { textDocument: { uri } });
        expect(JSON.stringify(outline)).toContain('"name":"A"');
        expect(exited).toBeUndefined();
    }, 120_000);
});
