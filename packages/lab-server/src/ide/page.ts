// The page of a workspace's browser IDE (docs/lab.md "The IDE in the lab"): the web app's
// index.html, for the workspace's owner and the course's instructors only (the same check as
// every workspace route), with the session's CSRF token in a meta tag: the page sends it with
// its writes (the lab wants it on every request that is no GET), as the lab's own pages do.
import { readFile } from 'node:fs/promises';
import path from 'node:path';
import { HttpError } from '@maa/ide-server/http';
import type { AuthedRequest, LabRoutes } from '../http/routes.js';
import { openWorkspaceFor } from '../workspaces/resolve.js';
import { IDE_PAGE } from './paths.js';

/** The meta tags the page reads (packages/ide-web/src/host/lab.ts). */
export const CSRF_META = 'maa-csrf-token';
export const WORKSPACE_META = 'maa-lab-workspace';

import { escapeHtml } from './html.js';

/** index.html with the lab's meta tags at the start of its head. */
export function withLabMeta(html: string, meta: Record<string, string>): string {
    const tags = Object.entries(meta)
        .map(([name, content]) => `<meta name="${escapeHtml(name)}" content="${escapeHtml(content)}">`)
        .join('');
    const head = /<head[^>]*>/i.exec(html);
    if (!head) throw new Error("the web app's index.html has no <head>");
    const at = head.index + head[0].length;
    return `${html.slice(0, at)}${tags}${html.slice(at)}`;
}

export function addIdePage(routes: LabRoutes, appDir: string | undefined): void {
    const page = async ({ res, store, auth, params }: AuthedRequest): Promise<void> => {
        const opened = await openWorkspaceFor(store, auth, params);
        if (!appDir) throw new HttpError(503, 'this lab serves no web app (start maa-lab with --app-dir)');
        const index = await readFile(path.join(appDir, 'index.html'), 'utf8').catch(() => {
            throw new HttpError(503, 'the web app is not built (npm run build -w @maa/ide-web)');
        });
        const body = withLabMeta(index, { [CSRF_META]: auth.session.csrfSecret, [WORKSPACE_META]: opened.prefix });
        res.writeHead(200, {
            'Content-Type': 'text/html; charset=utf-8',
            'Content-Length': Buffer.byteLength(body),
            // The page holds the session's CSRF token: never cached, never framed by another site.
            'Cache-Control': 'no-store',
            'X-Content-Type-Options': 'nosniff',
            'X-Frame-Options': 'SAMEORIGIN',
            'Referrer-Policy': 'same-origin',
        });
        res.end(body);
    };
    routes.add({
        method: 'GET',
        path: IDE_PAGE,
        access: 'user',
        handler: async ({ res, url }) => {
            res.writeHead(302, { Location: `${url.pathname}/${url.search}`, 'Content-Length': 0 });
            res.end();
        },
    });
    routes.add({ method: 'GET', path: `${IDE_PAGE}/`, access: 'user', handler: page });
    routes.add({ method: 'GET', path: `${IDE_PAGE}/index.html`, access: 'user', handler: page });
}
