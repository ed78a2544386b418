/**
 * Who the simulate relay (relay.ts) lets through, and where to: pure, so the rules are tested
 * with every attack on their own.
 */
import { createHash, timingSafeEqual } from 'node:crypto';

export type RelayAdmission =
    | {
          ok: true;
          /** The backend path and query (the capability removed). */
          path: string;
          /** The origin to answer CORS for (a webview), undefined for none. */
          cors: string | undefined;
          /** A backend `Location` as the client must see it (the capability kept). */
          relocate: (location: string) => string;
      }
    | { ok: false; status: 403 | 404; message: string };

/** Host names the relay answers to (it listens on 127.0.0.1). */
const LOOPBACK = new Set(['127.0.0.1', 'localhost']);

/** Constant-time comparison of a capability (hashing first evens out the lengths). */
export function sameCapability(given: string, expected: string): boolean {
    const a = createHash('sha256').update(given).digest();
    const b = createHash('sha256').update(expected).digest();
    return timingSafeEqual(a, b);
}

/** Whether `origin` may use the relay: its own origin (the viser page) or a VS Code webview. */
export function originAllowed(origin: string, relayPort: number): boolean {
    let url: URL;
    try {
        url = new URL(origin);
    } catch {
        return false;
    }
    if (url.protocol === 'vscode-webview:') return url.hostname !== '' && url.pathname === '' && origin === `vscode-webview://${url.host}`;
    return url.protocol === 'http:' && LOOPBACK.has(url.hostname) && url.port === String(relayPort) && origin === url.origin;
}

/**
 * Checks a request (or WebSocket upgrade) to the relay listening on `relayPort`: Host, Origin,
 * then the capability as the first path segment (`isCapability` compares it).
 */
export function relayAdmission(
    req: { host: string | undefined; origin: string | undefined; url: string },
    relayPort: number,
    isCapability: (segment: string) => boolean,
): RelayAdmission {
    const host = req.host ?? '';
    const colon = host.lastIndexOf(':');
    if (colon < 0 || !LOOPBACK.has(host.slice(0, colon)) || host.slice(colon + 1) !== String(relayPort)) {
        return { ok: false, status: 403, message: `the relay does not serve the host ${JSON.stringify(host)}` };
    }
    if (req.origin !== undefined && !originAllowed(req.origin, relayPort)) {
        return { ok: false, status: 403, message: `requests from the origin ${JSON.stringify(req.origin)} are not relayed` };
    }
    const m = /^\/([^/?#]*)(.*)$/s.exec(req.url);
    const segment = m?.[1] ?? '';
    if (!m || !isCapability(segment)) return { ok: false, status: 404, message: 'not found' };
    const rest = m[2] ?? '';
    const path = rest === '' ? '/' : rest.startsWith('/') ? rest : `/${rest}`;
    const cors = req.origin?.startsWith('vscode-webview:') ? req.origin : undefined;
    return {
        ok: true,
        path,
        cors,
        relocate: (location) => (location.startsWith('/') && !location.startsWith('//') ? `/${segment}${location}` : location),
    };
}
