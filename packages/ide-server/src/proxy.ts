import { STATUS_CODES, type IncomingMessage, type ServerResponse } from 'node:http';
import type { Duplex } from 'node:stream';
import httpProxy from 'http-proxy';
import { sendJson } from './http-util.js';
import type { SimTarget } from './sim-session.js';

export const ROSBRIDGE_PATH = '/sim/rosbridge';
export const VISER_PATH = '/sim/viser';

/**
 * The `/sim/...` part of the one origin: `/sim/rosbridge` (WebSocket) → the session's rosbridge,
 * `/sim/viser/...` (HTTP and WebSocket) → its viser server, with the prefix stripped.
 *
 * viser's client derives its WebSocket URL from `window.location.href` (query dropped, one
 * trailing slash removed), so the page `/sim/viser/` connects to `/sim/viser`: the bare prefix
 * is therefore a WebSocket route too, and the bare prefix over HTTP redirects to `/sim/viser/`
 * so relative URLs resolve below it.
 *
 * maa-sim's endpoints accept only requests with a loopback Host, no Origin and the session's
 * bearer token (docs/simulation.md). maa-ide checked the browser's Host, Origin and token
 * already, so every proxied request and handshake goes out with the target's Host
 * (`changeOrigin`), without Origin and Cookie (maa-ide's token stays here), and with
 * `Authorization: Bearer <session token>`.
 */
export class SimProxy {
    private readonly proxy = httpProxy.createProxyServer({ ws: true, xfwd: false, changeOrigin: true });

    constructor(private readonly sessions: SimProxySessions) {
        this.proxy.on('error', (err, _req, target) => {
            // `target` is the client's response (HTTP) or socket (WebSocket upgrade).
            if (isServerResponse(target)) {
                if (!target.headersSent) sendJson(target, 502, { error: `the simulator did not answer: ${err.message}` });
                else target.destroy();
            } else {
                (target as Duplex).destroy();
            }
        });
    }

    /** Handles `/sim/...` HTTP requests; false when the path is not ours. */
    handleRequest(req: IncomingMessage, res: ServerResponse, pathname: string): boolean {
        if (pathname === ROSBRIDGE_PATH || pathname.startsWith(`${ROSBRIDGE_PATH}/`)) {
            sendJson(res, 426, { error: `${ROSBRIDGE_PATH} is a WebSocket endpoint (rosbridge v2)` });
            return true;
        }
        if (pathname === VISER_PATH) {
            const query = req.url?.includes('?') ? req.url.slice(req.url.indexOf('?')) : '';
            res.writeHead(301, { Location: `${VISER_PATH}/${query}`, 'Content-Length': 0 });
            res.end();
            return true;
        }
        if (!pathname.startsWith(`${VISER_PATH}/`)) return false;
        const session = this.sessions.target();
        if (!session?.viser) {
            sendJson(res, 502, { error: 'no simulation session is running (start one with POST /api/sim/start)' });
            return true;
        }
        this.sessions.signOfLife();
        req.url = stripPrefix(req.url ?? '/', VISER_PATH);
        this.proxy.web(req, res, { target: session.viser.origin, headers: forwardHeaders(req, session.token) });
        return true;
    }

    /** Handles WebSocket upgrades of `/sim/rosbridge` and `/sim/viser`; false when not ours. */
    handleUpgrade(req: IncomingMessage, socket: Duplex, head: Buffer, pathname: string): boolean {
        let target: URL | undefined;
        let prefix: string;
        const session = this.sessions.target();
        if (pathname === ROSBRIDGE_PATH || pathname.startsWith(`${ROSBRIDGE_PATH}/`)) {
            prefix = ROSBRIDGE_PATH;
            target = session?.rosbridge;
        } else if (pathname === VISER_PATH || pathname.startsWith(`${VISER_PATH}/`)) {
            prefix = VISER_PATH;
            target = session?.viser;
        } else {
            return false;
        }
        if (!session || !target) {
            rejectUpgrade(socket, 502, 'no simulation session is running');
            return true;
        }
        // An open WebSocket is a client: the session lives while one is open.
        const release = this.sessions.clientOpened();
        socket.once('close', release);
        req.url = stripPrefix(req.url ?? '/', prefix);
        this.proxy.ws(req, socket, head, { target: target.origin, headers: forwardHeaders(req, session.token) });
        return true;
    }

    close(): void {
        this.proxy.close();
    }
}

/** What the proxy needs of the simulation sessions. */
export interface SimProxySessions {
    /** The running session's endpoints and token. */
    target(): SimTarget | undefined;
    /** A WebSocket client opened; the returned function is called when it closes. */
    clientOpened(): () => void;
    /** A proxied HTTP request arrived. */
    signOfLife(): void;
}

/**
 * Drops the browser's Origin and Cookie from the request (http-proxy copies the request's
 * headers) and returns the headers to add: the session's bearer token.
 */
function forwardHeaders(req: IncomingMessage, token: string): Record<string, string> {
    delete req.headers.origin;
    delete req.headers.cookie;
    return { authorization: `Bearer ${token}` };
}

/** `/sim/viser/a?b` → `/a?b`, `/sim/viser` → `/`. */
function stripPrefix(url: string, prefix: string): string {
    const rest = url.slice(prefix.length);
    return rest.startsWith('/') ? rest : `/${rest}`;
}

export function rejectUpgrade(socket: Duplex, status: number, message: string): void {
    const body = JSON.stringify({ error: message });
    const reason = STATUS_CODES[status] ?? 'Error';
    socket.end(
        `HTTP/1.1 ${status} ${reason}\r\nContent-Type: application/json; charset=utf-8\r\nContent-Length: ${Buffer.byteLength(body)}\r\nConnection: close\r\n\r\n${body}`,
    );
}

function isServerResponse(value: unknown): value is ServerResponse {
    return typeof value === 'object' && value !== null && 'writeHead' in value && 'headersSent' in value;
}
