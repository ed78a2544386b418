/**
 * The diagram webview's page: one container, the bundled script and stylesheet from
 * `out/webview/`, and a strict Content Security Policy (nothing by default; the script only with
 * the page's nonce; styles and images only from the extension's webview folder).
 */
export interface WebviewPage {
    /** The webview's `cspSource` (the origin of `asWebviewUri` resources). */
    readonly cspSource: string;
    /** A fresh random nonce for this page. */
    readonly nonce: string;
    /** `asWebviewUri` of `out/webview/diagram.js` and `out/webview/diagram.css`. */
    readonly scriptUri: string;
    readonly styleUri: string;
}

/** A nonce for a page's CSP: 128 random bits as hex (Web Crypto: in Node and in a browser extension host). */
export function newNonce(): string {
    const bytes = globalThis.crypto.getRandomValues(new Uint8Array(16));
    return Array.from(bytes, (b) => b.toString(16).padStart(2, '0')).join('');
}

/** The Content-Security-Policy of the page. */
export function contentSecurityPolicy(cspSource: string, nonce: string): string {
    return [
        "default-src 'none'",
        `script-src 'nonce-${nonce}'`,
        `style-src ${cspSource} 'nonce-${nonce}'`,
        `img-src ${cspSource} data:`,
        `font-src ${cspSource}`,
    ].join('; ');
}

function attr(value: string): string {
    return value.replace(/&/g, '&amp;').replace(/"/g, '&quot;').replace(/</g, '&lt;');
}

/** The page's HTML. */
export function webviewHtml(page: WebviewPage): string {
    const csp = contentSecurityPolicy(page.cspSource, page.nonce);
    return `<!DOCTYPE html>
<html lang="en">
<head>
<meta charset="UTF-8">
<meta http-equiv="Content-Security-Policy" content="${attr(csp)}">
<meta name="viewport" content="width=device-width, initial-scale=1.0">
<link rel="stylesheet" href="${attr(page.styleUri)}" nonce="${attr(page.nonce)}">
<title>MontiArc Diagram</title>
</head>
<body>
<div id="maa-diagram-root"></div>
<script nonce="${attr(page.nonce)}" src="${attr(page.scriptUri)}"></script>
</body>
</html>
`;
}
