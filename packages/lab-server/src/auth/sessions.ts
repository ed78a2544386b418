// Login sessions: a random token in an HttpOnly cookie (page scripts cannot read it), its hash
// in the sessions table with the session's CSRF secret and expiry. A state-changing request must
// also carry the CSRF secret in the X-CSRF-Token header (the page gets it from /api/login or
// /api/me); a forged cross-site request has the cookie but not the secret.
import type { IncomingMessage } from 'node:http';
import { readCookie, sameSecret } from '@maa/ide-server/http';
import type { LabStore, Session, User } from '../storage/index.js';
import { isSecretSyntax, newSecret, secretHash } from './tokens.js';

export const CSRF_HEADER = 'x-csrf-token';
export const DEFAULT_SESSION_HOURS = 12;

export interface SessionCookieOptions {
    /** add `Secure` (served over https, or behind a TLS-terminating proxy) */
    secure: boolean;
    /** how long a session lasts */
    ttlMs: number;
    /** the clock sessions start and expire by (default Date.now; a test moves it to expire one) */
    now?: () => number;
}

/** A logged-in request: who, and the session it came with. */
export interface Authenticated {
    user: User;
    session: Session;
}

export class SessionService {
    constructor(
        private readonly store: LabStore,
        private readonly options: SessionCookieOptions,
    ) {}

    /** The cookie's name: `__Host-` when Secure, so no subdomain or plain-http page can set or shadow it. */
    get cookieName(): string {
        return this.options.secure ? '__Host-maa-lab-session' : 'maa-lab-session';
    }

    /** Starts a session for the user; returns the `Set-Cookie` value and the CSRF token for the page. */
    async start(user: User): Promise<{ setCookie: string; csrfToken: string }> {
        const token = newSecret();
        const csrfToken = newSecret();
        await this.store.createSession({
            id: secretHash(token),
            userId: user.id,
            csrfSecret: csrfToken,
            expiresAt: new Date(this.now() + this.options.ttlMs),
        });
        return { setCookie: this.cookie(token, Math.floor(this.options.ttlMs / 1000)), csrfToken };
    }

    /** The session and user of a request's cookie, or undefined (no cookie, unknown, expired). */
    async authenticate(req: IncomingMessage): Promise<Authenticated | undefined> {
        const token = readCookie(req.headers.cookie, this.cookieName);
        if (token === undefined || !isSecretSyntax(token)) return undefined;
        const session = await this.find(secretHash(token));
        if (!session) return undefined;
        const user = await this.store.findUserById(session.userId);
        return user && { user, session };
    }

    /** The session of the id (the token's hash) while it has not expired, else undefined. */
    find(id: string): Promise<Session | undefined> {
        return this.store.findSession(id, new Date(this.now()));
    }

    private now(): number {
        return (this.options.now ?? Date.now)();
    }

    /** Whether the request carries the session's CSRF token in its header (constant-time comparison). */
    csrfOk(req: IncomingMessage, session: Session): boolean {
        const given = req.headers[CSRF_HEADER];
        return typeof given === 'string' && sameSecret(given, session.csrfSecret);
    }

    /** Ends the session (logout). */
    async end(session: Session): Promise<string> {
        await this.store.deleteSession(session.id);
        return this.clearCookie();
    }

    clearCookie(): string {
        return this.cookie('', 0);
    }

    private cookie(value: string, maxAge: number): string {
        // Lax: the cookie comes along when a student follows a link to the lab (and back from
        // single sign-on); every state-changing request needs the CSRF header besides.
        return `${this.cookieName}=${value}; HttpOnly; SameSite=Lax; Path=/; Max-Age=${maxAge}${this.options.secure ? '; Secure' : ''}`;
    }
}
