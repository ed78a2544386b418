/**
 * The simulate webview's page: the panel's script and stylesheet from the extension
 * (`out/webview/`), under a Content Security Policy that runs only the script with this page's
 * nonce and lets the page reach nothing but the relay (fetch and WebSockets: `connect-src`; the
 * viser view: `frame-src`). Pure.
 */
import { newNonce, webviewCsp, webviewPageHtml } from '../webview-page.js';

export interface SimulatePage {
    /** The webview's `cspSource` (where its own resources come from). */
    cspSource: string;
    /** The panel's script and stylesheet as webview URIs. */
    script: string;
    style: string;
    /** The backend's origin as the webview reaches it: desktop the relay's (`asExternalUri`), e.g. `http://127.0.0.1:40123`; web the page's. */
    relayOrigin: string;
    nonce?: string;
}

/** The WebSocket origin of an http(s) origin (`http:` → `ws:`, `https:` → `wss:`). */
export function webSocketOrigin(origin: string): string {
    const url = new URL(origin);
    if (url.protocol !== 'http:' && url.protocol !== 'https:') throw new Error(`not an http(s) origin: ${origin}`);
    return `${url.protocol === 'https:' ? 'wss:' : 'ws:'}//${url.host}`;
}

/** The other loopback name of a loopback origin (`127.0.0.1` ↔ `localhost`, `[::1]` → `127.0.0.1`), same port; else undefined. */
export function otherLoopbackOrigin(origin: string): string | undefined {
    const url = new URL(origin);
    const other = ({ '127.0.0.1': 'localhost', localhost: '127.0.0.1', '[::1]': '127.0.0.1' } as Record<string, string>)[url.hostname];
    return other && url.protocol === 'http:' ? `http://${other}${url.port ? `:${url.port}` : ''}` : undefined;
}

/**
 * The Content-Security-Policy of the page: the common one (../webview-page.ts) plus the relay for
 * connections and frames. The viser frame may also come from the relay's other loopback name:
 * maa-ide sends it there, to another site, so that it renders in a process of its own
 * (packages/ide-server/src/viser-view.ts).
 */
export function simulateCsp(page: Required<Pick<SimulatePage, 'cspSource' | 'relayOrigin' | 'nonce'>>): string {
    const relay = new URL(page.relayOrigin).origin;
    const frames = [relay, otherLoopbackOrigin(relay)].filter((o) => o !== undefined).join(' ');
    return webviewCsp(page.cspSource, page.nonce, { extra: [`connect-src ${relay} ${webSocketOrigin(relay)}`, `frame-src ${frames}`] });
}

/** The page's HTML (a fresh nonce unless `page.nonce`). */
export function simulateHtml(page: SimulatePage): string {
    const nonce = page.nonce ?? newNonce();
    return webviewPageHtml({
        title: 'MontiArc Simulation',
        csp: simulateCsp({ cspSource: page.cspSource, relayOrigin: page.relayOrigin, nonce }),
        nonce,
        scriptUri: page.script,
        styleUri: page.style,
        rootId: 'simulate-root',
        bodyClass: 'maa-vscode-simulate',
    });
}
