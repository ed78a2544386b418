// The dashboard's pages for instructors: `/dashboard` (asks for a course), `/dashboard/<course>`
// (the table) and `/dashboard/<course>/<exercise>/<login>` (one workspace read-only). They are
// the same small HTML shell; the script (web/dashboard/, bundled by esbuild into
// dist/web/dashboard.js at the build) renders them, under the lab's page policy (sendLabPage).
import { readFile } from 'node:fs/promises';
import { fileURLToPath } from 'node:url';
import { HttpError, sendText } from '@maa/ide-server/http';
import { sendLabPage } from '../http/pages.js';
import type { LabRoutes } from '../http/routes.js';

/** The bundle, from src/dashboard or dist/dashboard alike (both are two folders below the package). */
const BUNDLE = fileURLToPath(new URL('../../dist/web/dashboard.js', import.meta.url));

const STYLE = `
body { font-family: system-ui, sans-serif; margin: 1.5em; color: #1b1b1b; }
table { border-collapse: collapse; margin-top: 1em; }
th, td { border: 1px solid #999; padding: 0.3em 0.5em; text-align: left; vertical-align: top; }
th button { font: inherit; font-weight: bold; background: none; border: none; cursor: pointer; padding: 0; }
td.bad { background: #fde2e1; } td.warn { background: #fff3cd; } td.good { background: #dcf5dc; } td.none { background: #f2f2f2; }
.live { font-weight: bold; }
pre { background: #f6f6f6; padding: 0.5em; overflow: auto; }
.diag-error { color: #a00000; } .diag-warning { color: #7a5200; }
#status { min-height: 1.2em; }
section.grading { margin-top: 1.5em; } tr.feedback td { background: #fafafa; } tr.feedback ul { margin: 0.2em 0 0.6em; }
table.grades th button { font-weight: normal; text-decoration: underline; }
`;

export const DASHBOARD_HTML = `<!doctype html>
<html lang="en"><head><meta charset="utf-8"><meta name="viewport" content="width=device-width">
<title>maa-lab: dashboard</title>
<style>${STYLE}</style>
<script src="/lab-assets/dashboard.js" defer></script></head>
<body>
<main id="app"><h1>maa-lab: dashboard</h1><p>Loading…</p></main>
<p id="status" role="status" aria-live="polite"></p>
</body></html>
`;

export function addDashboardPages(routes: LabRoutes): void {
    const page = ({ res }: { res: Parameters<typeof sendText>[0] }) => sendLabPage(res, DASHBOARD_HTML);
    for (const path of ['/dashboard', '/dashboard/:course', '/dashboard/:course/:exercise/:student'])
        routes.add({ method: 'GET', path, access: 'instructor', handler: page });
    let script: Promise<string> | undefined;
    routes.add({
        method: 'GET',
        path: '/lab-assets/dashboard.js',
        access: 'public',
        handler: async ({ res }) => {
            script ??= readFile(BUNDLE, 'utf8');
            let text: string;
            try {
                text = await script;
            } catch {
                script = undefined;
                throw new HttpError(500, "the dashboard's script is not built (npm run build -w @maa/lab-server)");
            }
            sendText(res, 200, text, 'text/javascript; charset=utf-8');
        },
    });
}
