// Single sign-on against a real OpenID Connect provider started here (the `oidc-provider`
// package, its development login and consent pages driven like a browser): the authorization-code
// flow with PKCE, state and nonce; users found by issuer + subject, or linked once by their
// verified e-mail; an unknown user, a tampered state, a replayed callback and a callback without
// the flow cookie are refused.
import { createServer, type Server } from 'node:http';
import type { AddressInfo } from 'node:net';
import Provider from 'oidc-provider';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { type LabServer, startLabServer } from '../src/http/server.js';
import { type LabStore, openLabStore } from '../src/storage/index.js';
import { BACKENDS, type Backend, startBackend } from './backends.js';

/** The provider's accounts: subject → what it says about them. */
const ACCOUNTS: Record<string, { email: string; email_verified: boolean }> = {
    'prof-0001': { email: 'prof@uni.example', email_verified: true },
    'ada-0002': { email: 'Ada@Uni.example', email_verified: true },
    'eve-0003': { email: 'eve@elsewhere.example', email_verified: true },
    'mallory-0004': { email: 'bob@uni.example', email_verified: false },
};

async function startProvider(): Promise<{ issuer: string; server: Server; setRedirect(uri: string): void }> {
    const server = createServer();
    await new Promise<void>((resolve) => server.listen(0, '127.0.0.1', resolve));
    const issuer = `http://127.0.0.1:${(server.address() as AddressInfo).port}`;
    const redirectUris: string[] = [];
    let provider: Provider | undefined;
    const make = () =>
        new Provider(issuer, {
            clients: [
                {
                    client_id: 'maa-lab',
                    client_secret: 'a-client-secret-for-the-tests',
                    redirect_uris: redirectUris,
                    grant_types: ['authorization_code'],
                    response_types: ['code'],
                },
            ],
            claims: { openid: ['sub'], email: ['email', 'email_verified'] },
            pkce: { required: () => true },
            cookies: { keys: ['a-cookie-signing-key-for-the-tests'] },
            findAccount: async (_ctx, sub) => ({
                accountId: sub,
                claims: async () => ({ sub, ...(ACCOUNTS[sub] ?? {}) }),
            }),
        });
    server.on('request', (req, res) => {
        provider ??= make();
        void provider.callback()(req, res);
    });
    return { issuer, server, setRedirect: (uri) => void redirectUris.push(uri) };
}

/** A browser: cookies per host, redirects followed by hand, forms submitted. */
class Browser {
    private readonly jars = new Map<string, Map<string, string>>();

    async get(url: string): Promise<Response> {
        return this.request(url, { method: 'GET' });
    }

    async request(url: string, init: RequestInit): Promise<Response> {
        const target = new URL(url);
        const jar = this.jars.get(target.host) ?? new Map<string, string>();
        this.jars.set(target.host, jar);
        const headers = new Headers(init.headers);
        if (jar.size > 0) headers.set('Cookie', [...jar].map(([k, v]) => `${k}=${v}`).join('; '));
        const response = await fetch(target, { ...init, headers, redirect: 'manual' });
        for (const cookie of response.headers.getSetCookie()) {
            const [pair = ''] = cookie.split(';');
            const eq = pair.indexOf('=');
            const value = pair.slice(eq + 1);
            if (value === '' || /max-age=0|expires=thu, 01 jan 1970/i.test(cookie)) jar.delete(pair.slice(0, eq));
            else jar.set(pair.slice(0, eq), value);
        }
        return response;
    }

    /** Follows redirects from `url` until an answer that is not one, or until `stopAt` says so (returns that URL). */
    async follow(url: string, stopAt: (url: URL) => boolean = () => false): Promise<{ url: string; response?: Response }> {
        let current = url;
        for (let hops = 0; hops < 20; hops++) {
            if (stopAt(new URL(current))) return { url: current };
            const response = await this.get(current);
            const location = response.headers.get('location');
            if (response.status < 300 || response.status >= 400 || !location) return { url: current, response };
            await response.arrayBuffer();
            current = new URL(location, current).href;
        }
        throw new Error('too many redirects');
    }

