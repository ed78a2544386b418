import type { IncomingMessage } from 'node:http';
import { generateToken, sameSecret } from './access.js';
import { VISER_PATH } from './proxy.js';

/** Where the viser page is served to a frame of another site: `/sim/viser-view/<capability>/...`. */
export const VISER_VIEW_PATH = '/sim/viser-view';

/** The other loopback name of the same machine: a different site for the browser, the same server. */
const OTHER_LOOPBACK: Record<string, string> = { '127.0.0.1': 'localhost', localhost: '127.0.0.1', '[::1]': '127.0.0.1' };

/**
 * The simulator's 3D view (viser, three.js) in a renderer process of its own (issue 18). Without a
 * GPU, WebGL renders in software, and every frame of viser blocked the main thread the page's
 * frames share (same-site frames share one process): the workbench stopped answering for seconds
 * while a simulation ran. Chromium gives a frame of another *site* its own process, and maa-ide
 * answers to both loopback names, `127.0.0.1` and `localhost`, which are different sites. So
 * `GET /sim/viser/` (the page the simulate view frames, admitted with the token) redirects to the
 * same page under the other loopback name, below a path that carries a capability: the frame of
 * the other site has no token cookie (it is the page's, SameSite=Strict), so the secret in the
 * path admits its requests and its WebSocket, to the viser proxy only, after the usual Host and
 * Origin checks (docs/ide.md, "Access"). Pages opened under another name than a loopback one
 * (maa-ide behind `--host`) keep the view in their own site.
 */
export class ViserView {
    /** The capability: fresh at every start of maa-ide, like the token. */
    private readonly capability = generateToken();

    /** The address to redirect the viser page to, or undefined when the request stays where it is. */
    redirect(req: IncomingMessage, url: URL): string | undefined {
        // Only a frame's navigation moves (scripts, tests and a tab of its own stay on the page's name).
        if (req.method !== 'GET' || url.pathname !== `${VISER_PATH}/` || req.headers['sec-fetch-dest'] !== 'iframe') return undefined;
        let host: URL;
        try {
            host = new URL(`http://${req.headers.host ?? ''}`);
        } catch {
            return undefined;
        }
        const other = OTHER_LOOPBACK[host.hostname];
        if (!other) return undefined;
        const query = new URLSearchParams(url.searchParams);
        query.delete('token');
        const search = query.toString();
        return `http://${other}${host.port ? `:${host.port}` : ''}${VISER_VIEW_PATH}/${this.capability}/${search ? `?${search}` : ''}`;
    }

    /**
     * The viser proxy's path (`/sim/viser...`) for a path below the capability, or undefined when
     * the path is not one (a wrong capability included).
     */
    innerPath(pathname: string): string | undefined {
        if (!pathname.startsWith(`${VISER_VIEW_PATH}/`)) return undefined;
        const rest = pathname.slice(VISER_VIEW_PATH.length + 1);
        const slash = rest.indexOf('/');
        const given = slash < 0 ? rest : rest.slice(0, slash);
        if (!sameSecret(given, this.capability)) return undefined;
        return `${VISER_PATH}${slash < 0 ? '' : rest.slice(slash)}`;
    }

    /** Whether a request's path is admitted by the capability (no token needed). */
    admits(pathname: string): boolean {
        return this.innerPath(pathname) !== undefined;
    }

    /** Rewrites `req.url` from the capability's path to the viser proxy's; the proxy's pathname, or undefined. */
    rewrite(req: IncomingMessage, url: URL): string | undefined {
        const inner = this.innerPath(url.pathname);
        if (inner === undefined) return undefined;
        const query = new URLSearchParams(url.searchParams);
        query.delete('token'); // maa-ide's token is not the simulator's business
        const search = query.toString();
        req.url = `${inner}${search ? `?${search}` : ''}`;
        return inner;
    }
}
