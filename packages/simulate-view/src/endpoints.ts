/**
 * The backend's endpoints as the panel addresses them. In the browser IDE everything is on the
 * page's origin (`/api/sim/...`, `/sim/rosbridge`, `/sim/viser/`); in the VS Code webview
 * everything is below an absolute base URL (the extension's relay, e.g.
 * `http://127.0.0.1:40123/<capability>`). Pure.
 */
import { rosbridgeUrl } from './ros/url.js';

export interface SimEndpoints {
    /** Prefix of the HTTP API paths (`''`: the page's origin). */
    api: string;
    /** The rosbridge WebSocket URL. */
    rosbridge: string;
    /** The viser page (loaded in an iframe). */
    viser: string;
}

/** The endpoints for a backend base URL (`undefined`: the page's origin, `location`). */
export function simEndpoints(base: string | undefined, location: { protocol: string; host: string }): SimEndpoints {
    if (base === undefined || base === '') {
        return { api: '', rosbridge: rosbridgeUrl(location), viser: '/sim/viser/' };
    }
    const url = new URL(base);
    if (url.protocol !== 'http:' && url.protocol !== 'https:') throw new Error(`the backend base must be an http(s) URL: ${base}`);
    const prefix = `${url.origin}${url.pathname.replace(/\/+$/, '')}`;
    const ws = `${url.protocol === 'https:' ? 'wss:' : 'ws:'}//${url.host}${url.pathname.replace(/\/+$/, '')}`;
    return { api: prefix, rosbridge: `${ws}/sim/rosbridge`, viser: `${prefix}/sim/viser/` };
}
