/**
 * The simulate webview's way to the backend (docs/vscode.md "Simulate"): a loopback relay in the
 * extension host. The webview's page (origin `vscode-webview://…`) cannot send maa-ide's token
 * with the viser iframe's requests, and maa-ide rightly refuses a foreign Origin; so the relay
 * holds the token, and the webview gets a capability URL instead:
 * `http://127.0.0.1:<relay port>/<capability>/…` → `http://127.0.0.1:<backend port>/…` with
 * `Authorization: Bearer <token>`, the backend's Host, and no Origin, Cookie or Referer (maa-ide
 * then checks everything as for any client). The relay itself answers only requests that
 *   - name it by a loopback Host with its port (no DNS rebinding),
 *   - carry the capability (256 random bits) as the first path segment (the viser page's relative
 *     URLs keep it, so its assets and WebSocket pass too),
 *   - come without Origin, from its own origin (the viser page), or from a VS Code webview
 *     (`vscode-webview:`; only VS Code's webviews have that scheme: web pages cannot claim it).
 * Redirects of the backend keep the capability; its Set-Cookie headers are dropped; CORS is
 * answered for the webview's origin only (no credentials).
 */
import { randomBytes } from 'node:crypto';
import { createServer, type IncomingHttpHeaders, type IncomingMessage, request, type Server, type ServerResponse } from 'node:http';
import { connect, type Socket } from 'node:net';
import type { Duplex } from 'node:stream';
import { type RelayAdmission, relayAdmission, sameCapability } from './relay-rules.js';

export interface RelayTarget {
    /** The backend's port on 127.0.0.1. */
    port: number;
    /** The backend's token. */
    token: string;
}

/** Request headers that never leave the relay (the backend gets its own Host and the token). */
const DROPPED = new Set([
    'host',
    'origin',
    'cookie',
    'referer',
    'authorization',
    'connection',
    'proxy-authorization',
    'forwarded',
    'x-forwarded-for',
    // The viser frame is of another site than the webview already (a process of its own); maa-ide
    // would move a frame's viser page to its other loopback name (viser-view.ts), past the relay.
    'sec-fetch-dest',
]);

export class SimRelay {
    private server: Server | undefined;
    private listening: Promise<number> | undefined;
    private readonly capability = randomBytes(32).toString('base64url');
    private readonly sockets = new Set<Duplex>();

    constructor(private target: RelayTarget) {}

    /** Points the relay at another backend (a restarted one). */
    retarget(target: RelayTarget): void {
        this.target = target;
    }

    /** The base URL the webview uses (`http://127.0.0.1:<port>/<capability>`). */
    async base(): Promise<string> {
        const port = await this.listen();
        return `http://127.0.0.1:${port}/${this.capability}`;
    }

    async close(): Promise<void> {
        const server = this.server;
        this.server = undefined;
        this.listening = undefined;
        for (const s of this.sockets) s.destroy();
        this.sockets.clear();
        if (server) await new Promise<void>((resolve) => server.close(() => resolve()));
    }

    private listen(): Promise<number> {
        this.listening ??= new Promise<number>((resolve, reject) => {
            const server = createServer((req, res) => this.onRequest(req, res));
            server.on('upgrade', (req: IncomingMessage, socket: Duplex, head: Buffer) => this.onUpgrade(req, socket, head));
            server.on('connection', (s) => {
                this.sockets.add(s);
                s.on('close', () => this.sockets.delete(s));
            });
            server.once('error', reject);
            server.listen(0, '127.0.0.1', () => {
                const address = server.address();
                resolve(typeof address === 'object' && address ? address.port : 0);
            });
            this.server = server;
        });
        return this.listening;
    }

    private admit(req: IncomingMessage): RelayAdmission {
        const address = this.server?.address();
        const port = typeof address === 'object' && address ? address.port : -1;
        return relayAdmission({ host: req.headers.host, origin: req.headers.origin, url: req.url ?? '/' }, port, (given) =>
            sameCapability(given, this.capability),
        );
    }

    private onRequest(req: IncomingMessage, res: ServerResponse): void {
        const admission = this.admit(req);
        if (!admission.ok) {
            res.writeHead(admission.status, { 'content-type': 'text/plain; charset=utf-8' });
            res.end(`${admission.message}\n`);
            return;
        }
        const cors: Record<string, string> = admission.cors ? { 'access-control-allow-origin': admission.cors, vary: 'Origin' } : {};
        if (req.method === 'OPTIONS' && admission.cors) {
            res.writeHead(204, {
                ...cors,
                'access-control-allow-methods': 'GET, POST',
                'access-control-allow-headers': 'content-type',
                'access-control-max-age': '600',
            });
            res.end();
            return;
        }
        const out = request(
            {
                host: '127.0.0.1',
                port: this.target.port,
                method: req.method,
                path: admission.path,
                headers: this.forwardHeaders(req.headers),
            },
            (answer) => {
                const headers: Record<string, string | string[]> = { ...cors };
                for (const [name, value] of Object.entries(answer.headers)) {
                    if (value === undefined || name === 'set-cookie') continue;
                    headers[name] = name === 'location' && typeof value === 'string' ? admission.relocate(value) : value;
                }
                res.writeHead(answer.statusCode ?? 502, headers);
                answer.pipe(res);
            },
        );
        out.on('error', (e) => {
            if (res.headersSent) res.destroy();
            else {
                res.writeHead(502, { 'content-type': 'text/plain; charset=utf-8', ...cors });
                res.end(`the IDE backend did not answer: ${e.message}\n`);
            }
        });
        req.pipe(out);
    }

    private onUpgrade(req: IncomingMessage, socket: Duplex, head: Buffer): void {
        const admission = this.admit(req);
        if (!admission.ok) {
            socket.end(`HTTP/1.1 ${admission.status} Refused\r\nConnection: close\r\nContent-Length: 0\r\n\r\n`);
            return;
        }
        const upstream: Socket = connect(this.target.port, '127.0.0.1', () => {
            const headers = { ...this.forwardHeaders(req.headers), connection: 'Upgrade', upgrade: req.headers.upgrade ?? 'websocket' };
            const lines = [`${req.method ?? 'GET'} ${admission.path} HTTP/1.1`];
            for (const [name, value] of Object.entries(headers)) {
                for (const v of Array.isArray(value) ? value : [value]) lines.push(`${name}: ${v}`);
            }
            upstream.write(`${lines.join('\r\n')}\r\n\r\n`);
            if (head.length > 0) upstream.write(head);
            upstream.pipe(socket);
            socket.pipe(upstream);
        });
        this.sockets.add(upstream);
        const end = (): void => {
            upstream.destroy();
            socket.destroy();
            this.sockets.delete(upstream);
        };
        upstream.on('error', end);
        upstream.on('close', end);
        socket.on('error', end);
        socket.on('close', end);
    }

    /** The request's headers as the backend gets them. */
    private forwardHeaders(incoming: IncomingHttpHeaders): Record<string, string | string[]> {
        const headers: Record<string, string | string[]> = {};
        for (const [name, value] of Object.entries(incoming)) {
            if (value !== undefined && !DROPPED.has(name)) headers[name] = value;
        }
        headers['host'] = `127.0.0.1:${this.target.port}`;
        headers['authorization'] = `Bearer ${this.target.token}`;
        return headers;
    }
}
