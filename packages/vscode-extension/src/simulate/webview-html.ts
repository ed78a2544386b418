/**
 * The simulate webview's page: the panel's script and stylesheet from the extension
 * (`out/webview/`), under a Content Security Policy that runs only the script with this page's
 * nonce and lets the page reach nothing but the relay (fetch and WebSockets: `connect-src`; the
 * viser view: `frame-src`). Pure.
 */
import { randomBytes } from 'node:crypto';

export interface SimulatePage {
    /** The webview's `cspSource` (where its own resources come from). */
    cspSource: string;
    /** The panel's script and stylesheet as webview URIs. */
    script: string;
    style: string;
    /** The relay's origin as the webview reaches it (`asExternalUri`), e.g. `http://127.0.0.1:40123`. */
    relayOrigin: string;
    nonce?: string;
}

/** A fresh nonce (128 random bits). */
export function newNonce(): string {
    return randomBytes(16).toString('base64url');
}

/** The WebSocket origin of an http(s) origin (`http:` → `ws:`, `https:` → `wss:`). */
export function webSocketOrigin(origin: string): string {
    const url = new URL(origin);
    if (url.protocol !== 'http:' && url.protocol !== 'https:') throw new Error(`not an http(s) origin: ${origin}`);
    return `${url.protocol === 'https:' ? 'wss:' : 'ws:'}//${url.host}`;
}

/** The Content-Security-Policy of the page. */
export function simulateCsp(page: Required<Pick<SimulatePage, 'cspSource' | 'relayOrigin' | 'nonce'>>): string {
    const relay = new URL(page.relayOrigin).origin;
    return [
        "default-src 'none'",
        `script-src 'nonce-${page.nonce}'`,
        `style-src ${page.cspSource}`,
        `img-src ${page.cspSource} data:`,
        `font-src ${page.cspSource}`,
        `connect-src ${relay} ${webSocketOrigin(relay)}`,
        `frame-src ${relay}`,
    ].join('; ');
}

function attr(value: string): string {
    return value.replace(/&/g, '&amp;').replace(/"/g, '&quot;').replace(/</g, '&lt;');
}

export function simulateHtml(page: SimulatePage): string {
    const nonce = page.nonce ?? newNonce();
    const csp = simulateCsp({ cspSource: page.cspSource, relayOrigin: page.relayOrigin, nonce });
    return `<!doctype html>
<html lang="en">
<head>
<meta charset="utf-8">
<meta http-equiv="Content-Security-Policy" content="${attr(csp)}">
<meta name="viewport" content="width=device-width, initial-scale=1">
<link rel="stylesheet" href="${attr(page.style)}">
<title>MontiArc Simulation</title>
</head>
<body class="maa-vscode-simulate">
<div id="simulate-root"></div>
<script nonce="${attr(nonce)}" src="${attr(page.script)}"></script>
</body>
</html>
`;
}
