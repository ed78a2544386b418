// The lab's own pages before a session exists: /login and /invite (the invitation link's target),
// with one small script (no inline script: the pages' CSP allows only their own origin's).
import { sendText } from '@maa/ide-server/http';
import type { LabRoutes } from './routes.js';

/** The policy of every page the lab serves itself (login, invitation, dashboard): no inline script. */
export const LAB_PAGE_CSP =
    "default-src 'none'; script-src 'self'; style-src 'unsafe-inline'; connect-src 'self'; form-action 'self'; frame-ancestors 'none'";

/** Answers one of the lab's own HTML pages, under LAB_PAGE_CSP and never framed. */
export function sendLabPage(res: Parameters<typeof sendText>[0], html: string): void {
    res.setHeader('Content-Security-Policy', LAB_PAGE_CSP);
    res.setHeader('X-Frame-Options', 'DENY');
    sendText(res, 200, html, 'text/html; charset=utf-8');
}

function page(title: string, body: string): string {
    return `<!doctype html>
<html lang="en"><head><meta charset="utf-8"><meta name="viewport" content="width=device-width"><title>${title}</title>
<script src="/lab-assets/auth.js" defer></script></head>
<body style="font-family: sans-serif; max-width: 28em; margin: 3em auto">
<h1>${title}</h1>
${body}
<p id="message" role="status"></p>
</body></html>
`;
}

const LOGIN = page(
    'maa-lab: log in',
    `<form id="login">
<p><label>Login <input name="login" autocomplete="username" required></label></p>
<p><label>Password <input name="password" type="password" autocomplete="current-password" required></label></p>
<p><button>Log in</button></p>
</form>
<p id="sso" hidden><a href="/api/oidc/start">Log in with your university account</a></p>`,
);

const INVITE = page(
    'maa-lab: set your password',
    `<form id="invite">
<p><label>New password (at least 10 characters) <input name="password" type="password" autocomplete="new-password" required minlength="10"></label></p>
<p><button>Set password and log in</button></p>
</form>`,
);

/** The pages' script: posts the forms as JSON; the invitation token comes from the URL's fragment. */
const SCRIPT = `'use strict';
async function post(path, body) {
    const answer = await fetch(path, { method: 'POST', headers: { 'Content-Type': 'application/json' }, body: JSON.stringify(body) });
    const json = await answer.json().catch(() => ({}));
    if (!answer.ok) throw new Error(json.error || answer.statusText);
    return json;
}
function wire(id, send) {
    const form = document.getElementById(id);
    if (!form) return;
    form.addEventListener('submit', async (event) => {
        event.preventDefault();
        const message = document.getElementById('message');
        try {
            await send(new FormData(form));
            location.assign('/');
        } catch (e) {
            message.textContent = e.message;
        }
    });
}
wire('login', (data) => post('/api/login', { login: data.get('login'), password: data.get('password') }));
wire('invite', (data) => post('/api/invitations/accept', { token: location.hash.slice(1), password: data.get('password') }));
fetch('/api/oidc/enabled').then((r) => r.json()).then((j) => { if (j.enabled) document.getElementById('sso').hidden = false; }).catch(() => {});
`;

export function addPages(routes: LabRoutes, ssoEnabled: boolean): void {
    const html =
        (text: string) =>
        ({ res }: { res: Parameters<typeof sendText>[0] }) =>
            sendLabPage(res, text);
    routes.add({ method: 'GET', path: '/login', access: 'public', handler: html(LOGIN) });
    routes.add({ method: 'GET', path: '/invite', access: 'public', handler: html(INVITE) });
    routes.add({
        method: 'GET',
        path: '/lab-assets/auth.js',
        access: 'public',
        handler: ({ res }) => sendText(res, 200, SCRIPT, 'text/javascript; charset=utf-8'),
    });
    routes.add({
        method: 'GET',
        path: '/api/oidc/enabled',
        access: 'public',
        handler: ({ res }) => sendText(res, 200, JSON.stringify({ enabled: ssoEnabled }), 'application/json; charset=utf-8'),
    });
}
