// maa-lab's HTTP server (docs/lab.md "Running a lab"): every request passes the Host/Origin
// check (docs/lab.md "Security": maa-ide's HostOriginCheck, which also accepts the host of
// --public-url and then wants its origin), then its route's access rule (routes.ts), then its
// handler; errors are JSON.
import { createServer, type IncomingMessage, type Server, type ServerResponse } from 'node:http';
import type { AddressInfo } from 'node:net';
import { HostOriginCheck, HttpError, sendError, StaticApp } from '@maa/ide-server/http';
import { type OidcSettings, OidcSignOn } from '../auth/oidc.js';
import { DEFAULT_RATE_LIMITS, LoginRateLimiter, type RateLimitOptions } from '../auth/rate-limit.js';
import { DEFAULT_SESSION_HOURS, SessionService } from '../auth/sessions.js';
import { addDashboardRoutes, type DashboardHandle } from '../dashboard/index.js';
import { addGradingRoutes, GradingService, type GradingServiceOptions } from '../grading/index.js';
import { addHomePage, addIdePage, rewriteIdePath } from '../ide/index.js';
import type { LabStore } from '../storage/index.js';
import { type LabWorkspaceOptions, LabWorkspaces } from '../workspaces/index.js';
import { addAuthRoutes } from './auth-routes.js';
import { addCourseRoutes } from './course-routes.js';
import { addOidcRoutes } from './oidc-routes.js';
import { addPages } from './pages.js';
import { type LabRequest, LabRoutes, type Match, SAFE_METHODS } from './routes.js';

export interface LabServerOptions {
    store: LabStore;
    /** the address to listen on (default 127.0.0.1) */
    host?: string;
    /** the port (default 8090; 0: any free one) */
    port?: number;
    /** the address users open, e.g. https://lab.example.org behind a proxy (default http://host:port) */
    publicUrl?: string;
    /** behind a reverse proxy: the client address is the last X-Forwarded-For entry, cookies are Secure */
    trustProxy?: boolean;
    sessionHours?: number;
    /** the clock sessions start and expire by (default Date.now; a test moves it to expire a session at once) */
    now?: () => number;
    rateLimits?: RateLimitOptions;
    /** single sign-on (OpenID Connect); off when absent */
    oidc?: OidcSettings;
    /** the web app's folder, served to anyone (static assets) for paths no route has */
    appDir?: string;
    /** where the server's log lines go (default: stderr) */
    log?: (line: string) => void;
    /** students' workspaces: where their folders go, the quotas, the simulator (docs/lab.md "Workspaces") */
    workspaces?: LabWorkspaceOptions;
    /** autograding (docs/lab.md "Grading"): the engine, the Python, the Ray address; recordings go to `workspaces.dataDir` */
    grading?: Omit<GradingServiceOptions, 'dataDir'>;
}

export interface LabServer {
    /** the URL it listens on */
    url: string;
    /** the address users open (--public-url, or url) */
    publicUrl: string;
    port: number;
    /** add routes behind the same session, role and CSRF checks (docs/lab.md "Adding routes") */
    routes: LabRoutes;
    sessions: SessionService;
    /** students' workspaces: their runtimes and simulations */
    workspaces: LabWorkspaces;
    /** the instructor's dashboard's checker thread */
    dashboard: DashboardHandle;
    /** the grading runs (docs/lab.md "Grading") */
    grading: GradingService;
    close(): Promise<void>;
}

export const DEFAULT_PORT = 8090;

export async function startLabServer(options: LabServerOptions): Promise<LabServer> {
    const log = options.log ?? ((line: string) => process.stderr.write(`maa-lab: ${line}\n`));
    const host = options.host ?? '127.0.0.1';
    const server = createServer();
    const port = await listen(server, options.port ?? DEFAULT_PORT, host);
    const url = `http://${host.includes(':') ? `[${host}]` : host}:${port}`;
    const publicUrl = (options.publicUrl ?? url).replace(/\/+$/, '');
    const secure = publicUrl.startsWith('https:') || options.trustProxy === true;
    const sessions = new SessionService(options.store, {
        secure,
        ttlMs: (options.sessionHours ?? DEFAULT_SESSION_HOURS) * 3600_000,
        ...(options.now ? { now: options.now } : {}),
    });
    const routes = new LabRoutes();
    addAuthRoutes(routes, { sessions, limiter: new LoginRateLimiter(options.rateLimits ?? DEFAULT_RATE_LIMITS), log });
    addCourseRoutes(routes);
    // the instructor's dashboard; "is simulating" from the workspaces' running simulations
    const dashboard = addDashboardRoutes(routes, { live: { isSimulating: (id) => workspaces.pool.find(id)?.sim !== undefined } });
    addPages(routes, options.oidc !== undefined);
    addIdePage(routes, options.appDir);
    addHomePage(routes);
    if (options.oidc) {
        const signOn = await OidcSignOn.discover(options.oidc, `${publicUrl}/api/oidc/callback`);
        addOidcRoutes(routes, signOn, sessions, secure, log);
    }
    const context: Context = {
        store: options.store,
        origin: new HostOriginCheck('maa-lab', host, port, options.publicUrl),
        routes,
        sessions,
        publicUrl,
        trustProxy: options.trustProxy === true,
        app: options.appDir ? new StaticApp(options.appDir, 'the web app folder') : undefined,
        log,
    };
    const workspaces = new LabWorkspaces(
        { routes, store: options.store, sessions, originRefusal: (req) => context.origin.refusal(req), log },
        options.workspaces,
    );
    const grading = startGrading(options, routes, workspaces.dataDir, log);
    server.on('request', (req: IncomingMessage, res: ServerResponse) => {
        res.on('finish', () => log(`${req.method} ${(req.url ?? '/').split('?')[0]} ${res.statusCode}`));
        void handle(context, req, res);
    });
    // WebSockets: only a workspace's simulation endpoints, after their checks (else 404); the
    // IDE's (`/ide/<c>/<e>/<o>/sim/...`) are the same endpoints under the page's path.
    server.on('upgrade', (req, socket, head) => {
        const [pathname = '/', query] = (req.url ?? '/').split('?', 2);
        const rewritten = rewriteIdePath(pathname);
        if (rewritten) req.url = query === undefined ? rewritten : `${rewritten}?${query}`;
        workspaces.upgrade(req, socket, head);
    });
    const cleanup = setInterval(() => void options.store.deleteExpiredSessions().catch(() => undefined), 3600_000);
    cleanup.unref();
    return {
        url,
        publicUrl,
        port,
        routes,
        sessions,
        workspaces,
        dashboard,
        grading,
        close: async () => {
            clearInterval(cleanup);
            await grading.close();
            await workspaces.close();
            await dashboard.close();
            return new Promise<void>((resolve) => {
                server.close(() => resolve());
                server.closeAllConnections();
            });
        },
    };
}

