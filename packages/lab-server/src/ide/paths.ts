// Where a workspace's browser IDE lives (docs/lab.md "The IDE in the lab"): the page at
// `/ide/<course>/<exercise>/<owner>/`, and below it the same relative paths the page uses
// against maa-ide (`api/files`, `api/generate`, `sim/viser/`, `assets/…`). They are rewritten
// before routing, so every request still passes the workspace's own routes and checks.

/** The page route of a workspace's IDE (a trailing `/`: the page's relative URLs resolve below it). */
export const IDE_PAGE = '/ide/:course/:exercise/:owner';

const IDE_PATH = /^\/ide\/([^/]+)\/([^/]+)\/([^/]+)(\/.*)?$/;

/** The IDE's name for the workspace's info route (`GET <prefix>`): the exercise panel reads it. */
export const EXERCISE_INFO = '/api/exercise';

/**
 * The path a request below a workspace's IDE stands for, or undefined when it is none of those
 * (other paths, and the page itself, which its route answers):
 *   /ide/c/e/o/api/exercise  → /api/ws/c/e/o        (the workspace's info)
 *   /ide/c/e/o/api/<rest>    → /api/ws/c/e/o/<rest> (files, apps, generate, test, sim/...)
 *   /ide/c/e/o/sim/<rest>    → /api/ws/c/e/o/sim/<rest> (viser, rosbridge)
 *   /ide/c/e/o/<file>        → /<file>              (the web app's static files)
 * Segments stay as sent (percent-encoded); the router decodes them. The URL parser has already
 * resolved `.` and `..`, so a rewritten path never leaves its workspace's prefix.
 */
export function rewriteIdePath(pathname: string): string | undefined {
    const m = IDE_PATH.exec(pathname);
    if (!m) return undefined;
    const [, course, exercise, owner, rest = ''] = m;
    const prefix = `/api/ws/${course}/${exercise}/${owner}`;
    if (rest === '' || rest === '/' || rest === '/index.html') return undefined;
    if (rest === EXERCISE_INFO) return prefix;
    if (rest.startsWith('/api/')) return `${prefix}${rest.slice('/api'.length)}`;
    if (rest === '/sim' || rest.startsWith('/sim/')) return `${prefix}${rest}`;
    return rest;
}
