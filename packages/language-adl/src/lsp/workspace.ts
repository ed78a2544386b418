import {
    DefaultDocumentBuilder,
    DefaultLangiumDocuments,
    isOperationCancelled,
    URI,
    UriUtils,
    type BuildOptions,
    type FileSystemNode,
    type FileSystemProvider,
    type LangiumDocument,
    type LangiumDocuments,
    type DocumentBuilder,
    type WorkspaceLock,
} from 'langium';
import { DefaultDocumentUpdateHandler, type DocumentUpdateHandler, type LangiumSharedServices } from 'langium/lsp';
import { LSPErrorCodes, ResponseError, type CancellationToken } from 'vscode-languageserver-protocol';
import type { DidChangeWatchedFilesParams, InitializeParams } from 'vscode-languageserver-protocol';
import type { WorkspaceFolder } from 'vscode-languageserver-types';
import { AdlWorkspaceManager, type AdlSharedServices } from '../adl-module.js';
import type { ModelRoots } from '../model-roots.js';
import { ReservedNames, type RootConfiguration } from '../validation/reserved-names.js';
import { serverLog } from './guard.js';

/**
 * The workspace in the editor. Its model roots are
 * - every workspace folder, and
 * - every folder below a workspace folder that contains a `maa.json` (the project file of a
 *   model root; `{}` is enough),
 * so a repository holding several projects can be opened as one folder. Each root's `maa.json`
 * configures its checks (reserved names). Every model file of the workspace is loaded and
 * validated at start-up, so the problems panel lists the diagnostics of closed files too.
 */
export class AdlLspWorkspaceManager extends AdlWorkspaceManager {
    private readonly modelRoots: ModelRoots;
    private readonly reservedNames: ReservedNames;
    private configured: URI[] = [];

    constructor(services: AdlSharedServices) {
        super(services);
        this.modelRoots = services.maa.ModelRoots;
        this.reservedNames = services.maa.ReservedNames;
        this.initialBuildOptions = { validation: true } satisfies BuildOptions;
    }

    /** Clients that send only a root URI (no workspace folders) get that folder as the workspace. */
    override initialize(params: InitializeParams): void {
        super.initialize(params);
        if (!this.folders?.length && params.rootUri) {
            const uri = URI.parse(params.rootUri);
            this.folders = [{ uri: params.rootUri, name: UriUtils.basename(uri) }];
        }
    }

    protected override async performStartup(folders: WorkspaceFolder[]): Promise<LangiumDocument[]> {
        await this.configureModelRoots(folders);
        return super.performStartup(folders);
    }

    /** Finds the model roots of the workspace folders again (after a `maa.json` changed). */
    async reloadModelRoots(): Promise<void> {
        await this.configureModelRoots(this.workspaceFolders ?? []);
    }

    protected async configureModelRoots(folders: readonly WorkspaceFolder[]): Promise<void> {
        const roots = new Map<string, URI>();
        const configs = new Map<string, RootConfiguration>();
        for (const folder of folders) {
            const uri = URI.parse(folder.uri);
            roots.set(uri.toString(), uri);
            await this.findConfigurations(uri, roots, configs);
        }
        this.modelRoots.setRoots([...roots.values()]);
        // A root that lost its maa.json goes back to the default configuration.
        for (const old of this.configured) {
            if (!configs.has(old.toString())) this.reservedNames.configure(old, {});
        }
        this.configured = [];
        for (const [key, config] of configs) {
            const root = URI.parse(key);
            this.reservedNames.configure(root, config);
            this.configured.push(root);
        }
    }

    private async findConfigurations(folder: URI, roots: Map<string, URI>, configs: Map<string, RootConfiguration>): Promise<void> {
        let entries: FileSystemNode[];
        try {
            entries = await this.fileSystemProvider.readDirectory(folder);
        } catch {
            return;
        }
        for (const entry of entries) {
            const name = UriUtils.basename(entry.uri);
            if (entry.isFile && name === ReservedNames.CONFIG_FILE) {
                roots.set(folder.toString(), folder);
                const config = await this.readConfiguration(entry.uri);
                if (config) configs.set(folder.toString(), config);
            } else if (entry.isDirectory && this.shouldIncludeEntry(entry)) {
                await this.findConfigurations(entry.uri, roots, configs);
            }
        }
    }

    private async readConfiguration(uri: URI): Promise<RootConfiguration | undefined> {
        try {
            const text = await this.fileSystemProvider.readFile(uri);
            return text.trim() ? (JSON.parse(text) as RootConfiguration) : {};
        } catch (e) {
            console.warn(`${uri.toString()}: ignored (${(e as Error).message})`);
            return undefined;
        }
    }
}

/**
 * The documents of the workspace. A request for a document that is neither open nor readable
 * (one closed a moment ago and dropped because it has no file) is refused with a RequestFailed
 * error naming the document: Langium's request handlers read it from the file system and would
 * answer the read error as an internal error.
 */
