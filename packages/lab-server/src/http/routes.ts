// The lab's routes and the checks in front of each (docs/lab.md "Adding routes"): a route is
// `public` (login, invitations, single sign-on), for any logged-in `user`, or `instructor`-only.
// Behind every non-public route: a session (401 without), the role (403), and for every
// state-changing method the session's CSRF token in the X-CSRF-Token header (403 without).
// Other parts of the lab (exercises, the IDE's lab mode) add their routes with `add`.
import type { IncomingMessage, ServerResponse } from 'node:http';
import { HttpError } from '@maa/ide-server/http';
import type { Authenticated } from '../auth/sessions.js';
import type { LabStore } from '../storage/index.js';

export type Access = 'public' | 'user' | 'instructor';

export interface LabRequest {
    req: IncomingMessage;
    res: ServerResponse;
    url: URL;
    /** the `:name` segments of the pattern, decoded; `*` is the rest of the path */
    params: Record<string, string>;
    /** the client's address (behind --trust-proxy: what the proxy says) */
    clientAddress: string;
    store: LabStore;
}

/** A request to a non-public route: who sent it. */
export interface AuthedRequest extends LabRequest {
    auth: Authenticated;
}

export type PublicHandler = (r: LabRequest) => Promise<void> | void;
export type AuthedHandler = (r: AuthedRequest) => Promise<void> | void;

export type LabRoute =
    | { method: string; path: string; access: 'public'; handler: PublicHandler }
    | { method: string; path: string; access: 'user' | 'instructor'; handler: AuthedHandler };

/** Methods that change nothing (no CSRF token needed). */
export const SAFE_METHODS = new Set(['GET', 'HEAD', 'OPTIONS']);

interface Compiled {
    route: LabRoute;
    segments: string[];
}

export interface Match {
    route: LabRoute;
    params: Record<string, string>;
}

/**
 * Routes by pattern: `/api/courses/:course/students` (a `:name` matches one segment), a final `*`
 * matches the rest (at least one segment). Exact segments win over parameters when both match.
 */
export class LabRoutes {
    private readonly routes: Compiled[] = [];

    add(route: LabRoute): this {
        if (!route.path.startsWith('/')) throw new Error(`a route's path starts with /: ${route.path}`);
        const segments = route.path.split('/').slice(1);
        if (segments.slice(0, -1).includes('*')) throw new Error(`* may only end a route's path: ${route.path}`);
        const method = route.method.toUpperCase();
        if (this.routes.some((r) => r.route.method === method && r.route.path === route.path))
            throw new Error(`the route ${method} ${route.path} exists already`);
        this.routes.push({ route: { ...route, method } as LabRoute, segments });
        // More specific first: fewer parameters, then no wildcard.
        this.routes.sort((a, b) => weight(a.segments) - weight(b.segments));
        return this;
    }

    /** The route for the request, or an HttpError: 404 for an unknown path, 405 for another method. */
    match(method: string, pathname: string): Match {
        const given = pathname.split('/').slice(1);
        const allowed: string[] = [];
        for (const { route, segments } of this.routes) {
            const params = matchSegments(segments, given);
            if (!params) continue;
            if (route.method === method || (method === 'HEAD' && route.method === 'GET')) return { route, params };
            allowed.push(route.method);
        }
        if (allowed.length > 0)
            throw new HttpError(405, `method ${method} not allowed on ${pathname} (allowed: ${[...new Set(allowed)].join(', ')})`);
        throw new HttpError(404, `unknown route: ${method} ${pathname}`);
    }
}

function weight(segments: string[]): number {
    return segments.filter((s) => s.startsWith(':')).length + (segments.at(-1) === '*' ? 100 : 0);
}

function matchSegments(pattern: string[], given: string[]): Record<string, string> | undefined {
    const params: Record<string, string> = {};
    for (let i = 0; i < pattern.length; i++) {
        const p = pattern[i] as string;
        if (p === '*') {
            const rest = given.slice(i);
            if (rest.length === 0 || rest.some((s) => s === '')) return undefined;
            params['*'] = rest.map(decode).join('/');
            return params;
        }
        const g = given[i];
        if (g === undefined) return undefined;
        if (p.startsWith(':')) {
            if (g === '') return undefined;
            params[p.slice(1)] = decode(g);
        } else if (p !== g) return undefined;
    }
    return given.length === pattern.length ? params : undefined;
}

function decode(segment: string): string {
    try {
        return decodeURIComponent(segment);
    } catch {
        throw new HttpError(400, `malformed path segment: ${segment}`);
    }
}
