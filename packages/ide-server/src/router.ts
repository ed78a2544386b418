import type { IncomingMessage, ServerResponse } from 'node:http';
import { HttpError, sendError, type Redact } from './http-util.js';

export interface RequestContext {
    req: IncomingMessage;
    res: ServerResponse;
    query: URLSearchParams;
}

export type Handler = (ctx: RequestContext) => Promise<void> | void;

/** Exact-path routes with per-method handlers: unknown paths 404, other methods 405 (JSON). */
export class Router {
    private readonly routes = new Map<string, Map<string, Handler>>();

    /** @param redact what error bodies pass through (no absolute paths) */
    constructor(private readonly redact?: Redact) {}

    on(method: string, pathname: string, handler: Handler): this {
        let methods = this.routes.get(pathname);
        if (!methods) this.routes.set(pathname, (methods = new Map()));
        methods.set(method, handler);
        if (method === 'GET' && !methods.has('HEAD')) methods.set('HEAD', handler);
        return this;
    }

    /** Dispatches a request; every failure becomes a JSON error answer. */
    async dispatch(req: IncomingMessage, res: ServerResponse, pathname: string, query: URLSearchParams): Promise<void> {
        try {
            const methods = this.routes.get(pathname);
            if (!methods) throw new HttpError(404, `unknown route: ${req.method} ${pathname}`);
            const handler = methods.get(req.method ?? '');
            if (!handler) {
                res.setHeader('Allow', [...methods.keys()].join(', '));
                throw new HttpError(405, `method ${req.method} not allowed on ${pathname} (allowed: ${[...methods.keys()].join(', ')})`);
            }
            await handler({ req, res, query });
        } catch (e) {
            sendError(res, e, this.redact, `${req.method} ${pathname}`);
        }
    }
}