export class AdlLspLangiumDocuments extends DefaultLangiumDocuments {
    override async getOrCreateDocument(uri: URI, cancellationToken?: CancellationToken): Promise<LangiumDocument> {
        try {
            return await super.getOrCreateDocument(uri, cancellationToken);
        } catch (e) {
            if (isOperationCancelled(e) || e instanceof ResponseError) throw e;
            throw new ResponseError(
                LSPErrorCodes.RequestFailed,
                `${uri.toString()} is not open and cannot be read: ${e instanceof Error ? e.message : String(e)}`,
            );
        }
    }
}

/** Documents of the built-in library are never validated (nor published to the client). */
export class AdlLspDocumentBuilder extends DefaultDocumentBuilder {
    private readonly roots: ModelRoots;

    constructor(services: AdlSharedServices) {
        super(services);
        this.roots = services.maa.ModelRoots;
    }

    protected override shouldValidate(document: LangiumDocument): boolean {
        return !this.roots.isBuiltin(document.uri) && super.shouldValidate(document);
    }
}

/**
 * Watched-file changes as Langium handles them, plus: when a `maa.json` appears, changes or
 * disappears, the model roots are found again and every model file is rebuilt (packages,
 * scopes and reserved names may all have changed).
 *
 * A document closed in the editor that has no file (opened under a new name and never saved)
 * leaves the workspace: it is deleted from the documents and the index, the documents that
 * linked against it are rebuilt, and its diagnostics are cleared (Langium's builder publishes
 * empty diagnostics for deleted documents). Otherwise its errors would come back on every
 * later build and every such document would stay in memory. A document with a file that was
 * closed without saving goes back to the file's text (Langium would keep the editor's text).
 *
 * A build that fails (a bug in a check that escaped its guard, a stack overflow) is logged and
 * the server goes on; Langium leaves that rejection unhandled, which ends a Node process.
 */
export class AdlDocumentUpdateHandler extends DefaultDocumentUpdateHandler {
    private readonly adlWorkspace: AdlLspWorkspaceManager;
    private readonly builder: DocumentBuilder;
    private readonly lock: WorkspaceLock;
    private readonly documents: LangiumDocuments;
    private readonly roots: ModelRoots;
    private readonly files: FileSystemProvider;
    private readonly openDocuments: LangiumSharedServices['workspace']['TextDocuments'];
    private readonly log: (message: string) => void;

    constructor(services: LangiumSharedServices & AdlSharedServices) {
        super(services);
        this.files = services.workspace.FileSystemProvider;
        this.openDocuments = services.workspace.TextDocuments;
        this.log = serverLog(services);
        this.adlWorkspace = services.workspace.WorkspaceManager as AdlLspWorkspaceManager;
        this.builder = services.workspace.DocumentBuilder;
        this.lock = services.workspace.WorkspaceLock;
        this.documents = services.workspace.LangiumDocuments;
        this.roots = services.maa.ModelRoots;
    }

    override didChangeWatchedFiles(params: DidChangeWatchedFilesParams): void {
        super.didChangeWatchedFiles(params);
        if (params.changes.some((c) => UriUtils.basename(URI.parse(c.uri)) === ReservedNames.CONFIG_FILE)) {
            this.afterStartup('reloading the model roots', () =>
                this.lock.write(async (token) => {
                    await this.adlWorkspace.reloadModelRoots();
                    const all = this.documents.all
                        .filter((d) => !this.roots.isBuiltin(d.uri))
                        .map((d) => d.uri)
                        .toArray();
                    await this.builder.update(all, [], token);
                }),
            );
        }
    }

    protected override fireDocumentUpdate(changed: URI[], deleted: URI[]): void {
        this.afterStartup('building the workspace', () => this.lock.write((token) => this.builder.update(changed, deleted, token)));
    }

    didCloseDocument(event: Parameters<NonNullable<DocumentUpdateHandler['didCloseDocument']>>[0]): void {
        const uri = URI.parse(event.document.uri);
        if (this.roots.isBuiltin(uri)) return;
        this.afterStartup(`handling the closed document ${uri.toString()}`, async () => {
            const file = await this.hasFile(uri);
            // Opened again meanwhile: the editor's text is the document again.
            const document = this.documents.getDocument(uri);
            if (this.openDocuments.get(uri.toString()) || !document) return;
            if (!file) {
                await this.lock.write((token) => this.builder.update([], [uri], token));
            } else if (await this.differsFromFile(uri, document.textDocument.getText())) {
                // Closed without saving: the workspace goes back to the text on disk.
                await this.lock.write((token) => this.builder.update([uri], [], token));
            }
        });
    }

    private async differsFromFile(uri: URI, text: string): Promise<boolean> {
        try {
            return (await this.files.readFile(uri)) !== text;
        } catch {
            return false;
        }
    }

    /** Whether a document has a file (unreadable storage counts as a file: nothing is dropped on doubt). */
    private async hasFile(uri: URI): Promise<boolean> {
        try {
            return await this.files.exists(uri);
        } catch {
            return true;
        }
    }

    /** Runs a workspace action once the workspace is loaded; a failure is logged, never left unhandled. */
    private afterStartup(what: string, action: () => Promise<unknown>): void {
        this.adlWorkspace.ready.then(action).catch((e: unknown) => {
            if (!isOperationCancelled(e)) this.log(`Error ${what}: ${e instanceof Error ? (e.stack ?? e.message) : String(e)}`);
        });
    }
}
