/**
 * The family's language server and diagram server for a Web Worker (or anything that talks LSP
 * over a message port): workspace files over the IDE backend's HTTP API, generators from the
 * bundled manifests. Browser-safe: no Node built-ins in its imports.
 */
import { startLanguageServer } from 'langium/lsp';
import { BrowserMessageReader, BrowserMessageWriter, createConnection } from 'vscode-languageserver/browser.js';
import { configureGeneratorRegistry } from '@maa/generator-core';
import type { HostLspServices } from '@maa/language-adl';
// Imported from the modules, not the package index: the index also exports the Node-only checker.
import { addMaaDiagramServer, type MaaDiagramServices } from '../diagram/index.js';
import { createMaaLspServices, MAA_SERVICE_REQUIREMENTS } from '../family.js';
import { bundledGeneratorRegistry } from './generator-registry.js';
import { HttpFileSystemProvider } from './http-file-system.js';

/** A message port as BrowserMessageReader/Writer take it (a worker scope, a MessagePort). */
export type ServerPort = ConstructorParameters<typeof BrowserMessageReader>[0];

export interface BrowserServerOptions {
    /**
     * The backend's base URL (`<apiBase>/api/files`). Default: `initializationOptions.apiBase`
     * of the client's initialize request, else the worker's origin.
     */
    readonly apiBase?: string;
}

export interface BrowserLanguageServer {
    readonly family: HostLspServices;
    readonly diagrams: MaaDiagramServices;
    readonly fileSystem: HttpFileSystemProvider;
}

/** Starts the server on a message port. */
export function startBrowserLanguageServer(port: ServerPort, options: BrowserServerOptions = {}): BrowserLanguageServer {
    const connection = createConnection(new BrowserMessageReader(port), new BrowserMessageWriter(port));
    const fileSystem = new HttpFileSystemProvider({ apiBase: options.apiBase ?? workerOrigin() });
    const family = createMaaLspServices({ connection, fileSystemProvider: () => fileSystem });
    configureGeneratorRegistry(family.shared, bundledGeneratorRegistry());
    // The workspace is read after `initialized`; the client's apiBase is known by then.
    family.shared.lsp.LanguageServer.onInitialize((params) => {
        const init = params.initializationOptions as { apiBase?: unknown } | undefined;
        if (options.apiBase === undefined && typeof init?.apiBase === 'string') fileSystem.setApiBase(init.apiBase);
    });
    // Saved, created or deleted files change the listing. A closed document is dropped when the
    // listing does not have its file (AdlDocumentUpdateHandler): ask the backend afresh, the
    // file may have been saved under its name a moment ago.
    family.shared.workspace.DocumentBuilder.onUpdate(() => fileSystem.invalidate());
    family.shared.workspace.TextDocuments.onDidClose(() => fileSystem.invalidate());
    const diagrams = addMaaDiagramServer(family);
    // The outline waits for linked documents (see MAA_SERVICE_REQUIREMENTS).
    startLanguageServer(family.shared, MAA_SERVICE_REQUIREMENTS);
    return { family, diagrams, fileSystem };
}

/** The origin of the page or worker script (`location` exists in both; typed loosely without the DOM library). */
function workerOrigin(): string {
    const location = (globalThis as { location?: { origin?: string } }).location;
    return location?.origin && location.origin !== 'null' ? location.origin : '';
}
