import { createHash, randomBytes, timingSafeEqual } from 'node:crypto';
import type { IncomingMessage } from 'node:http';

/**
 * Who may talk to maa-ide (docs/ide.md "Access"): requests must name the server by a loopback
 * name or the `--host` it listens on (a DNS-rebound name is refused), come from its own origin
 * when the browser says where they come from (CSRF, cross-site WebSockets), and carry the
 * per-start token (cookie or `Authorization: Bearer`), as Jupyter does.
 */

/** Host names every server accepts besides the one it listens on (WHATWG-normalized). */
const LOOPBACK_NAMES = ['127.0.0.1', 'localhost', '[::1]'];
/** Characters a token may hold: URL- and cookie-safe without escaping. */
const TOKEN_SYNTAX = /^[A-Za-z0-9._~-]+$/;
export const MIN_TOKEN_LENGTH = 16;

/** A fresh token: 32 random bytes, base64url. */
export function generateToken(): string {
    return randomBytes(32).toString('base64url');
}

/** The reason a given token cannot be used, or undefined when it can. */
export function tokenProblem(token: string): string | undefined {
    if (token.length < MIN_TOKEN_LENGTH) return `the token must have at least ${MIN_TOKEN_LENGTH} characters`;
    if (!TOKEN_SYNTAX.test(token)) return 'the token may hold only letters, digits and . _ ~ -';
    return undefined;
}

/** Constant-time comparison (hashing first makes the lengths equal, so the length leaks nothing either). */
export function sameSecret(given: string, expected: string): boolean {
    const a = createHash('sha256').update(given).digest();
    const b = createHash('sha256').update(expected).digest();
    return timingSafeEqual(a, b);
}

/** `host[:port]` as the URL parser normalizes it (lower case, IPv6 in brackets), or undefined when malformed. */
function parseHost(value: string): URL | undefined {
    // No userinfo, path or query may hide in a Host header.
    if (!/^[A-Za-z0-9.:[\]-]+$/.test(value)) return undefined;
    try {
        return new URL(`http://${value}`);
    } catch {
        return undefined;
    }
}

/**
 * Which Host headers a server answers to, and the origin each belongs to (docs/ide.md "Access",
 * docs/lab.md "Security"): a request must name the server by a loopback name or the address it
 * listens on, with its port, or by the host of its public URL, so a DNS-rebound name is refused;
 * and when the browser says where a request comes from (CSRF, cross-site WebSockets), that
 * origin must be the named host's own. maa-ide and maa-lab both admit requests with it.
 */
export class HostOriginCheck {
    /** Accepted Host headers (`host[:port]` as the URL parser normalizes it) → the origin they belong to. */
    private readonly origins = new Map<string, string>();

    /**
     * @param server the server's name in refusals (`maa-ide`)
     * @param listenHost the address it listens on (also accepted as Host unless a wildcard)
     * @param port the port it listens on
     * @param publicUrl the address users open when that is another (behind a proxy: the proxy's https address)
     */
    constructor(
        private readonly server: string,
        listenHost: string,
        port: number,
        publicUrl?: string,
    ) {
        const own = parseHost(listenHost.includes(':') && !listenHost.startsWith('[') ? `[${listenHost}]` : listenHost)?.hostname;
        // 0.0.0.0 and :: are "every address", never a name a browser would send.
        const wildcard = own === '0.0.0.0' || own === '[::]';
        for (const name of [...LOOPBACK_NAMES, ...(own && !wildcard ? [own] : [])]) {
            const url = new URL(`http://${name}:${port}`);
            this.origins.set(url.host, url.origin);
        }
        if (publicUrl) {
            const url = new URL(publicUrl);
            this.origins.set(url.host, url.origin);
        }
    }

    /** Undefined when the request's Host and Origin are acceptable, else why not. */
    refusal(req: IncomingMessage): string | undefined {
        const header = req.headers.host;
        if (!header) return 'the request has no Host header';
        const host = parseHost(header);
        const expected = host && this.origins.get(host.host);
        if (expected === undefined) {
            return `${this.server} does not serve the host ${JSON.stringify(header)} (it serves ${[...this.origins.keys()].join(', ')})`;
        }
        const given = req.headers.origin;
        if (given === undefined) return undefined;
        let origin: string | undefined;
        try {
            origin = new URL(given).origin;
        } catch {
            origin = undefined;
        }
        if (origin !== expected) return `requests from the origin ${JSON.stringify(given)} are not accepted (only from ${expected})`;
        return undefined;
    }
}

export type AccessRefusal = { status: 400 | 401 | 403; message: string };

export type Authentication =
    /** Token from the cookie or the Authorization header. */
    | { ok: true; via: 'cookie' | 'bearer' }
    /** Token from `?token=`: set the cookie (and redirect pages to the URL without it). */
    | { ok: true; via: 'query' }
    | { ok: false; refusal: AccessRefusal };

/** A request (or WebSocket upgrade) let in, with its parsed URL, or refused and why. */
export type Admission =
    | { ok: true; url: URL; via: 'cookie' | 'bearer' | 'query' | 'public' | 'capability' }
    /** `unauthenticated`: the Host and Origin were fine, the token was missing or wrong (401). */
    | { ok: false; refusal: AccessRefusal; unauthenticated: boolean };

