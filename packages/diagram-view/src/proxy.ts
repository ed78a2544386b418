/**
 * The diagram's model source: a `DiagramServerProxy` whose channel is the shell's
 * {@link DiagramHost} (LSP notifications `diagram/accept` to the diagram server in the language
 * server worker). Every model that arrives is normalized for the client's registry and handed to
 * the model listeners.
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
            super.messageReceived(object);
            for (const l of [...this.modelListeners]) l(action.newRoot, action.kind);
            return;
        }
        super.messageReceived(object);
    }
}
decorate(injectable(), MaaDiagramProxy);
