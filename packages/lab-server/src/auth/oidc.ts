// Single sign-on through OpenID Connect (docs/lab.md "Single sign-on") with openid-client: the
// authorization-code flow with PKCE (S256), state and nonce. The pending flow (verifier, state,
// nonce) stays on the server under a random id in a short-lived cookie; the callback checks all
// three. A user is found by the ID token's issuer and subject; a user without an identity yet
// whose e-mail the provider has verified is linked to it on the first sign-on.
import * as client from 'openid-client';
import type { LabStore, User } from '../storage/index.js';
import { newSecret } from './tokens.js';

export interface OidcSettings {
    /** the provider's issuer URL (its discovery document is at .well-known/openid-configuration) */
    issuer: string;
    clientId: string;
    clientSecret: string;
    /** requested scopes (default `openid email profile`) */
    scope?: string;
    /** allow an http:// provider (tests, a provider on the same machine); never for a real one */
    allowHttp?: boolean;
}

interface PendingFlow {
    verifier: string;
    state: string;
    nonce: string;
    expires: number;
}

/** How long a sign-on may take between start and callback. */
const FLOW_MS = 10 * 60 * 1000;
/** At most this many unfinished sign-ons are kept (the oldest go first). */
const MAX_PENDING = 10_000;

export type SignOnResult = { ok: true; user: User } | { ok: false; status: 400 | 403; message: string };

export class OidcSignOn {
    private readonly pending = new Map<string, PendingFlow>();

    private constructor(
        private readonly config: client.Configuration,
        private readonly settings: OidcSettings,
        private readonly redirectUri: string,
    ) {}

    /** Discovers the provider; `redirectUri` is the lab's callback as the provider sees it. */
    static async discover(settings: OidcSettings, redirectUri: string): Promise<OidcSignOn> {
        const execute = settings.allowHttp ? [client.allowInsecureRequests] : [];
        const config = await client.discovery(new URL(settings.issuer), settings.clientId, settings.clientSecret, undefined, { execute });
        return new OidcSignOn(config, settings, redirectUri);
    }

    /** Starts a sign-on: the flow id (for the cookie) and the provider's authorization URL. */
    async start(): Promise<{ flowId: string; authorizationUrl: URL }> {
        const verifier = client.randomPKCECodeVerifier();
        const flow: PendingFlow = { verifier, state: client.randomState(), nonce: client.randomNonce(), expires: Date.now() + FLOW_MS };
        const flowId = newSecret();
        this.prune();
        this.pending.set(flowId, flow);
        const authorizationUrl = client.buildAuthorizationUrl(this.config, {
            redirect_uri: this.redirectUri,
            scope: this.settings.scope ?? 'openid email profile',
            code_challenge: await client.calculatePKCECodeChallenge(verifier),
            code_challenge_method: 'S256',
            state: flow.state,
            nonce: flow.nonce,
        });
        return { flowId, authorizationUrl };
    }

    /** Ends a sign-on at the callback: exchanges the code (checking state, nonce, PKCE) and finds the user. */
    async finish(store: LabStore, flowId: string | undefined, callbackUrl: URL): Promise<SignOnResult> {
        const flow = flowId === undefined ? undefined : this.pending.get(flowId);
        if (flowId !== undefined) this.pending.delete(flowId); // a flow is used once
        if (!flow || flow.expires < Date.now())
            return { ok: false, status: 400, message: 'this sign-on was not started here or took too long: start it again' };
        let identity: Identity;
        try {
            const tokens = await client.authorizationCodeGrant(this.config, callbackUrl, {
                pkceCodeVerifier: flow.verifier,
                expectedState: flow.state,
                expectedNonce: flow.nonce,
                idTokenExpected: true,
            });
            const claims = tokens.claims();
            if (!claims) return { ok: false, status: 400, message: 'the provider sent no ID token' };
            identity = { issuer: claims.iss, subject: claims.sub, ...emailOf(claims) };
            // Providers that keep the e-mail out of the ID token give it at the userinfo endpoint.
            if (identity.email === undefined && tokens.access_token) {
                identity = { ...identity, ...emailOf(await client.fetchUserInfo(this.config, tokens.access_token, claims.sub)) };
            }
        } catch (e) {
            return { ok: false, status: 400, message: `the sign-on failed: ${describe(e)}` };
        }
        return findUser(store, identity);
    }

    private prune(): void {
        const now = Date.now();
        for (const [id, flow] of this.pending) if (flow.expires < now) this.pending.delete(id);
        while (this.pending.size >= MAX_PENDING) {
            const oldest = this.pending.keys().next().value;
            if (oldest === undefined) break;
            this.pending.delete(oldest);
        }
    }
}

/** An openid-client error with what caused it (its message alone is often "invalid response encountered"). */
function describe(error: unknown): string {
    const parts: string[] = [];
    for (let e: unknown = error; e instanceof Error && parts.length < 3; e = e.cause) parts.push(e.message);
    return parts.join(': ') || String(error);
}

/** Who signed on: the ID token's issuer and subject, and the e-mail address the provider verified. */
interface Identity {
    issuer: string;
    subject: string;
    email?: string;
}

function emailOf(claims: Record<string, unknown>): { email?: string } {
    const email = claims['email'];
    return typeof email === 'string' && claims['email_verified'] === true ? { email } : {};
}

async function findUser(store: LabStore, identity: Identity): Promise<SignOnResult> {
    const known = await store.findUserByOidc(identity.issuer, identity.subject);
    if (known) return { ok: true, user: known };
    if (identity.email) {
        const byEmail = await store.findUserByEmail(identity.email);
        if (byEmail && byEmail.oidcIssuer === null)
            return { ok: true, user: await store.linkOidc(byEmail.id, identity.issuer, identity.subject) };
    }
    return {
        ok: false,
        status: 403,
        message:
            'there is no lab account for this sign-on (ask the instructor to add you to the roster with the e-mail address your university knows)',
    };
}