    /** Submits the page's form with these fields; returns where the answer redirects. */
    async submit(pageUrl: string, page: string, fields: Record<string, string>): Promise<string> {
        const action = /<form[^>]*action="([^"]+)"/.exec(page)?.[1];
        if (!action) throw new Error(`no form on ${pageUrl}: ${page.slice(0, 300)}`);
        const response = await this.request(new URL(action, pageUrl).href, {
            method: 'POST',
            headers: { 'Content-Type': 'application/x-www-form-urlencoded' },
            body: new URLSearchParams(fields).toString(),
        });
        await response.arrayBuffer();
        const location = response.headers.get('location');
        if (!location) throw new Error(`the form on ${pageUrl} answered ${response.status}`);
        return new URL(location, pageUrl).href;
    }

    cookie(host: string, name: string): string | undefined {
        return this.jars.get(host)?.get(name);
    }
}

describe.each(BACKENDS)('single sign-on on %s', (backendName) => {
    let backend: Backend;
    let store: LabStore;
    let provider: Awaited<ReturnType<typeof startProvider>>;
    let lab: LabServer;
    const log: string[] = [];

    beforeAll(async () => {
        backend = await startBackend(backendName);
        store = await openLabStore(await backend.freshStorage());
        provider = await startProvider();
        const port = await freePort();
        provider.setRedirect(`http://127.0.0.1:${port}/api/oidc/callback`);
        lab = await startLabServer({
            store,
            port,
            oidc: { issuer: provider.issuer, clientId: 'maa-lab', clientSecret: 'a-client-secret-for-the-tests', allowHttp: true },
            log: (line) => log.push(line),
        });
        await store.createUser({ login: 'prof', name: 'Prof', role: 'instructor', oidcIssuer: provider.issuer, oidcSubject: 'prof-0001' });
        await store.createUser({ login: 'ada', name: 'Ada', role: 'student', email: 'ada@uni.example' });
        await store.createUser({ login: 'bob', name: 'Bob', role: 'student', email: 'bob@uni.example' });
    });
    afterAll(async () => {
        await lab?.close();
        await new Promise((resolve) => provider?.server.close(resolve));
        provider?.server.closeAllConnections();
        await store?.close();
        await backend?.dispose();
    });

    const isCallback = (url: URL) => url.pathname === '/api/oidc/callback';

    /**
     * Starts a sign-on at the lab and signs on at the provider as `subject`; returns the callback
     * URL the provider sent the browser to. `tamper` may change the authorization request first.
     */
    async function signOnAtProvider(
        browser: Browser,
        subject: string,
        tamper?: (url: URL) => void,
    ): Promise<{ callback: string; authorization: URL }> {
        const start = await browser.get(`${lab.url}/api/oidc/start`);
        expect(start.status).toBe(302);
        const authorization = new URL(start.headers.get('location') ?? '');
        tamper?.(authorization);
        let at = await browser.follow(authorization.href, isCallback);
        for (let step = 0; step < 4 && !isCallback(new URL(at.url)); step++) {
            const page = (await at.response?.text()) ?? '';
            const fields: Record<string, string> = page.includes('name="login"')
                ? { prompt: 'login', login: subject, password: 'any' }
                : { prompt: 'consent' };
            at = await browser.follow(await browser.submit(at.url, page, fields), isCallback);
        }
        expect(isCallback(new URL(at.url))).toBe(true);
        return { callback: at.url, authorization };
    }

    it('sends the browser to the provider with PKCE (S256), state and nonce', async () => {
        const browser = new Browser();
        const start = await browser.get(`${lab.url}/api/oidc/start`);
        const url = new URL(start.headers.get('location') ?? '');
        expect(url.origin).toBe(provider.issuer);
        expect(url.searchParams.get('code_challenge_method')).toBe('S256');
        expect(url.searchParams.get('code_challenge')).toMatch(/^[A-Za-z0-9_-]{43}$/);
        expect(url.searchParams.get('state')).toBeTruthy();
        expect(url.searchParams.get('nonce')).toBeTruthy();
        expect(url.searchParams.get('redirect_uri')).toBe(`${lab.url}/api/oidc/callback`);
        expect(start.headers.get('set-cookie')).toMatch(/^maa-lab-oidc=[^;]+; HttpOnly; SameSite=Lax; Path=\/api\/oidc/);
    });

    it('logs in a user known by issuer and subject', async () => {
        const browser = new Browser();
        const { callback } = await signOnAtProvider(browser, 'prof-0001');
        const done = await browser.get(callback);
        expect(done.status, await done.clone().text()).toBe(302);
        expect(done.headers.get('location')).toBe('/');
        const me = await browser.get(`${lab.url}/api/me`);
        expect(me.status).toBe(200);
        expect(((await me.json()) as { user: { login: string } }).user.login).toBe('prof');
        expect(log).toContain('login (single sign-on): prof (instructor)');
    });

    it('links a user without an identity by the e-mail the provider verified, then finds them by subject', async () => {
        const first = new Browser();
        const done = await first.get((await signOnAtProvider(first, 'ada-0002')).callback);
        expect(done.status).toBe(302);
        const linked = await store.findUserByOidc(provider.issuer, 'ada-0002');
        expect(linked?.login).toBe('ada');
        const again = new Browser();
        expect((await again.get((await signOnAtProvider(again, 'ada-0002')).callback)).status).toBe(302);
        const me = (await (await again.get(`${lab.url}/api/me`)).json()) as { user: { login: string } };
        expect(me.user.login).toBe('ada');
    });

    it('refuses a subject without an account, and an e-mail the provider has not verified (403)', async () => {
        for (const subject of ['eve-0003', 'mallory-0004']) {
            const browser = new Browser();
            const refused = await browser.get((await signOnAtProvider(browser, subject)).callback);
            expect(refused.status).toBe(403);
            expect(((await refused.json()) as { error: string }).error).toContain('there is no lab account');
            expect((await browser.get(`${lab.url}/api/me`)).status).toBe(401);
        }
        expect((await store.findUserByLogin('bob'))?.oidcSubject).toBeNull();
    });

    it('refuses a tampered state, another nonce, another PKCE challenge, a replayed callback and a callback without the flow cookie (400)', async () => {
        const tampered = new Browser();
        const { callback } = await signOnAtProvider(tampered, 'prof-0001');
        const bad = new URL(callback);
        bad.searchParams.set('state', 'not-the-state');
        const refused = await tampered.get(bad.href);
        expect(refused.status).toBe(400);
        expect(((await refused.json()) as { error: string }).error).toContain('state');
        // The flow is used up by the refused attempt: the genuine callback no longer works either.
        expect((await tampered.get(callback)).status).toBe(400);

        const replay = new Browser();
        const genuine = (await signOnAtProvider(replay, 'prof-0001')).callback;
        expect((await replay.get(genuine)).status).toBe(302);
        expect((await replay.get(genuine)).status).toBe(400);

        // An ID token for another nonce (the authorization request changed on the way) is refused.
        const noncey = new Browser();
        const swapped = await noncey.get(
            (await signOnAtProvider(noncey, 'prof-0001', (url) => url.searchParams.set('nonce', 'an-attackers-nonce'))).callback,
        );
        expect(swapped.status).toBe(400);
        expect(((await swapped.json()) as { error: string }).error).toContain('nonce');
        // PKCE: a code issued for another code challenge is refused at the token endpoint.
        const pkce = new Browser();
        const otherChallenge = await pkce.get(
            (await signOnAtProvider(pkce, 'prof-0001', (url) => url.searchParams.set('code_challenge', 'A'.repeat(43)))).callback,
        );
        expect(otherChallenge.status).toBe(400);
        expect((await pkce.get(`${lab.url}/api/me`)).status).toBe(401);

        // Another browser (an attacker who got the callback URL) has no flow cookie.
        const victim = new Browser();
        const stolen = (await signOnAtProvider(victim, 'prof-0001')).callback;
        const attacker = new Browser();
        const answer = await attacker.get(stolen);
        expect(answer.status).toBe(400);
        expect((await attacker.get(`${lab.url}/api/me`)).status).toBe(401);
    });
});

async function freePort(): Promise<number> {
    const server = createServer();
    await new Promise<void>((resolve) => server.listen(0, '127.0.0.1', resolve));
    const { port } = server.address() as AddressInfo;
    await new Promise((resolve) => server.close(resolve));
    return port;
}
