// The family's language server in the test process, spoken to over a real LSP connection (a pair
// of in-memory streams): Langium's request handlers, the document sync and diagnostics as the
// node entry runs them, while the test can look at the server's services (its documents).
import { PassThrough } from 'node:stream';
import { startLanguageServer } from 'langium/lsp';
import { NodeFileSystem } from 'langium/node';
import { createConnection, ProposedFeatures } from 'vscode-languageserver/node.js';
import {
    createProtocolConnection,
    InitializedNotification,
    InitializeRequest,
    LogMessageNotification,
    PublishDiagnosticsNotification,
    StreamMessageReader,
    StreamMessageWriter,
    type Diagnostic,
    type ProtocolConnection,
} from 'vscode-languageserver-protocol/node.js';
import type { HostLspServices } from '@maa/language-adl';
import { createMaaLspServices, MAA_SERVICE_REQUIREMENTS } from '../src/family.js';

export interface InProcessServer {
    readonly family: HostLspServices;
    readonly client: ProtocolConnection;
    /** Every diagnostics notification so far, in order. */
    readonly published: Array<{ uri: string; diagnostics: Diagnostic[] }>;
    /** Every message the server logged (window/logMessage). */
    readonly logs: string[];
    /** Waits (event-driven) until a condition on the published diagnostics and logs holds. */
    until<T>(what: string, probe: () => T | undefined, timeoutMs?: number): Promise<T>;
    /** The latest diagnostics published for a URI. */
    latest(uri: string): Diagnostic[] | undefined;
    dispose(): void;
}

/** Starts the server on a folder of the real file system and initializes it with that folder. */
export async function startInProcess(folderUri: string): Promise<InProcessServer> {
    const toServer = new PassThrough();
    const toClient = new PassThrough();
    // Reader and writer objects (not streams): the node connection then installs no process exit hooks.
    const connection = createConnection(ProposedFeatures.all, new StreamMessageReader(toServer), new StreamMessageWriter(toClient));
    const family = createMaaLspServices({ connection, ...NodeFileSystem });
    startLanguageServer(family.shared, MAA_SERVICE_REQUIREMENTS);
    const client = createProtocolConnection(new StreamMessageReader(toClient), new StreamMessageWriter(toServer));
    const published: InProcessServer['published'] = [];
    const logs: string[] = [];
    let wake: () => void = () => undefined;
    client.onNotification(PublishDiagnosticsNotification.type, (p) => {
        published.push({ uri: p.uri, diagnostics: p.diagnostics });
        wake();
    });
    client.onNotification(LogMessageNotification.type, (p) => {
        logs.push(p.message);
        wake();
    });
    // Requests of the server to the client (none with the capabilities sent, but answered if any).
    client.onRequest('client/registerCapability', () => null);
    client.onRequest('workspace/configuration', () => []);
    client.listen();
    await client.sendRequest(InitializeRequest.type, {
        processId: null,
        rootUri: folderUri,
        workspaceFolders: [{ uri: folderUri, name: 'ws' }],
        capabilities: {},
    });
    await client.sendNotification(InitializedNotification.type, {});
    await family.shared.workspace.WorkspaceManager.ready;
    const latest = (uri: string): Diagnostic[] | undefined => published.filter((p) => p.uri === uri).at(-1)?.diagnostics;
    return {
        family,
        client,
        published,
        logs,
        latest,
        async until(what, probe, timeoutMs = 60_000) {
            const deadline = Date.now() + timeoutMs;
            for (;;) {
                const v = probe();
                if (v !== undefined) return v;
                if (Date.now() > deadline)
                    throw new Error(`timed out waiting for ${what}; published: ${JSON.stringify(published.slice(-5))}`);
                // Wakes on the next notification; the timer only bounds a wait for a condition on state.
                await new Promise<void>((r) => {
                    wake = r;
                    setTimeout(r, 250);
                });
            }
        },
        dispose() {
            client.dispose();
            connection.dispose();
            toServer.end();
            toClient.end();
        },
    };
}
