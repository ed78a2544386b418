/**
 * What every webview page of the extension shares (the diagram, src/diagram/html.ts; the simulate
 * view, src/simulate/webview-html.ts): a nonce, the base of a strict Content Security Policy and
 * the page around one root element and one bundled script. Pure, and Web Crypto only, so the
 * desktop and the web entry can both use it.
 */

/** A nonce for a page's CSP: 128 random bits as hex (Web Crypto: in Node and in a browser extension host). */
export function newNonce(): string {
    const bytes = globalThis.crypto.getRandomValues(new Uint8Array(16));
    return Array.from(bytes, (b) => b.toString(16).padStart(2, '0')).join('');
}

/**
 * A Content-Security-Policy: nothing by default, the script only with the nonce, styles, images
 * and fonts only from `cspSource` (styles also with the nonce when `styleNonce`), then `extra`.
 */
export function webviewCsp(cspSource: string, nonce: string, options: { styleNonce?: boolean; extra?: readonly string[] } = {}): string {
    return [
        "default-src 'none'",
        `script-src 'nonce-${nonce}'`,
        options.styleNonce ? `style-src ${cspSource} 'nonce-${nonce}'` : `style-src ${cspSource}`,
        `img-src ${cspSource} data:`,
        `font-src ${cspSource}`,
        ...(options.extra ?? []),
    ].join('; ');
}

/** `value` escaped for a double-quoted HTML attribute. */
function attr(value: string): string {
    return value.replace(/&/g, '&amp;').replace(/"/g, '&quot;').replace(/</g, '&lt;');
}

export interface PageParts {
    readonly title: string;
    /** The whole Content-Security-Policy (webviewCsp). */
    readonly csp: string;
    readonly nonce: string;
    /** The bundled script and stylesheet as webview URIs. */
    readonly scriptUri: string;
    readonly styleUri: string;
    /** The id of the element the script renders into. */
    readonly rootId: string;
    readonly bodyClass?: string;
}

/** The page's HTML: the stylesheet, one root element and the script with the nonce. */
export function webviewPageHtml(page: PageParts): string {
    const bodyClass = page.bodyClass ? ` class="${attr(page.bodyClass)}"` : '';
    return `<!DOCTYPE html>
<html lang="en">
<head>
<meta charset="UTF-8">
<meta http-equiv="Content-Security-Policy" content="${attr(page.csp)}">
<meta name="viewport" content="width=device-width, initial-scale=1.0">
<link rel="stylesheet" href="${attr(page.styleUri)}" nonce="${attr(page.nonce)}">
<title>${attr(page.title)}</title>
</head>
<body${bodyClass}>
<div id="${attr(page.rootId)}"></div>
<script nonce="${attr(page.nonce)}" src="${attr(page.scriptUri)}"></script>
</body>
</html>
`;
}
