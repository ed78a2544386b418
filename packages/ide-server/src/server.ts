import { realpathSync, statSync } from 'node:fs';
import { createServer, type IncomingMessage, type ServerResponse } from 'node:http';
import type { AddressInfo } from 'node:net';
import path from 'node:path';
import type { Duplex } from 'node:stream';
import { fileURLToPath } from 'node:url';
import { AccessGuard, generateToken, loginPage, tokenProblem, type AccessRefusal } from './access.js';
import { createApiRouter } from './api.js';
import { GenerationService } from './generation.js';
import { sendError, sendJson, sendText } from './http-util.js';
import { rejectUpgrade, SimProxy } from './proxy.js';
import { PathRedactor } from './redact.js';
import { Ros2Environment } from './ros2-environment.js';
import { SimSessions } from './sim-session.js';
import { StaticApp } from './static.js';
import { Workspace } from './workspace.js';

/** This package's folder (dist/ or src/ lie one level below it). */
export const packageDir = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..');
const repoDir = path.resolve(packageDir, '..', '..');

export const defaults = {
    port: 3000,
    host: '127.0.0.1',
    appDir: path.join(repoDir, 'packages', 'ide-web', 'dist'),
    maaSim: path.join(repoDir, 'sim-server', '.venv', 'bin', 'maa-sim'),
    ros2Venv: path.join(repoDir, 'packages', 'generators-python', '.venv-ros2'),
    maxFileBytes: 5 * 1024 * 1024,
    sessionIdleSeconds: 60,
};

export interface IdeServerOptions {
    /** The folder the IDE edits. */
    workspace: string;
    port?: number;
    host?: string;
    /** The built web app (default: packages/ide-web/dist). */
    appDir?: string;
    /** The `maa-sim` executable (default: sim-server/.venv/bin/maa-sim). */
    maaSim?: string;
    /**
     * The Python venv ROS 2 sessions run in: its maa-sim, the generated interface packages installed
     * into it (default: packages/generators-python/.venv-ros2, created by its setup script when missing).
     */
    ros2Venv?: string;
    /** Generated output (default: `<workspace>/../.maa-ide-out`, docs/ide.md). */
    outDir?: string;
    /** Largest accepted PUT body (default 5 MB). */
    maxFileBytes?: number;
    /** How long a simulation may take to become ready (default 90 s). */
    simReadyTimeoutMs?: number;
    /** The secret every request must carry (default: 32 random bytes, base64url; docs/ide.md "Access"). */
    token?: string;
    /** A simulation session ends when it had no client for this long (default 60 s). */
    sessionIdleSeconds?: number;
    /** How long stopping a simulation waits after SIGTERM before SIGKILL (default 8 s; tests shorten it). */
    simStopGraceMs?: number;
}

export interface IdeServer {
    /** `http://host:port/` with the real port (requests need the token, see loginUrl). */
    url: string;
    /** `http://host:port/?token=...`: the URL to open (it stores the token in a cookie). */
    loginUrl: string;
    /** The per-start secret (cookie `maa-ide-token-<port>` or `Authorization: Bearer <token>`). */
    token: string;
    port: number;
    workspace: string;
    /** Stops the simulation session, closes every connection and the listener. */
    close(): Promise<void>;
}

