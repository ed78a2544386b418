import type { IncomingMessage, ServerResponse } from 'node:http';
import type { Duplex } from 'node:stream';
import { type AccessRefusal, type Admission, AccessGuard, loginPage } from './access.js';
import { sendJson, sendText } from './http-util.js';
import { rejectUpgrade } from './proxy.js';

/**
 * The one door of maa-ide (docs/ide.md "Access"): every request and every WebSocket upgrade
 * passes here before anything else sees it. The AccessGuard checks Host, Origin and the token;
 * the gate answers what it refuses, turns a `?token=` login into the cookie, and takes the
 * token out of what it lets through.
 */
export class Gate {
    private guard: AccessGuard | undefined;

    /** Known once the server listens (the port may be 0 until then); no request arrives before. */
    open(host: string, port: number, token: string, capabilityPath?: (pathname: string) => boolean): void {
        this.guard = new AccessGuard(host, port, token, capabilityPath);
    }

    /**
     * The URL of an admitted request that still needs its answer, or undefined when the gate
     * answered it already (a refusal, or the redirect that ends a login).
     */
    admitRequest(req: IncomingMessage, res: ServerResponse): URL | undefined {
        const admission = this.admit(req);
        if (!admission.ok) {
            refuse(req, res, admission.refusal, admission.unauthenticated);
            return undefined;
        }
        const { url } = admission;
        if (admission.via === 'query') {
            res.setHeader('Set-Cookie', this.opened().setCookie());
            if (isPage(req, url.pathname)) {
                // The token leaves the address bar (and history); the cookie carries it from now on.
                res.writeHead(302, { Location: withoutToken(url), 'Content-Length': 0, 'Cache-Control': 'no-store' });
                res.end();
                return undefined;
            }
        }
        return url;
    }

    /** The URL of an admitted upgrade (its `req.url` without the token), or undefined when refused (the socket is answered). */
    admitUpgrade(req: IncomingMessage, socket: Duplex): URL | undefined {
        const admission = this.admit(req);
        if (!admission.ok) {
            rejectUpgrade(socket, admission.refusal.status, admission.refusal.message);
            return undefined;
        }
        const { url } = admission;
        // maa-ide's token is not the simulator's business.
        req.url = withoutToken(url);
        return url;
    }

    private admit(req: IncomingMessage): Admission {
        return this.opened().admit(req);
    }

    private opened(): AccessGuard {
        if (!this.guard) throw new Error('maa-ide: a request arrived before the server listened');
        return this.guard;
    }
}

/** Whether `pathname` is `prefix` or below it. */
export function isUnder(pathname: string, prefix: string): boolean {
    return pathname === prefix || pathname.startsWith(`${prefix}/`);
}

/** A page a browser navigates to (not the API or the simulator): gets HTML, and redirects. */
function isPage(req: IncomingMessage, pathname: string): boolean {
    return (req.method === 'GET' || req.method === 'HEAD') && !isUnder(pathname, '/api') && !isUnder(pathname, '/sim');
}

/** Answers a refused request: a page that asks for the token gets the login page, the rest JSON. */
function refuse(req: IncomingMessage, res: ServerResponse, refusal: AccessRefusal, unauthenticated: boolean): void {
    if (!unauthenticated) {
        sendJson(res, refusal.status, { error: refusal.message });
        return;
    }
    res.setHeader('WWW-Authenticate', 'Bearer realm="maa-ide"');
    const pathname = (req.url ?? '/').split('?')[0] ?? '/';
    if (isPage(req, pathname) && (req.headers.accept ?? '').includes('text/html'))
        sendText(res, 401, loginPage(), 'text/html; charset=utf-8');
    else sendJson(res, refusal.status, { error: refusal.message });
}

/** The path and query of a URL without its `token` parameter. */
function withoutToken(url: URL): string {
    const query = new URLSearchParams(url.searchParams);
    query.delete('token');
    const rest = query.toString();
    return `${url.pathname}${rest ? `?${rest}` : ''}`;
}
