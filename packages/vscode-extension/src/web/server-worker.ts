/**
 * The language server's Web Worker from the extension's own files. The worker script
 * (`out/web/server.js`) is read through VS Code's file service, so it works wherever the
 * extension's files live (an `https:` folder in VS Code for the Web, the `extension-file:`
 * scheme of the browser IDE's workbench), and started from a blob URL: a worker needs a
 * same-origin script URL, which an extension's location is not in every host.
 */
import * as vscode from 'vscode';

/** The DOM's worker and blob types as far as this module uses them (the package compiles without the DOM library). */
interface WorkerLike {
    addEventListener(type: 'error', listener: (event: { message?: string }) => void): void;
}
interface WebGlobals {
    Worker: new (url: string, options?: { name?: string }) => WorkerLike;
    Blob: typeof Blob;
    URL: typeof URL;
}

/** The path of the server bundle inside the extension (bin/build.mjs writes it). */
export const SERVER_SCRIPT = 'out/web/server.js';

export async function startServerWorker(extensionUri: vscode.Uri): Promise<WorkerLike> {
    const web = globalThis as unknown as WebGlobals;
    const source = await vscode.workspace.fs.readFile(vscode.Uri.joinPath(extensionUri, SERVER_SCRIPT));
    const url = web.URL.createObjectURL(new web.Blob([source], { type: 'text/javascript' }));
    const worker = new web.Worker(url, { name: 'maa-language-server' });
    worker.addEventListener('error', (event) => {
        void vscode.window.showErrorMessage(`MontiArc: the language server worker failed: ${event.message ?? 'unknown error'}`);
    });
    return worker;
}
