import { request } from 'node:http';
import { cpSync, mkdirSync, mkdtempSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import path from 'node:path';
import WebSocket from 'ws';
import { startIdeServer, type IdeServer, type IdeServerOptions } from '../src/index.js';
import { repo, TEST_TOKEN } from './basics.js';

export { repo, TEST_TOKEN, until } from './basics.js';
export const BEARER = { Authorization: `Bearer ${TEST_TOKEN}` };

/** fetch with the test token as `Authorization: Bearer` (what scripts do). */
export function authFetch(input: string | URL, init: RequestInit = {}): Promise<Response> {
    const headers = new Headers(init.headers);
    if (!headers.has('authorization')) headers.set('authorization', BEARER.Authorization);
    return fetch(input, { ...init, headers });
}

/** A WebSocket to an http(s) URL of the backend, with the test token unless `headers` says otherwise. */
export function authWebSocket(url: string, protocols?: string[], headers: Record<string, string> = BEARER): WebSocket {
    return new WebSocket(url.replace(/^http/, 'ws'), protocols, { headers });
}

export interface TestSite {
    /** The temporary folder: the workspace is `ws/` inside, generated output `.maa-ide-out/`. */
    dir: string;
    workspace: string;
    server: IdeServer;
    url(pathAndQuery: string): string;
    dispose(): Promise<void>;
}

/** A workspace in a fresh temporary folder (a copy of examples/ unless `empty`) and a backend on a free port. */
export async function startSite(options: { empty?: boolean } & Partial<IdeServerOptions> = {}): Promise<TestSite> {
    const dir = mkdtempSync(path.join(tmpdir(), 'maa-ide-test-'));
    const workspace = path.join(dir, 'ws');
    if (options.empty) mkdirSync(workspace);
    else cpSync(path.join(repo, 'examples'), workspace, { recursive: true });
    const server = await startIdeServer({ appDir: path.join(dir, 'no-app'), token: TEST_TOKEN, ...options, workspace, port: 0 });
    const site: TestSite = {
        dir,
        workspace,
        server,
        url: (p) => new URL(p, site.server.url).toString(),
        async dispose() {
            await site.server.close();
            rmSync(dir, { recursive: true, force: true });
        },
    };
    return site;
}

/** The query string `path=...` with the value encoded as given (so `%2e%2e` stays literal). */
export function q(params: Record<string, string>): string {
    return Object.entries(params)
        .map(([k, v]) => `${k}=${encodeURIComponent(v)}`)
        .join('&');
}

export async function json<T = Record<string, unknown>>(response: Response): Promise<T> {
    return (await response.json()) as T;
}

/**
 * A request with the path and headers sent byte for byte (fetch would normalize `%2e%2e`
 * segments away, and it does not let a caller set Host or Origin). The test token goes along
 * unless `headers` holds an Authorization of its own (or `null` for none).
 */
export function rawRequest(
    base: string,
    rawPath: string,
    { method = 'GET', headers = {}, body }: { method?: string; headers?: Record<string, string | null>; body?: string } = {},
): Promise<{ status: number; body: string; headers: Record<string, string | string[] | undefined> }> {
    const sent: Record<string, string> = {};
    for (const [k, v] of Object.entries({ Authorization: BEARER.Authorization, ...headers })) if (v !== null) sent[k] = v;
    return new Promise((resolve, reject) => {
        const req = request(base, { path: rawPath, method, headers: sent }, (res) => {
            let text = '';
            res.setEncoding('utf8');
            res.on('data', (c: string) => (text += c));
            res.on('end', () => resolve({ status: res.statusCode ?? 0, body: text, headers: res.headers }));
        });
        req.on('error', reject);
        req.end(body);
    });
}

/** A GET with the path sent byte for byte (fetch would normalize `%2e%2e` segments away). */
export function rawGet(base: string, rawPath: string): Promise<{ status: number; body: string }> {
    return rawRequest(base, rawPath);
}
