// Single sign-on routes: /api/oidc/start sends the browser to the provider, /api/oidc/callback
// takes it back, checks everything (auth/oidc.ts) and starts a session.
import { readCookie, sendJson } from '@maa/ide-server/http';
import type { OidcSignOn } from '../auth/oidc.js';
import type { SessionService } from '../auth/sessions.js';
import type { LabRoutes } from './routes.js';

const FLOW_COOKIE = 'maa-lab-oidc';

export function addOidcRoutes(
    routes: LabRoutes,
    signOn: OidcSignOn,
    sessions: SessionService,
    secure: boolean,
    log: (line: string) => void,
): void {
    const flowCookie = (value: string, maxAge: number) =>
        `${FLOW_COOKIE}=${value}; HttpOnly; SameSite=Lax; Path=/api/oidc; Max-Age=${maxAge}${secure ? '; Secure' : ''}`;
    routes.add({
        method: 'GET',
        path: '/api/oidc/start',
        access: 'public',
        handler: async ({ res }) => {
            const { flowId, authorizationUrl } = await signOn.start();
            res.writeHead(302, {
                Location: authorizationUrl.href,
                'Set-Cookie': flowCookie(flowId, 600),
                'Cache-Control': 'no-store',
                'Content-Length': 0,
            });
            res.end();
        },
    });
    routes.add({
        method: 'GET',
        path: '/api/oidc/callback',
        access: 'public',
        handler: async ({ req, res, store, url }) => {
            const result = await signOn.finish(store, readCookie(req.headers.cookie, FLOW_COOKIE), url);
            if (!result.ok) {
                log(`single sign-on refused: ${result.message}`);
                res.setHeader('Set-Cookie', flowCookie('', 0));
                sendJson(res, result.status, { error: result.message });
                return;
            }
            const { setCookie } = await sessions.start(result.user);
            log(`login (single sign-on): ${result.user.login} (${result.user.role})`);
            res.writeHead(302, {
                Location: '/',
                'Set-Cookie': [setCookie, flowCookie('', 0)],
                'Cache-Control': 'no-store',
                'Content-Length': 0,
            });
            res.end();
        },
    });
}