/** The grading service and its routes (docs/lab.md "Grading"); recordings go to the workspaces' data directory. */
function startGrading(options: LabServerOptions, routes: LabRoutes, dataDir: string, log: (line: string) => void): GradingService {
    const grading = new GradingService(options.store, { log, ...options.grading, dataDir });
    addGradingRoutes(routes, grading, dataDir);
    return grading;
}

interface Context {
    store: LabStore;
    origin: HostOriginCheck;
    routes: LabRoutes;
    sessions: SessionService;
    publicUrl: string;
    trustProxy: boolean;
    app: StaticApp | undefined;
    log: (line: string) => void;
}

async function handle(ctx: Context, req: IncomingMessage, res: ServerResponse): Promise<void> {
    const method = req.method ?? 'GET';
    try {
        const refusal = ctx.origin.refusal(req);
        if (refusal) throw new HttpError(403, refusal);
        let url: URL;
        try {
            url = new URL(req.url ?? '/', `${ctx.publicUrl}/`);
        } catch {
            throw new HttpError(400, 'malformed URL');
        }
        // A request of a workspace's IDE page is the workspace's route it stands for (ide/paths.ts).
        const rewritten = rewriteIdePath(url.pathname);
        if (rewritten !== undefined) url = new URL(`${rewritten}${url.search}`, url);
        let match: Match;
        try {
            match = ctx.routes.match(method, url.pathname);
        } catch (e) {
            if (ctx.app && e instanceof HttpError && e.status === 404 && !url.pathname.startsWith('/api/')) {
                await ctx.app.handle(req, res, url.pathname);
                return;
            }
            throw e;
        }
        const request: LabRequest = {
            req,
            res,
            url,
            params: match.params,
            clientAddress: clientAddress(req, ctx.trustProxy),
            store: ctx.store,
        };
        await dispatch(ctx, match, request);
    } catch (e) {
        if (e instanceof HttpError && e.status === 401 && wantsPage(req)) {
            res.writeHead(302, { Location: '/login', 'Cache-Control': 'no-store', 'Content-Length': 0 });
            res.end();
            return;
        }
        sendError(res, e, undefined, `${method} ${(req.url ?? '/').split('?')[0]}`);
    }
}

async function dispatch(ctx: Context, { route }: Match, request: LabRequest): Promise<void> {
    if (route.access === 'public') {
        await route.handler(request);
        return;
    }
    const auth = await ctx.sessions.authenticate(request.req);
    if (!auth) throw new HttpError(401, 'log in first (POST /api/login, or open /login)');
    if (route.access === 'instructor' && auth.user.role !== 'instructor') throw new HttpError(403, 'only an instructor may do this');
    if (!SAFE_METHODS.has(route.method) && !ctx.sessions.csrfOk(request.req, auth.session) && !fromOwnPage(request.req))
        throw new HttpError(403, "the request lacks the session's CSRF token (send it in the X-CSRF-Token header; GET /api/me gives it)");
    await route.handler({ ...request, auth });
}

/**
 * A write a browser sent from one of the lab's own pages: browsers name the sending page's origin
 * in `Origin` on every request that is no GET or HEAD, and the Host/Origin check in front of the
 * routes has already refused every origin but the lab's (and `null`). That proves what the CSRF
 * token proves, also for the IDE's webviews (the simulate view), which are frames of the lab's
 * origin but cannot read the page's token. Clients without an `Origin` still need the token.
 */
function fromOwnPage(req: IncomingMessage): boolean {
    return typeof req.headers.origin === 'string' && req.headers.origin !== '';
}

/** The client's address: the socket's, or behind a trusted proxy the last address the proxy added. */
function clientAddress(req: IncomingMessage, trustProxy: boolean): string {
    if (trustProxy) {
        const forwarded = String(req.headers['x-forwarded-for'] ?? '')
            .split(',')
            .map((s) => s.trim())
            .filter(Boolean)
            .at(-1);
        if (forwarded) return forwarded;
    }
    return req.socket.remoteAddress ?? 'unknown';
}

function wantsPage(req: IncomingMessage): boolean {
    const path = (req.url ?? '/').split('?')[0] ?? '/';
    return (req.method === 'GET' || req.method === 'HEAD') && !path.startsWith('/api/') && (req.headers.accept ?? '').includes('text/html');
}

function listen(server: Server, port: number, host: string): Promise<number> {
    return new Promise((resolve, reject) => {
        server.once('error', reject);
        server.listen(port, host, () => {
            server.off('error', reject);
            resolve((server.address() as AddressInfo).port);
        });
    });
}
