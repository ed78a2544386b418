/**
 * Where a simulation runs in the browser IDE (web.ts): on the backend that serves the page
 * (`maa-ide`, docs/ide.md "Backend HTTP API"), so the simulate view's webview, whose frames have
 * the page's origin in this workbench, reaches `/api/sim/...`, `/sim/rosbridge` and `/sim/viser/`
 * directly with the page's token cookie (SameSite=Strict, same site) and its own Origin, which
 * maa-ide accepts; no process, no relay, no token in a URL. Pure.
 */

/** The backend's base as the view gets it: `apiBase` (web/backend.ts backendBase) without a trailing `/`; only http(s). */
export function webBackendBase(apiBase: string): string {
    const url = new URL(apiBase);
    if (url.protocol !== 'http:' && url.protocol !== 'https:') throw new Error(`the backend must be an http(s) URL: ${apiBase}`);
    if (url.search || url.hash || url.username || url.password) throw new Error(`the backend URL must be a plain folder: ${apiBase}`);
    return `${url.origin}${url.pathname.replace(/\/+$/, '')}`;
}

/**
 * The application as the backend names it: `appFile` (a path of the workspace, `/` or `\`
 * separated as `Uri.fsPath` gives it) relative to the workspace folder `root`, with `/`.
 * Undefined when the file is not below the folder.
 */
export function webAppPath(root: string, appFile: string): string | undefined {
    const slashes = (p: string) => p.replace(/\\/g, '/');
    const folder = slashes(root).replace(/\/+$/, '');
    const file = slashes(appFile);
    if (!file.startsWith(`${folder}/`)) return undefined;
    const rel = file.slice(folder.length + 1);
    const parts = rel.split('/');
    if (rel === '' || parts.some((p) => p === '' || p === '.' || p === '..')) return undefined;
    return rel;
}
