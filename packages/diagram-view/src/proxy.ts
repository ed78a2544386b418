/**
 * The diagram's model source: a `DiagramServerProxy` whose channel is the shell's
 * {@link DiagramHost} (LSP notifications `diagram/accept` to the diagram server in the language
 * server worker). Every model that arrives is normalized for the client's registry and handed to
 * the model listeners. An update that brings the model shown already (but for its revision: the
 * server sends one after every build's validation, also when a keystroke in a behavior body or an
 * expression changed nothing the diagram shows) is not applied: Sprotty would render the whole
 * diagram again for nothing (issue 18: the longest tasks while typing).
 */
import { decorate, injectable } from 'inversify';
import { DiagramServerProxy } from 'sprotty';
import type { Action, ActionMessage } from 'sprotty-protocol';
import type { DiagramHost, Disposable } from './contracts.js';
import { normalizeSchemaTypes, type SchemaElement } from './schema.js';

/** Called with each new model (`kind`: `setModel` or `updateModel`). */
export type ModelListener = (root: SchemaElement, kind: string) => void;

export class MaaDiagramProxy extends DiagramServerProxy {
    private host?: DiagramHost;
    private subscription?: Disposable;
    readonly modelListeners = new Set<ModelListener>();
    /** The last model received (set or update), as text without its revision. */
    private shownText: string | undefined;
    /** How many updates were not applied because they brought the shown model (for tests). */
    skippedUpdates = 0;

    connect(host: DiagramHost): void {
        this.host = host;
        this.subscription = host.onDiagramMessage((message) => this.messageReceived(message));
    }

    disconnect(): void {
        this.subscription?.dispose();
        this.subscription = undefined;
        this.host = undefined;
    }

    protected sendMessage(message: ActionMessage): void {
        this.host?.sendDiagramMessage(message);
    }

    protected override messageReceived(data: unknown): void {
        const object = (typeof data === 'string' ? JSON.parse(data) : data) as ActionMessage | undefined;
        const action = object?.action as (Action & { newRoot?: SchemaElement }) | undefined;
        const mine = !object?.clientId || object.clientId === this.clientId;
        if (mine && action && (action.kind === 'setModel' || action.kind === 'updateModel') && action.newRoot) {
            normalizeSchemaTypes(action.newRoot);
            const text = modelText(action.newRoot);
            const same = action.kind === 'updateModel' && text === this.shownText;
            this.shownText = text;
            if (same) this.skippedUpdates++;
            else super.messageReceived(object);
            for (const l of [...this.modelListeners]) l(action.newRoot, action.kind);
            return;
        }
        super.messageReceived(object);
    }
}
decorate(injectable(), MaaDiagramProxy);

/** A model as text, without the revision the server counts up with every update. */
function modelText(root: SchemaElement): string {
    return JSON.stringify({ ...root, revision: undefined });
}
