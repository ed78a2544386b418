/**
 * The language server of the family in a Web Worker (the browser IDE): LSP over the worker's
 * message port, documents from the client only (no file system; the IDE sends every workspace
 * file it wants checked with didOpen). Bundled by the IDE's build.
 */
import { EmptyFileSystem } from 'langium';
import { startLanguageServer } from 'langium/lsp';
import { BrowserMessageReader, BrowserMessageWriter, createConnection } from 'vscode-languageserver/browser.js';
// Imported from the module, not the package index: the index also exports the Node-only checker.
import { createMaaLspServices } from '../family.js';

/** The worker's global scope (typed loosely: this package compiles without the DOM library). */
declare const self: ConstructorParameters<typeof BrowserMessageReader>[0];

/** Starts the server on the worker's message port. */
export function startBrowserLanguageServer(port: ConstructorParameters<typeof BrowserMessageReader>[0] = self): void {
    const connection = createConnection(new BrowserMessageReader(port), new BrowserMessageWriter(port));
    const { shared } = createMaaLspServices({ connection, ...EmptyFileSystem });
    startLanguageServer(shared);
}

startBrowserLanguageServer();
