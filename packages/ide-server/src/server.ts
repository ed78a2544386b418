import { statSync } from 'node:fs';
import { createServer, type IncomingMessage, type ServerResponse } from 'node:http';
import type { AddressInfo } from 'node:net';
import path from 'node:path';
import type { Duplex } from 'node:stream';
import { fileURLToPath } from 'node:url';
import { createApiRouter } from './api.js';
import { GenerationService } from './generation.js';
import { sendError, sendJson } from './http-util.js';
import { rejectUpgrade, SimProxy } from './proxy.js';
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
}

export interface IdeServer {
  /** `http://host:port/` with the real port. */
  url: string;
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
  const workspace = new Workspace(workspaceDir);
  const generation = new GenerationService(workspace, path.resolve(options.outDir ?? path.join(workspaceDir, '..', '.maa-ide-out')), [packageDir]);
  const sims = new SimSessions(path.resolve(options.maaSim ?? defaults.maaSim), options.simReadyTimeoutMs, ros2Environment(options.ros2Venv));
  const api = createApiRouter({ workspace, generation, sims, maxFileBytes: options.maxFileBytes ?? defaults.maxFileBytes });
  const proxy = new SimProxy(() => sims.endpoints());
  const app = new StaticApp(path.resolve(options.appDir ?? defaults.appDir));

  const handle = async (req: IncomingMessage, res: ServerResponse): Promise<void> => {
    let url: URL;
    try {
      url = new URL(req.url ?? '/', 'http://localhost');
    } catch {
      sendJson(res, 400, { error: `malformed URL: ${req.url}` });
      return;
    }
    const pathname = url.pathname;
    if (pathname === '/api' || pathname.startsWith('/api/')) await api.dispatch(req, res, pathname, url.searchParams);
    else if (pathname === '/sim' || pathname.startsWith('/sim/')) {
      if (!proxy.handleRequest(req, res, pathname)) sendJson(res, 404, { error: `unknown route: ${req.method} ${pathname}` });
    } else await app.handle(req, res, pathname);
  };

  const server = createServer((req, res) => {
    handle(req, res).catch((e: unknown) => sendError(res, e));
  });
  // Upgraded sockets leave the server's bookkeeping, so close() ends them itself.
  const upgraded = new Set<Duplex>();
  server.on('upgrade', (req: IncomingMessage, socket: Duplex, head: Buffer) => {
    upgraded.add(socket);
    socket.on('close', () => upgraded.delete(socket));
    socket.on('error', () => socket.destroy());
    let pathname: string;
    try {
      pathname = new URL(req.url ?? '/', 'http://localhost').pathname;
    } catch {
      rejectUpgrade(socket, 400, 'malformed URL');
      return;
    }
    if (!proxy.handleUpgrade(req, socket, head, pathname)) rejectUpgrade(socket, 404, `no WebSocket endpoint at ${pathname}`);
  });
  server.on('clientError', (_err, socket) => {
    if (socket.writable) socket.end('HTTP/1.1 400 Bad Request\r\nConnection: close\r\n\r\n');
    else socket.destroy();
  });

  await new Promise<void>((resolve, reject) => {
    server.once('error', reject);
    server.listen(options.port ?? defaults.port, host, () => {
      server.off('error', reject);
      resolve();
    });
  });
  const port = (server.address() as AddressInfo).port;
  const shownHost = host.includes(':') ? `[${host}]` : host;
  let closing: Promise<void> | undefined;
  return {
    url: `http://${shownHost}:${port}/`,
    port,
    workspace: workspaceDir,
    close() {
      closing ??= (async () => {
        await sims.stop().catch(() => undefined);
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
