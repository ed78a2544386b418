import { existsSync, realpathSync, statSync } from 'node:fs';
import { createServer, type IncomingMessage, type Server, type ServerResponse } from 'node:http';
import { createRequire } from 'node:module';
import type { AddressInfo } from 'node:net';
import path from 'node:path';
import type { Duplex } from 'node:stream';
import { fileURLToPath } from 'node:url';
import { generateToken, tokenProblem } from './access.js';
import { createApiRouter } from './api.js';
import { GenerationService } from './generation.js';
import { Gate, isUnder } from './gate.js';
import { sendError, sendJson } from './http-util.js';
import { rejectUpgrade, SimProxy, VISER_PATH } from './proxy.js';
import { PathRedactor } from './redact.js';
import { Ros2Environment } from './ros2-environment.js';
import { Recordings } from './recordings.js';
import type { Router } from './router.js';
import { SimSessions } from './sim-session.js';
import { StaticApp } from './static.js';
import { ViserView } from './viser-view.js';
import { Workspace } from './workspace.js';

/** This package's folder (dist/ or src/ lie one level below it). */
export const packageDir = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..');
const repoDir = path.resolve(packageDir, '..', '..');

/** The folder of an installed package (the workspace's in a clone), or undefined when it is not installed. */
function installedPackageDir(name: string): string | undefined {
    try {
        return path.dirname(createRequire(import.meta.url).resolve(`${name}/package.json`));
    } catch {
        return undefined;
    }
}

/** The built web app: @maa/ide-web's dist/. */
function defaultAppDir(): string {
    return path.join(installedPackageDir('@maa/ide-web') ?? path.join(repoDir, 'packages', 'ide-web'), 'dist');
}

/**
 * maa-sim: in a clone the development venv's (sim-server/scripts/setup_env.sh creates it); installed
 * from the registry @maa/sim-server's launcher, which installs maa-sim into a cached venv on first use.
 */
function defaultMaaSim(): string {
    const simServer = installedPackageDir('@maa/sim-server') ?? path.join(repoDir, 'sim-server');
    const development = path.join(simServer, '.venv', 'bin', 'maa-sim');
    const inClone = existsSync(path.join(simServer, 'scripts', 'setup_env.sh'));
    return inClone || existsSync(development) ? development : path.join(simServer, 'bin', 'maa-sim.mjs');
}

export const defaults = {
    port: 3000,
    host: '127.0.0.1',
    appDir: defaultAppDir(),
    maaSim: defaultMaaSim(),
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
    /** The `maa-sim` executable (default: sim-server/.venv/bin/maa-sim in a clone, @maa/sim-server's launcher when installed). */
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
    const settings = checkedSettings(options);
    const services = createServices(options, settings);
    // Saves killed before their rename left temp files; nothing else writes them, so once is enough.
    const orphans = await services.workspace.removeOrphanTemps();
    if (orphans.length > 0) console.error(`maa-ide: removed ${orphans.length} temp file(s) of interrupted saves: ${orphans.join(', ')}`);

    const gate = new Gate();
    const server = createServer(requestHandler(gate, services));
    const upgraded = handleUpgrades(server, gate, services);
    server.on('clientError', (_err, socket) => {
        if (socket.writable) socket.end('HTTP/1.1 400 Bad Request\r\nConnection: close\r\n\r\n');
        else socket.destroy();
    });
    const port = await listen(server, options.port ?? defaults.port, settings.host, (port) =>
        gate.open(settings.host, port, settings.token, (pathname) => services.viserView.admits(pathname)),
    );
    const shownHost = displayHost(settings.host);
    return {
        url: `http://${shownHost}:${port}/`,
        loginUrl: `http://${shownHost}:${port}/?token=${settings.token}`,
        token: settings.token,
        port,
        workspace: settings.workspaceDir,
        close: shutdown(server, services, upgraded),
    };
}

/** The options every start needs, checked before anything is built. */
interface Settings {
    workspaceDir: string;
    host: string;
    token: string;
    idleSeconds: number;
}

/** The options' workspace, host, token and idle time, each checked (an Error says what is wrong). */
function checkedSettings(options: IdeServerOptions): Settings {
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
    return { workspaceDir, host, token, idleSeconds };
}

/** What answers the requests behind the gate. */
interface Services {
    workspace: Workspace;
    redact: PathRedactor;
    sims: SimSessions;
    api: Router;
    proxy: SimProxy;
    viserView: ViserView;
    app: StaticApp;
}

