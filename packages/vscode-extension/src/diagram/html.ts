/**
 * The diagram webview's page: one container, the bundled script and stylesheet from
 * `out/webview/`, and a strict Content Security Policy (nothing by default; the script only with
 * the page's nonce; styles and images only from the extension's webview folder). The page itself
 * is ../webview-page.ts's, which the simulate view shares.
 */
import { newNonce, webviewCsp, webviewPageHtml } from '../webview-page.js';

export { newNonce };

export interface WebviewPage {
    /** The webview's `cspSource` (the origin of `asWebviewUri` resources). */
    readonly cspSource: string;
    /** A fresh random nonce for this page. */
    readonly nonce: string;
    /** `asWebviewUri` of `out/webview/diagram.js` and `out/webview/diagram.css`. */
    readonly scriptUri: string;
    readonly styleUri: string;
}

/** The Content-Security-Policy of the page (styles also with the nonce). */
export function contentSecurityPolicy(cspSource: string, nonce: string): string {
    return webviewCsp(cspSource, nonce, { styleNonce: true });
}

/** The page's HTML. */
export function webviewHtml(page: WebviewPage): string {
    return webviewPageHtml({
        title: 'MontiArc Diagram',
        csp: contentSecurityPolicy(page.cspSource, page.nonce),
        nonce: page.nonce,
        scriptUri: page.scriptUri,
        styleUri: page.styleUri,
        rootId: 'maa-diagram-root',
    });
}
