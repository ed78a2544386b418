import { DocumentState, URI, type LangiumDocument } from 'langium';
import { Disposable, type CancellationToken } from 'vscode-languageserver';
import { DefaultDiagramServerManager, DiagramActionNotification, type LangiumSprottySharedServices } from 'langium-sprotty';
import {
    RequestModelAction,
    type Action,
    type ActionMessage,
    type DiagramOptions,
    type DiagramServer,
    type SModelElement,
    type SModelRoot,
} from 'sprotty-protocol';
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
 *
 * A diagram's structure needs linked documents, not validated ones (issue 18: keystroke →
 * diagram): the update starts as soon as a build has linked and indexed every document (its
 * `IndexedReferences` phase), before that build validates, if no newer edit has reset a document
 * meanwhile (no half-linked model is shown; that edit's build updates the diagrams then). Its
 * elements keep the markers they had (the edited documents' diagnostics are not there yet), and
 * it is not sent if nothing changed; the update after the build's validation (sent after every
 * build, as before) brings the new markers. Updates
 * that a newer one overtook are dropped, so the client never gets an older model after a newer one.
 */
export class MaaDiagramServerManager extends DefaultDiagramServerManager {
    private readonly services: MaaDiagramServices;
    private readonly listeners = new Set<(message: ActionMessage) => void>();
    private timer: ReturnType<typeof setTimeout> | undefined;
    /** Counts update runs: a run sends nothing once a newer one has started. */
    private updateRun = 0;
    /** Update after a build's linking (true) or only after its validation, under the workspace lock (false: before issue 18). */
    updateAfterLinking = true;

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
        services.shared.workspace.DocumentBuilder.onBuildPhase(DocumentState.IndexedReferences, (built) => this.documentsLinked(built));
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

    private changedIn(built: LangiumDocument[]): boolean {
        return built.some((d) => this.changedUris.some((u) => u.toString() === d.uri.toString()));
    }

    /** A build has linked and indexed its documents: the diagrams can be updated now. */
    private documentsLinked(built: LangiumDocument[]): Promise<void> {
        if (this.updateAfterLinking && this.changedIn(built) && this.diagramServerMap.size > 0) {
            // At once, not debounced: this build got through linking, so no newer edit came
            // meanwhile; the validation goes on while the diagrams are laid out.
            if (this.timer) clearTimeout(this.timer);
            this.timer = undefined;
            void this.updateAll(true);
        }
        return Promise.resolve();
    }

    protected override documentsBuilt(built: LangiumDocument[], _cancelToken: CancellationToken): Promise<void> {
        const changed = this.changedIn(built);
        this.changedUris = [];
        if (changed && this.diagramServerMap.size > 0) this.schedule();
        return Promise.resolve();
    }

    /** Updates the diagrams soon, under the workspace lock. */
    private schedule(): void {
        if (this.timer) clearTimeout(this.timer);
        this.timer = setTimeout(() => {
            this.timer = undefined;
            void this.services.shared.workspace.WorkspaceLock.read(() => this.updateAll());
        }, UPDATE_DELAY_MS);
    }

    /** Whether every document is linked and indexed (a new edit resets its documents to an earlier state). */
    private allLinked(): boolean {
        return this.services.shared.workspace.LangiumDocuments.all.every((d) => d.state >= DocumentState.IndexedReferences);
    }

    /**
     * Regenerates every open diagram from the current documents and sends the updates; with
     * `whileLinked`, outside the workspace lock, only as long as every document is linked (each
     * diagram is generated in one go up to its layout, which reads no documents).
     */
    async updateAll(whileLinked = false): Promise<void> {
        const run = ++this.updateRun;
        const documents = this.services.shared.workspace.LangiumDocuments;
        for (const server of this.servers()) {
            if (whileLinked && !this.allLinked()) return;
            const uri = server.sourceUri;
            const document = uri ? documents.getDocument(URI.parse(uri)) : undefined;
            if (!document || document.parseResult.lexerErrors.length > 0 || document.parseResult.parserErrors.length > 0) continue;
            try {
                const model = await this.services.diagram.DiagramGenerator.generate({
                    document,
                    options: server.state.options ?? {},
                    state: server.state,
                });
                // A newer update has started (after a newer edit): its models replace these.
                if (run !== this.updateRun) return;
                const previous = server.state.currentRoot;
                if (whileLinked) {
                    keepMarkers(model, previous);
                    // Nothing the diagram shows changed (an expression, a comment): the update after the validation follows.
                    if (previous && sameModel(previous, model)) continue;
                }
                await server.updateModel(model);
            } catch (err) {
                console.error(`Diagram update failed: ${(err as Error).message}`);
            }
        }
    }
}

/**
 * The markers of the shown model on the elements of a model generated before its documents'
 * validation (whose diagnostics are not there yet): like an editor's squiggles, markers change
 * when the validation ends (the update after the build sends them), and do not blink off meanwhile.
 */
function keepMarkers(model: SModelRoot, previous: SModelRoot | undefined): void {
    if (!previous) return;
    const before = new Map<string, unknown>();
    const collect = (e: SModelElement): void => {
        const severity = (e as { severity?: unknown }).severity;
        if (severity !== undefined) before.set(e.id, severity);
        for (const c of e.children ?? []) collect(c);
    };
    collect(previous);
    const apply = (e: SModelElement): void => {
        const marked = e as { severity?: unknown };
        if (marked.severity === undefined && before.has(e.id)) marked.severity = before.get(e.id);
        for (const c of e.children ?? []) apply(c);
    };
    apply(model);
}

/** Whether two models are the same but for their revision (which the diagram server sets). */
function sameModel(a: SModelRoot, b: SModelRoot): boolean {
    const text = (m: SModelRoot): string => JSON.stringify({ ...m, revision: undefined });
    return text(a) === text(b);
}
