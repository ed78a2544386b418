import { DiagramServer, UpdateModelAction, type Action, type DiagramServices } from 'sprotty-protocol';

/**
 * One client diagram. Our models arrive laid out by the server, so a client that does not say
 * otherwise needs no layout round trip (Sprotty's default is to ask the client for bounds);
 * updates are animated.
 */
export class MaaDiagramServer extends DiagramServer {
    constructor(dispatch: <A extends Action>(action: A) => Promise<void>, services: DiagramServices) {
        super((action) => dispatch(action.kind === UpdateModelAction.KIND ? { ...action, animate: true } : action), services);
    }

    override get needsClientLayout(): boolean {
        return this.state.options?.needsClientLayout === true;
    }

    /** The source document's URI the client asked for. */
    get sourceUri(): string | undefined {
        const uri = this.state.options?.sourceUri;
        return typeof uri === 'string' ? uri : undefined;
    }
}