/** Starts the IDE backend (docs/ide.md): the app, the workspace API, generation, sim sessions and their proxy. */
export async function startIdeServer(options: IdeServerOptions): Promise<IdeServer> {
    const workspaceDir = path.resolve(options.workspace);
    let isDir = false;
    try {
        isDir = statSync(workspaceDir).isDirectory();
    } catch {
        isDir = false;
    }
    if (!isDir) throw new Error(`the workspace folder ${workspaceDir} does not exist`);
    const host = options.host ?? defaults.host;
    const token = options.token ?? generateToken();
    const problem = tokenProblem(token);
    if (problem) throw new Error(problem);
    const idleSeconds = options.sessionIdleSeconds ?? defaults.sessionIdleSeconds;
    if (!(idleSeconds > 0)) throw new Error(`the session idle time must be a positive number of seconds, not ${idleSeconds}`);
    const workspace = new Workspace(workspaceDir);
    const outDir = path.resolve(options.outDir ?? path.join(workspaceDir, '..', '.maa-ide-out'));
    const maaSim = path.resolve(options.maaSim ?? defaults.maaSim);
    const redact = new PathRedactor([
        [workspaceDir, ''],
        [realpathSync(workspaceDir), ''],
        [outDir, '<generated>'],
        [path.resolve(options.ros2Venv ?? defaults.ros2Venv), '<ros2-venv>'],
        [maaSim, 'maa-sim'],
        [repoDir, ''],
    ]);
    const generation = new GenerationService(workspace, outDir, [packageDir]);
    const sims = new SimSessions(
        maaSim,
        { readyTimeoutMs: options.simReadyTimeoutMs, idleMs: idleSeconds * 1000, stopGraceMs: options.simStopGraceMs },
        ros2Environment(options.ros2Venv),
    );
    const api = createApiRouter({ workspace, generation, sims, maxFileBytes: options.maxFileBytes ?? defaults.maxFileBytes, redact });
    const proxy = new SimProxy(sims);
    const appDir = path.resolve(options.appDir ?? defaults.appDir);
    const app = new StaticApp(appDir, redact.text(appDir));

    // Saves killed before their rename left temp files; nothing else writes them, so once is enough.
    const orphans = await workspace.removeOrphanTemps();
    if (orphans.length > 0) console.error(`maa-ide: removed ${orphans.length} temp file(s) of interrupted saves: ${orphans.join(', ')}`);

    // Known once the server listens (the port may be 0 until then); no request arrives before.
    let guard!: AccessGuard;

    const handle = async (req: IncomingMessage, res: ServerResponse): Promise<void> => {
        const admission = guard.admit(req);
        if (!admission.ok) {
            refuse(req, res, admission.refusal, admission.unauthenticated);
            return;
        }
        const { url } = admission;
        if (admission.via === 'query') {
            res.setHeader('Set-Cookie', guard.setCookie());
            if (isPage(req, url.pathname)) {
                // The token leaves the address bar (and history); the cookie carries it from now on.
                res.writeHead(302, { Location: withoutToken(url), 'Content-Length': 0, 'Cache-Control': 'no-store' });
                res.end();
                return;
            }
        }
        await route(req, res, url);
    };

    /** Where an admitted request goes: the REST API, the simulator's proxy, or the app's files. */
    const route = async (req: IncomingMessage, res: ServerResponse, url: URL): Promise<void> => {
        const pathname = url.pathname;
        if (pathname.startsWith('/api/sim/')) sims.signOfLife();
        if (isUnder(pathname, '/api')) await api.dispatch(req, res, pathname, url.searchParams);
        else if (isUnder(pathname, '/sim')) {
            if (!proxy.handleRequest(req, res, pathname)) sendJson(res, 404, { error: `unknown route: ${req.method} ${pathname}` });
        } else await app.handle(req, res, pathname);
    };

    const server = createServer((req, res) => {
        handle(req, res).catch((e: unknown) => sendError(res, e, redact, `${req.method} ${req.url?.split('?')[0]}`));
    });
    // Upgraded sockets leave the server's bookkeeping, so close() ends them itself.
    const upgraded = new Set<Duplex>();
    server.on('upgrade', (req: IncomingMessage, socket: Duplex, head: Buffer) => {
        upgraded.add(socket);
        socket.on('close', () => upgraded.delete(socket));
        socket.on('error', () => socket.destroy());
        const admission = guard.admit(req);
        if (!admission.ok) {
            rejectUpgrade(socket, admission.refusal.status, admission.refusal.message);
            return;
        }
        const { url } = admission;
        // maa-ide's token is not the simulator's business.
        req.url = withoutToken(url);
        if (!proxy.handleUpgrade(req, socket, head, url.pathname)) rejectUpgrade(socket, 404, `no WebSocket endpoint at ${url.pathname}`);
    });
    server.on('clientError', (_err, socket) => {
        if (socket.writable) socket.end('HTTP/1.1 400 Bad Request\r\nConnection: close\r\n\r\n');
        else socket.destroy();
    });

    await new Promise<void>((resolve, reject) => {
        server.once('error', reject);
        server.listen(options.port ?? defaults.port, host, () => {
            server.off('error', reject);
            guard = new AccessGuard(host, (server.address() as AddressInfo).port, token);
            resolve();
        });
    });
    const port = (server.address() as AddressInfo).port;
    // A wildcard address is no name a browser may use (the Host check refuses it): print loopback.
    const shownHost = host === '0.0.0.0' || host === '::' ? '127.0.0.1' : host.includes(':') ? `[${host}]` : host;
    let closing: Promise<void> | undefined;
    return {
        url: `http://${shownHost}:${port}/`,
        loginUrl: `http://${shownHost}:${port}/?token=${token}`,
        token,
        port,
        workspace: workspaceDir,
        close() {
            closing ??= (async () => {
                await sims.stop().catch(() => undefined);
                sims.dispose();
                const closed = new Promise<void>((resolve) => server.close(() => resolve()));
                server.closeAllConnections();
                for (const s of upgraded) s.destroy();
                proxy.close();
                await closed;
            })();
            return closing;
        },
    };
}

/** The path and query of a URL without its `token` parameter. */
/** Whether `pathname` is `prefix` or below it. */
function isUnder(pathname: string, prefix: string): boolean {
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

function withoutToken(url: URL): string {
    const query = new URLSearchParams(url.searchParams);
    query.delete('token');
    const rest = query.toString();
    return `${url.pathname}${rest ? `?${rest}` : ''}`;
}

/** The default venv is created by its setup script when missing; another one must exist. */
function ros2Environment(venv: string | undefined): Ros2Environment {
    const scripts = path.join(repoDir, 'packages', 'generators-python', 'scripts');
    const dir = path.resolve(venv ?? defaults.ros2Venv);
    return new Ros2Environment({
        venv: dir,
        setupScript: dir === path.resolve(defaults.ros2Venv) ? path.join(scripts, 'setup_ros2_venv.sh') : undefined,
        installScript: path.join(scripts, 'install_ros2_interfaces.sh'),
    });
}
