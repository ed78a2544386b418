// A workspace's simulation endpoints below its prefix: `<prefix>/sim/rosbridge` (WebSocket) and
// `<prefix>/sim/viser/...` (HTTP and WebSocket), handed to maa-ide's SimProxy of the workspace's
// session. Only the workspace's owner reaches them (rosbridge drives the robot: no read-only
// use), after the same Host/Origin and session checks as every route; WebSocket upgrades are
// checked here since they bypass the routes.
import type { IncomingMessage } from 'node:http';
import type { Duplex } from 'node:stream';
import { ROSBRIDGE_PATH, rejectUpgrade, VISER_PATH } from '@maa/ide-server';
import { HttpError, sendJson } from '@maa/ide-server/http';
import type { Authenticated, SessionService } from '../auth/sessions.js';
import type { AuthedRequest, LabRoutes } from '../http/routes.js';
import type { LabStore } from '../storage/index.js';
import type { RuntimePool } from './pool.js';
import { type OpenedWorkspace, openWorkspaceFor, requireOwner, WS_PREFIX } from './resolve.js';

/** `/api/ws/<course>/<exercise>/<owner>/sim/<rest>` → its parts (undefined for any other path). */
const SIM_PATH = /^\/api\/ws\/([^/]+)\/([^/]+)\/([^/]+)(\/sim\/.*)$/;

export function addProxyRoutes(routes: LabRoutes, pool: RuntimePool): void {
    const viser = async (r: AuthedRequest): Promise<void> => {
        const opened = await ownersWorkspace(r.store, r.auth, r.params, 'use the simulation');
        const runtime = pool.find(opened.workspace.id);
        const rest = r.url.pathname.slice(opened.prefix.length);
        if (!runtime) {
            sendJson(r.res, 502, { error: 'no simulation session is running (start one with POST .../sim/start)' });
            return;
        }
        if (rest === VISER_PATH) {
            // Below the prefix, as maa-ide does for its own: relative URLs of the page resolve under it.
            r.res.writeHead(301, { Location: `${opened.prefix}${VISER_PATH}/${r.url.search}`, 'Content-Length': 0 });
            r.res.end();
            return;
        }
        r.req.url = `${rest}${r.url.search}`;
        runtime.proxy.handleRequest(r.req, r.res, rest);
    };
    for (const path of [VISER_PATH, `${VISER_PATH}/`, `${VISER_PATH}/*`, ROSBRIDGE_PATH])
        routes.add({ method: 'GET', path: `${WS_PREFIX}${path}`, access: 'user', handler: viser });
}

/** What the upgrade handler needs of the server. */
export interface UpgradeChecks {
    store: LabStore;
    sessions: SessionService;
    /** why the request's Host or Origin is refused (undefined: accepted) */
    originRefusal(req: IncomingMessage): string | undefined;
}

/**
 * Handles a WebSocket upgrade: a workspace's simulation endpoint after the checks, anything else
 * 404. The sockets it hands over are kept (`open`) so the server's stop can end them.
 */
export class WorkspaceUpgrades {
    readonly open = new Set<Duplex>();

    constructor(
        private readonly pool: RuntimePool,
        private readonly checks: UpgradeChecks,
    ) {}

    async handle(req: IncomingMessage, socket: Duplex, head: Buffer): Promise<void> {
        try {
            const refusal = this.checks.originRefusal(req);
            if (refusal) throw new HttpError(403, refusal);
            const match = SIM_PATH.exec((req.url ?? '/').split('?')[0] ?? '/');
            if (!match) throw new HttpError(404, 'no WebSocket here');
            const [, course, exercise, owner, rest] = match as unknown as [string, string, string, string, string];
            const auth = await this.checks.sessions.authenticate(req);
            if (!auth) throw new HttpError(401, 'log in first');
            const params = { course: decode(course), exercise: decode(exercise), owner: decode(owner) };
            const opened = await ownersWorkspace(this.checks.store, auth, params, 'use the simulation');
            const runtime = this.pool.find(opened.workspace.id);
            if (!runtime) throw new HttpError(502, 'no simulation session is running');
            this.open.add(socket);
            socket.once('close', () => this.open.delete(socket));
            const query = req.url?.includes('?') ? req.url.slice(req.url.indexOf('?')) : '';
            req.url = `${rest}${query}`;
            if (!runtime.proxy.handleUpgrade(req, socket, head, rest)) throw new HttpError(404, 'no WebSocket here');
        } catch (e) {
            const status = e instanceof HttpError ? e.status : 500;
            rejectUpgrade(socket, status, e instanceof HttpError ? e.message : 'internal error');
        }
    }

    closeAll(): void {
        for (const socket of this.open) socket.destroy();
        this.open.clear();
    }
}

async function ownersWorkspace(
    store: LabStore,
    auth: Authenticated,
    params: Record<string, string>,
    what: string,
): Promise<OpenedWorkspace> {
    const opened = await openWorkspaceFor(store, auth, params);
    requireOwner(opened, what);
    return opened;
}

function decode(segment: string): string {
    try {
        return decodeURIComponent(segment);
    } catch {
        throw new HttpError(400, `malformed path segment: ${segment}`);
    }
}
