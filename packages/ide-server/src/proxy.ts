import type { IncomingMessage, ServerResponse } from 'node:http';
import type { Duplex } from 'node:stream';
import httpProxy from 'http-proxy';
import { sendJson } from './http-util.js';
import type { SimEndpoints } from './sim-session.js';

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
 */
export class SimProxy {
  private readonly proxy = httpProxy.createProxyServer({ ws: true, xfwd: false });

  constructor(private readonly endpoints: () => SimEndpoints | undefined) {
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
    const viser = this.endpoints()?.viser;
    if (!viser) {
      sendJson(res, 502, { error: 'no simulation session is running (start one with POST /api/sim/start)' });
      return true;
    }
    req.url = stripPrefix(req.url ?? '/', VISER_PATH);
    this.proxy.web(req, res, { target: viser.origin });
    return true;
  }

  /** Handles WebSocket upgrades of `/sim/rosbridge` and `/sim/viser`; false when not ours. */
  handleUpgrade(req: IncomingMessage, socket: Duplex, head: Buffer, pathname: string): boolean {
    let target: URL | undefined;
    let prefix: string;
    if (pathname === ROSBRIDGE_PATH || pathname.startsWith(`${ROSBRIDGE_PATH}/`)) {
      prefix = ROSBRIDGE_PATH;
      target = this.endpoints()?.rosbridge;
    } else if (pathname === VISER_PATH || pathname.startsWith(`${VISER_PATH}/`)) {
      prefix = VISER_PATH;
      target = this.endpoints()?.viser;
    } else {
      return false;
    }
    if (!target) {
      rejectUpgrade(socket, 502, 'no simulation session is running');
      return true;
    }
    req.url = stripPrefix(req.url ?? '/', prefix);
    this.proxy.ws(req, socket, head, { target: target.origin });
    return true;
  }

  close(): void {
    this.proxy.close();
  }
}

/** `/sim/viser/a?b` → `/a?b`, `/sim/viser` → `/`. */
function stripPrefix(url: string, prefix: string): string {
  const rest = url.slice(prefix.length);
  return rest.startsWith('/') ? rest : `/${rest}`;
}

export function rejectUpgrade(socket: Duplex, status: number, message: string): void {
  const body = JSON.stringify({ error: message });
  const reason = status === 502 ? 'Bad Gateway' : status === 404 ? 'Not Found' : 'Bad Request';
  socket.end(
    `HTTP/1.1 ${status} ${reason}\r\nContent-Type: application/json; charset=utf-8\r\nContent-Length: ${Buffer.byteLength(body)}\r\nConnection: close\r\n\r\n${body}`,
  );
}

function isServerResponse(value: unknown): value is ServerResponse {
  return typeof value === 'object' && value !== null && 'writeHead' in value && 'headersSent' in value;
}
