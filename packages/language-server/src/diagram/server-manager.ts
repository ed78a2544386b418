import { DocumentState, URI, type LangiumDocument } from 'langium';
import { Disposable, type CancellationToken } from 'vscode-languageserver';
import { DefaultDiagramServerManager, DiagramActionNotification, type LangiumSprottySharedServices } from 'langium-sprotty';
import { RequestModelAction, type Action, type ActionMessage, type DiagramOptions, type DiagramServer } from 'sprotty-protocol';
import { MaaDiagramServer } from './diagram-server.js';
import type { MaaDiagramServices } from './services.js';

/**
 * How long to wait after a build before the diagrams are regenerated: the builds themselves follow
 * the edits (a new edit cancels the build under way), so this only merges builds that end close
 * together; every millisecond of it is part of keystroke → diagram (issue 18: 150 before).
 */
export const UPDATE_DELAY_MS = 30;
/** How long a model request waits at most for its source document's validation. */
const VALIDATION_WAIT_MS = 10_000;

/**
 * The diagram servers of one language server, one per client diagram. Unlike langium-sprotty's
 * default (which updates a diagram only when its own source document changed), every diagram is
 * regenerated after any document of the workspace changed: a component diagram shows
 * subcomponent types, behaviors and data types from other files of the family. Updates are
 * debounced, and skipped while the source document does not parse (the last good diagram stays).
 */
export class MaaDiagramServerManager extends DefaultDiagramServerManager {
    private readonly services: MaaDiagramServices;
    private readonly listeners = new Set<(message: ActionMessage) => void>();
    private timer: ReturnType<typeof setTimeout> | undefined;

    constructor(services: MaaDiagramServices) {
        const holder: { manager?: MaaDiagramServerManager } = {};
        // langium-sprotty's manager reads only these members of its services.
        const facade = {
            lsp: services.shared.lsp,
            ServiceRegistry: services.shared.ServiceRegistry,
            workspace: services.shared.workspace,
            diagram: {
                diagramServerFactory: (clientId: string, options?: DiagramOptions) => holder.manager!.createServer(clientId, options),
            },
        } as unknown as LangiumSprottySharedServices;
        super(facade);
        holder.manager = this;
        this.services = services;
    }

    /** Listens to every action sent to clients (besides the LSP notification, if connected). */
    onDidSend(listener: (message: ActionMessage) => void): Disposable {
        this.listeners.add(listener);
        return Disposable.create(() => this.listeners.delete(listener));
    }

    servers(): MaaDiagramServer[] {
        return [...this.diagramServerMap.values()] as MaaDiagramServer[];
    }

    /** Answers a model request once the workspace is built, so the model shows linked, validated documents. */
    override async acceptAction(message: ActionMessage): Promise<void> {
        if (message.action.kind === RequestModelAction.KIND) {
            const workspace = this.services.shared.workspace;
            // A language server answers after its workspace's start-up (services without a
            // connection, as in tools and tests, have none).
            if (this.connection) await workspace.WorkspaceManager.ready;
            const uri = (message.action as RequestModelAction).options?.sourceUri;
            if (typeof uri === 'string' && workspace.LangiumDocuments.hasDocument(URI.parse(uri))) {
                // Bounded: a document the builder never validates must not block the diagram.
                let timer: ReturnType<typeof setTimeout> | undefined;
                await Promise.race([
                    workspace.DocumentBuilder.waitUntil(DocumentState.Validated, URI.parse(uri)).catch(() => undefined),
                    new Promise((resolve) => {
                        timer = setTimeout(resolve, VALIDATION_WAIT_MS);
                    }),
                ]);
                clearTimeout(timer);
            }
            return workspace.WorkspaceLock.read(() => super.acceptAction(message));
        }
        return super.acceptAction(message);
    }

    protected createServer(clientId: string, _options?: DiagramOptions): DiagramServer {
        const d = this.services.diagram;
        return new MaaDiagramServer((action: Action) => this.send({ clientId, action }), {
            DiagramGenerator: d.DiagramGenerator,
            ModelLayoutEngine: d.ModelLayoutEngine,
            ServerActionHandlerRegistry: d.ServerActionHandlerRegistry,
        });
    }

    private async send(message: ActionMessage): Promise<void> {
        for (const listener of this.listeners) listener(message);
        await this.connection?.sendNotification(DiagramActionNotification.type, message);
    }

    protected override documentsBuilt(built: LangiumDocument[], _cancelToken: CancellationToken): Promise<void> {
        const changed = built.some((d) => this.changedUris.some((u) => u.toString() === d.uri.toString()));
        this.changedUris = [];
        if (changed && this.diagramServerMap.size > 0) this.schedule();
        return Promise.resolve();
    }

    private schedule(): void {
        if (this.timer) clearTimeout(this.timer);
        this.timer = setTimeout(() => {
            this.timer = undefined;
            void this.services.shared.workspace.WorkspaceLock.read(() => this.updateAll());
        }, UPDATE_DELAY_MS);
    }

    /** Regenerates every open diagram from the current documents and sends the updates. */
    async updateAll(): Promise<void> {
        const documents = this.services.shared.workspace.LangiumDocuments;
        for (const server of this.servers()) {
            const uri = server.sourceUri;
            const document = uri ? documents.getDocument(URI.parse(uri)) : undefined;
            if (!document || document.parseResult.lexerErrors.length > 0 || document.parseResult.parserErrors.length > 0) continue;
            try {
                const model = await this.services.diagram.DiagramGenerator.generate({
                    document,
                    options: server.state.options ?? {},
                    state: server.state,
                });
                await server.updateModel(model);
            } catch (err) {
                console.error(`Diagram update failed: ${(err as Error).message}`);
            }
        }
    }
}
