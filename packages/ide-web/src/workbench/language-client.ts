/** The language client on the language server's Web Worker (`src/worker.ts`). */
import * as monaco from '@codingame/monaco-vscode-editor-api';
import { MonacoLanguageClient } from 'monaco-languageclient';
import { BrowserMessageReader, BrowserMessageWriter } from 'vscode-languageclient/browser.js';
import { MODEL_LANGUAGE_IDS } from '../languages.js';
import { notify, setServerStatus } from './status.js';

export async function startLanguageClient(): Promise<MonacoLanguageClient> {
    setServerStatus('Language server: starting…', 'starting');
    const worker = new Worker(new URL('../worker.ts', import.meta.url), { type: 'module', name: 'maa-language-server' });
    worker.addEventListener('error', (e) => {
        setServerStatus('Language server: failed', 'error');
        notify('error', `The language server worker failed: ${e.message}`);
    });
    const client = new MonacoLanguageClient({
        name: 'MontiArcAutomaton',
        id: 'maa',
        clientOptions: {
            documentSelector: MODEL_LANGUAGE_IDS.map((language) => ({ scheme: 'file', language })),
            workspaceFolder: { index: 0, name: 'workspace', uri: monaco.Uri.parse('file:///workspace') },
            // The server reads the workspace over the backend API at this base (docs/ide.md).
            initializationOptions: { apiBase: new URL('.', document.baseURI).href.replace(/\/$/, '') },
            errorHandler: {
                error: () => ({ action: 1 /* Continue */ }),
                closed: () => ({ action: 1 /* DoNotRestart */ }),
            },
        },
        messageTransports: { reader: new BrowserMessageReader(worker), writer: new BrowserMessageWriter(worker) },
    });
    await client.start();
    setServerStatus('Language server: ready', 'ready');
    return client;
}