function createServices(options: IdeServerOptions, { workspaceDir, idleSeconds }: Settings): Services {
    const workspace = new Workspace(workspaceDir);
    const outDir = path.resolve(options.outDir ?? path.join(workspaceDir, '..', '.maa-ide-out'));
    const maaSim = path.resolve(options.maaSim ?? defaults.maaSim);
    // What error messages and answers must not reveal of this machine's folders.
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
    const api = createApiRouter({
        workspace,
        generation,
        sims,
        maxFileBytes: options.maxFileBytes ?? defaults.maxFileBytes,
        redact,
        recordings: new Recordings(workspace),
    });
    const proxy = new SimProxy(sims);
    const appDir = path.resolve(options.appDir ?? defaults.appDir);
    const app = new StaticApp(appDir, redact.text(appDir));
    return { workspace, redact, sims, api, proxy, viserView: new ViserView(), app };
}

/** Every request goes through the gate, then to its route; a failure is answered as a (redacted) error. */
function requestHandler(gate: Gate, services: Services): (req: IncomingMessage, res: ServerResponse) => void {
    const handle = async (req: IncomingMessage, res: ServerResponse): Promise<void> => {
        const url = gate.admitRequest(req, res);
        if (url) await route(services, req, res, url);
    };
    return (req, res) => {
        handle(req, res).catch((e: unknown) => sendError(res, e, services.redact, `${req.method} ${req.url?.split('?')[0]}`));
    };
}

/** Where an admitted request goes: the REST API, the simulator's proxy, or the app's files. */
async function route({ sims, api, proxy, viserView, app }: Services, req: IncomingMessage, res: ServerResponse, url: URL): Promise<void> {
    const pathname = url.pathname;
    if (pathname.startsWith('/api/sim/')) sims.signOfLife();
    if (isUnder(pathname, '/api')) await api.dispatch(req, res, pathname, url.searchParams);
    else if (isUnder(pathname, '/sim')) {
        // The viser page goes to a frame of another site, a process of its own (viser-view.ts).
        const away = viserView.redirect(req, url);
        const inner = away ? undefined : viserView.rewrite(req, url);
        if (away || inner === VISER_PATH) {
            res.writeHead(302, { Location: away ?? `${pathname}/${url.search}`, 'Content-Length': 0, 'Cache-Control': 'no-store' });
            res.end();
        } else if (!proxy.handleRequest(req, res, inner ?? pathname))
            sendJson(res, 404, { error: `unknown route: ${req.method} ${pathname}` });
    } else await app.handle(req, res, pathname);
}

/**
 * WebSocket upgrades go through the gate to the simulator's proxy. Upgraded sockets leave the
 * server's bookkeeping, so the returned set holds them for the shutdown to end.
 */
function handleUpgrades(server: Server, gate: Gate, { proxy, viserView }: Services): Set<Duplex> {
    const upgraded = new Set<Duplex>();
    server.on('upgrade', (req: IncomingMessage, socket: Duplex, head: Buffer) => {
        upgraded.add(socket);
        socket.on('close', () => upgraded.delete(socket));
        socket.on('error', () => socket.destroy());
        const url = gate.admitUpgrade(req, socket);
        if (!url) return;
        const pathname = viserView.rewrite(req, url) ?? url.pathname;
        if (!proxy.handleUpgrade(req, socket, head, pathname)) rejectUpgrade(socket, 404, `no WebSocket endpoint at ${url.pathname}`);
    });
    return upgraded;
}

/** Listens; `onListening` runs with the real port before any request can arrive. Resolves with that port. */
async function listen(server: Server, port: number, host: string, onListening: (port: number) => void): Promise<number> {
    await new Promise<void>((resolve, reject) => {
        server.once('error', reject);
        server.listen(port, host, () => {
            server.off('error', reject);
            onListening((server.address() as AddressInfo).port);
            resolve();
        });
    });
    return (server.address() as AddressInfo).port;
}

/** A wildcard address is no name a browser may use (the Host check refuses it): print loopback. */
function displayHost(host: string): string {
    return host === '0.0.0.0' || host === '::' ? '127.0.0.1' : host.includes(':') ? `[${host}]` : host;
}

/** `IdeServer.close`: stops the simulation session, then every connection and the listener; later calls share the first one's promise. */
function shutdown(server: Server, { sims, proxy }: Services, upgraded: Set<Duplex>): () => Promise<void> {
    let closing: Promise<void> | undefined;
    return () => {
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
    };
}

/** The default venv is created by its setup script when missing; another one must exist. */
export function ros2Environment(venv: string | undefined): Ros2Environment {
    const scripts = path.join(repoDir, 'packages', 'generators-python', 'scripts');
    const dir = path.resolve(venv ?? defaults.ros2Venv);
    return new Ros2Environment({
        venv: dir,
        setupScript: dir === path.resolve(defaults.ros2Venv) ? path.join(scripts, 'setup_ros2_venv.sh') : undefined,
        installScript: path.join(scripts, 'install_ros2_interfaces.sh'),
    });
}
