// Login, logout, who am I, and accepting an invitation (docs/lab.md "Accounts").
import { HttpError, sendJson } from '@maa/ide-server/http';
import { hashPassword, passwordProblem, verifyPassword } from '../auth/passwords.js';
import type { LoginRateLimiter } from '../auth/rate-limit.js';
import type { SessionService } from '../auth/sessions.js';
import { isSecretSyntax, secretHash } from '../auth/tokens.js';
import { readJson, stringField, userView } from './body.js';
import type { LabRequest, LabRoutes } from './routes.js';

export interface AuthRouteDeps {
    sessions: SessionService;
    limiter: LoginRateLimiter;
    /** the server's log (a password never reaches it) */
    log: (line: string) => void;
}

export function addAuthRoutes(routes: LabRoutes, deps: AuthRouteDeps): void {
    const { sessions, log } = deps;
    routes.add({
        method: 'POST',
        path: '/api/login',
        access: 'public',
        handler: (request) => logIn(request, deps),
    });
    routes.add({
        method: 'POST',
        path: '/api/logout',
        access: 'user',
        handler: async ({ res, auth }) => {
            res.setHeader('Set-Cookie', await sessions.end(auth.session));
            log(`logout: ${auth.user.login}`);
            sendJson(res, 200, { loggedOut: true });
        },
    });
    routes.add({
        method: 'GET',
        path: '/api/me',
        access: 'user',
        handler: ({ res, auth }) => sendJson(res, 200, { user: userView(auth.user), csrfToken: auth.session.csrfSecret }),
    });
    routes.add({
        method: 'POST',
        path: '/api/invitations/accept',
        access: 'public',
        handler: (request) => acceptInvitation(request, deps),
    });
}

/** POST /api/login: rate limit, password check, a new session. */
async function logIn({ req, res, store, clientAddress }: LabRequest, { sessions, limiter, log }: AuthRouteDeps): Promise<void> {
    const body = await readJson(req, 16 * 1024);
    const login = stringField(body, 'login', 256);
    const password = stringField(body, 'password', 1024);
    const wait = limiter.retryAfter(login, clientAddress);
    if (wait > 0) {
        log(`login refused (too many failures): ${JSON.stringify(login)} from ${clientAddress}`);
        res.setHeader('Retry-After', String(wait));
        throw new HttpError(429, `too many failed logins: try again in ${wait} seconds`, { retryAfter: wait });
    }
    const user = await store.findUserByLogin(login);
    if (!(await verifyPassword(user?.passwordHash, password)) || !user) {
        limiter.failed(login, clientAddress);
        log(`login failed: ${JSON.stringify(login)} from ${clientAddress}`);
        throw new HttpError(401, 'wrong login or password');
    }
    limiter.succeeded(login);
    const { setCookie, csrfToken } = await sessions.start(user);
    log(`login: ${user.login} (${user.role}) from ${clientAddress}`);
    res.setHeader('Set-Cookie', setCookie);
    sendJson(res, 200, { user: userView(user), csrfToken });
}

/** POST /api/invitations/accept: sets the password once and logs in. */
async function acceptInvitation({ req, res, store }: LabRequest, { sessions, log }: AuthRouteDeps): Promise<void> {
    const body = await readJson(req, 16 * 1024);
    const token = stringField(body, 'token', 256);
    const password = stringField(body, 'password', 1024);
    const problem = passwordProblem(password);
    if (problem) throw new HttpError(400, problem);
    if (!isSecretSyntax(token)) throw new HttpError(404, 'this invitation link is not valid (check that it was copied whole)');
    const redemption = await store.redeemInvitation(secretHash(token), await hashPassword(password));
    if (!redemption.ok) {
        if (redemption.reason === 'unknown') throw new HttpError(404, 'this invitation link is not valid (check that it was copied whole)');
        throw new HttpError(
            410,
            redemption.reason === 'used'
                ? 'this invitation link was used already: log in with your password, or ask the instructor for a new link'
                : 'this invitation link has expired: ask the instructor for a new one',
        );
    }
    const { setCookie, csrfToken } = await sessions.start(redemption.user);
    log(`invitation accepted: ${redemption.user.login}`);
    res.setHeader('Set-Cookie', setCookie);
    sendJson(res, 200, { user: userView(redemption.user), csrfToken });
}
