// A tiny stand-in for the IDE backend's workspace API (docs/ide.md): `GET /api/files` and
// `GET /api/file?path=P` over a folder, for the tests of the browser entry.
import { createServer, type Server } from 'node:http';
import { readdirSync, readFileSync, statSync } from 'node:fs';
import { join, relative, resolve, sep } from 'node:path';

export interface WorkspaceServer {
    readonly url: string;
    /** The request paths served so far. */
    readonly requests: string[];
    close(): Promise<void>;
}

export async function serveWorkspace(dir: string): Promise<WorkspaceServer> {
    const requests: string[] = [];
    const server: Server = createServer((req, res) => {
        const url = new URL(req.url ?? '/', 'http://localhost');
        requests.push(`${url.pathname}${url.search}`);
        const json = (status: number, body: unknown): void => {
            res.writeHead(status, { 'content-type': 'application/json' });
            res.end(JSON.stringify(body));
        };
        if (url.pathname === '/api/files') {
            json(200, { root: 'workspace', entries: list(dir) });
        } else if (url.pathname === '/api/file') {
            const path = url.searchParams.get('path') ?? '';
            const file = resolve(dir, path);
            if (!path || path.startsWith('/') || path.split('/').includes('..')) return json(400, { error: `bad path '${path}'` });
            try {
                const text = readFileSync(file, 'utf8');
                res.writeHead(200, { 'content-type': 'text/plain; charset=utf-8' });
                res.end(text);
            } catch {
                json(404, { error: `no file '${path}'` });
            }
        } else {
            json(404, { error: `no route ${url.pathname}` });
        }
    });
    await new Promise<void>((r) => server.listen(0, '127.0.0.1', r));
    const address = server.address();
    if (!address || typeof address === 'string') throw new Error('no address');
    return {
        url: `http://127.0.0.1:${address.port}`,
        requests,
        close: () => new Promise<void>((r) => server.close(() => r())),
    };
}

function list(dir: string): Array<{ path: string; type: 'file' | 'directory'; size?: number }> {
    const out: Array<{ path: string; type: 'file' | 'directory'; size?: number }> = [];
    const walk = (d: string): void => {
        for (const name of readdirSync(d)) {
            if (name.startsWith('.')) continue;
            const p = join(d, name);
            const rel = relative(dir, p).split(sep).join('/');
            const s = statSync(p);
            if (s.isDirectory()) {
                out.push({ path: rel, type: 'directory' });
                walk(p);
            } else {
                out.push({ path: rel, type: 'file', size: s.size });
            }
        }
    };
    walk(dir);
    return out.sort((a, b) => (a.path < b.path ? -1 : a.path > b.path ? 1 : 0));
}
