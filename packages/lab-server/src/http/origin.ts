// Host and Origin (docs/lab.md "Security"): a request must name the lab by a name it serves (a
// loopback name or the --host it listens on, with its port, or the host of --public-url) so a
// DNS-rebound name is refused, and when the browser says where a request comes from, that
// origin must be the lab's own (no cross-site requests, no cross-site WebSockets).
import type { IncomingMessage } from 'node:http';

const LOOPBACK_NAMES = ['127.0.0.1', 'localhost', '[::1]'];

function parseHost(value: string): URL | undefined {
    if (!/^[A-Za-z0-9.:[\]-]+$/.test(value)) return undefined;
    try {
        return new URL(`http://${value}`);
    } catch {
        return undefined;
    }
}

export class OriginCheck {
    /** Accepted Host headers (`host:port` as the URL parser normalizes it) → the origin they belong to. */
    private readonly hosts = new Map<string, string>();

    /**
     * @param listenHost the address the server listens on
     * @param port the port it listens on
     * @param publicUrl the address users open (behind a proxy: the proxy's https address)
     */
    constructor(listenHost: string, port: number, publicUrl?: string) {
        const own = parseHost(listenHost.includes(':') && !listenHost.startsWith('[') ? `[${listenHost}]` : listenHost)?.hostname;
        const wildcard = own === '0.0.0.0' || own === '[::]';
        for (const name of [...LOOPBACK_NAMES, ...(own && !wildcard ? [own] : [])]) {
            const url = new URL(`http://${name}:${port}`);
            this.hosts.set(url.host, url.origin);
        }
        if (publicUrl) {
            const url = new URL(publicUrl);
            this.hosts.set(url.host, url.origin);
        }
    }

    /** Undefined when the request's Host and Origin are acceptable, else why not. */
    refusal(req: IncomingMessage): string | undefined {
        const header = req.headers.host;
        if (!header) return 'the request has no Host header';
        const host = parseHost(header);
        const origin = host && this.hosts.get(host.host);
        if (origin === undefined)
            return `maa-lab does not serve the host ${JSON.stringify(header)} (it serves ${[...this.hosts.keys()].join(', ')})`;
        const given = req.headers.origin;
        if (given === undefined) return undefined;
        if (given !== origin) return `requests from the origin ${JSON.stringify(given)} are not accepted (only from ${origin})`;
        return undefined;
    }
}