/**
 * The one path served without the token: the script of VS Code's webview service worker
 * (`assets/service-worker-<hash>.js`, a build file of the workbench that holds no workspace data).
 * Chromium fetches a service worker's script without the page's SameSite=Strict token cookie
 * when a webview frame registers it, so without this exception no webview (the diagram, the
 * simulate view) could start. Only GET and HEAD, only that name (the URL is already normalized, so
 * no `..` reaches past it), and only after the Host and Origin checks (docs/ide.md, "Access").
 */
const PUBLIC_SCRIPT = /^\/assets\/service-worker-[\w-]+\.js$/;

export function isPublicScript(method: string | undefined, pathname: string): boolean {
    return (method === 'GET' || method === 'HEAD') && PUBLIC_SCRIPT.test(pathname);
}

export class AccessGuard {
    private readonly hostOrigin: HostOriginCheck;

    /**
     * @param listenHost the `--host` the server listens on (also accepted as Host)
     * @param port the port it serves
     * @param token the per-start secret
     * @param capabilityPath whether a path carries a capability of its own instead of the token
     *   (the viser view's, viser-view.ts); Host and Origin are checked all the same
     */
    constructor(
        listenHost: string,
        readonly port: number,
        readonly token: string,
        private readonly capabilityPath: (pathname: string) => boolean = () => false,
    ) {
        this.hostOrigin = new HostOriginCheck('maa-ide', listenHost, port);
    }

    /** The cookie that holds the token; the port is in its name because cookies ignore ports. */
    get cookieName(): string {
        return `maa-ide-token-${this.port}`;
    }

    /** The `Set-Cookie` value that stores the token in the browser. */
    setCookie(): string {
        return `${this.cookieName}=${this.token}; HttpOnly; SameSite=Strict; Path=/`;
    }

    /**
     * Every check a request or upgrade passes before it is routed, in this order: Host and Origin
     * (so a refused page reads, writes and starts nothing), a well-formed URL, the token.
     */
    admit(req: IncomingMessage): Admission {
        const refusal = this.checkOrigin(req);
        if (refusal) return { ok: false, refusal, unauthenticated: false };
        let url: URL;
        try {
            url = new URL(req.url ?? '/', 'http://localhost');
        } catch {
            return { ok: false, refusal: { status: 400, message: 'malformed URL' }, unauthenticated: false };
        }
        if (isPublicScript(req.method, url.pathname)) return { ok: true, url, via: 'public' };
        if (this.capabilityPath(url.pathname)) return { ok: true, url, via: 'capability' };
        const auth = this.authenticate(req, url.searchParams);
        return auth.ok ? { ok: true, url, via: auth.via } : { ok: false, refusal: auth.refusal, unauthenticated: true };
    }

    /** Host and Origin (docs/ide.md, HostOriginCheck): undefined when both are acceptable. */
    checkOrigin(req: IncomingMessage): AccessRefusal | undefined {
        const message = this.hostOrigin.refusal(req);
        return message === undefined ? undefined : { status: 403, message };
    }

    /** Checks the token of a request: the query parameter, the cookie, or `Authorization: Bearer`. */
    authenticate(req: IncomingMessage, query: URLSearchParams): Authentication {
        const fromQuery = query.get('token');
        if (fromQuery !== null && sameSecret(fromQuery, this.token)) return { ok: true, via: 'query' };
        const cookie = readCookie(req.headers.cookie, this.cookieName);
        if (cookie !== undefined && sameSecret(cookie, this.token)) return { ok: true, via: 'cookie' };
        const bearer = /^Bearer\s+(\S+)\s*$/i.exec(req.headers.authorization ?? '')?.[1];
        if (bearer !== undefined && sameSecret(bearer, this.token)) return { ok: true, via: 'bearer' };
        const given = fromQuery !== null || cookie !== undefined || bearer !== undefined;
        return {
            ok: false,
            refusal: {
                status: 401,
                message: given
                    ? 'the token is not valid (maa-ide makes a new one at every start: open the URL it printed)'
                    : 'a token is required: open the URL maa-ide printed (it holds ?token=...), or send "Authorization: Bearer <token>"',
            },
        };
    }
}

/** The value of one cookie of a `Cookie` header (the last one when repeated). */
export function readCookie(header: string | undefined, name: string): string | undefined {
    if (!header) return undefined;
    let value: string | undefined;
    for (const part of header.split(';')) {
        const eq = part.indexOf('=');
        if (eq < 0) continue;
        if (part.slice(0, eq).trim() === name) value = part.slice(eq + 1).trim();
    }
    return value;
}

/** The page a browser gets without the token (text only: nothing of the app is revealed). */
export function loginPage(): string {
    return `<!doctype html>
<html lang="en"><head><meta charset="utf-8"><title>maa-ide: token required</title></head>
<body style="font-family: sans-serif; max-width: 40em; margin: 3em auto">
<h1>maa-ide needs its token</h1>
<p>Open the URL that <code>maa-ide</code> printed when it started (it ends with
<code>?token=...</code>). The browser then keeps the token in a cookie for this address and port.</p>
<p>maa-ide makes a new token at every start, so an old bookmark does not work after a restart.</p>
</body></html>
`;
}
