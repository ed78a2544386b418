// The instructor's dashboard routes (docs/lab.md "The instructor's dashboard"): the JSON the
// page polls (with an ETag, so an unchanged dashboard is a 304 without a body), the CSV export,
// one workspace's files with their diagnostics (the read-only view), and the pages.
import { createHash } from 'node:crypto';
import type { ServerResponse } from 'node:http';
import { HttpError, sendJson } from '@maa/ide-server/http';
import type { LabRoutes } from '../http/routes.js';
import type { LabStore } from '../storage/index.js';
import { WorkspaceChecker } from './checker.js';
import { dashboardCsv } from './csv.js';
import { buildDashboard, type DashboardSources, type LiveSimulations, NO_LIVE_SIMULATIONS } from './data.js';
import { addDashboardPages } from './pages.js';

export interface DashboardOptions {
    /** which workspaces simulate now (default: none; the lab server passes its workspaces' simulations) */
    live?: LiveSimulations;
    /** the checker (default: the language family's, cached per workspace revision) */
    checker?: (store: LabStore) => WorkspaceChecker;
    /** a workspace is re-checked by the polls at most this often (default RECHECK_MS, 10 s) */
    recheckMs?: number;
}

/** The dashboard's checker, seen from the server: for its close and for tests. */
export interface DashboardHandle {
    /** resolves when no check runs or waits */
    settled(): Promise<void>;
    /** ends the checker thread */
    close(): Promise<void>;
}

/** Adds the dashboard's routes and pages (instructors only). */
export function addDashboardRoutes(routes: LabRoutes, options: DashboardOptions = {}): DashboardHandle {
    let checker: WorkspaceChecker | undefined;
    const sources = (store: LabStore): DashboardSources => {
        checker ??= options.checker ? options.checker(store) : new WorkspaceChecker(store, undefined, { recheckMs: options.recheckMs });
        return { store, checker, live: options.live ?? NO_LIVE_SIMULATIONS };
    };
    routes.add({
        method: 'GET',
        path: '/api/courses/:course/dashboard',
        access: 'instructor',
        handler: async ({ req, res, store, params }) => {
            const body = JSON.stringify(await buildDashboard(sources(store), params['course'] ?? ''));
            const etag = `"${createHash('sha256').update(body).digest('base64url').slice(0, 27)}"`;
            const headers = { ETag: etag, 'Cache-Control': 'no-cache' };
            if (matches(req.headers['if-none-match'], etag)) {
                res.writeHead(304, headers);
                res.end();
                return;
            }
            send(res, body, 'application/json; charset=utf-8', headers);
        },
    });
    routes.add({
        method: 'GET',
        path: '/api/courses/:course/results.csv',
        access: 'instructor',
        handler: async ({ res, store, params }) => {
            const dashboard = await buildDashboard(sources(store), params['course'] ?? '', true);
            const file = `${dashboard.course.name.replace(/[^A-Za-z0-9._-]/g, '_')}-results.csv`;
            send(res, dashboardCsv(dashboard), 'text/csv; charset=utf-8', {
                'Content-Disposition': `attachment; filename="${file}"`,
                'Cache-Control': 'no-store',
            });
        },
    });
    routes.add({
        method: 'GET',
        path: '/api/courses/:course/dashboard/:exercise/:student',
        access: 'instructor',
        handler: async ({ res, store, params }) => {
            sendJson(res, 200, await workspaceView(sources(store), params));
        },
    });
    addDashboardPages(routes);
    return {
        settled: async () => {
            await checker?.settled();
        },
        close: async () => {
            await checker?.close();
        },
    };
}

/** One student's workspace of an exercise: its current files with their contents and diagnostics. */
async function workspaceView({ store, checker }: DashboardSources, params: Record<string, string>) {
    const course = await store.findCourse(params['course'] ?? '');
    if (!course) throw new HttpError(404, `there is no course ${JSON.stringify(params['course'])}`);
    const exercise = await store.findExercise(course.id, params['exercise'] ?? '');
    if (!exercise) throw new HttpError(404, `the course ${course.name} has no exercise ${JSON.stringify(params['exercise'])}`);
    const student = await store.findUserByLogin(params['student'] ?? '');
    const enrolled = student && (await store.listEnrolled(course.id)).some((u) => u.id === student.id);
    if (!student || !enrolled)
        throw new HttpError(404, `${JSON.stringify(params['student'])} is not enrolled in the course ${course.name}`);
    const workspace = (await store.listWorkspaces(exercise.id)).find((w) => w.ownerId === student.id);
    if (!workspace) throw new HttpError(404, `${student.login} has not opened the exercise ${exercise.name} yet`);
    const check = await checker.check(workspace.id);
    const files = [];
    for (const info of await store.listFiles(workspace.id)) {
        const file = await store.readFile(workspace.id, info.path);
        files.push({
            path: info.path,
            revision: info.revision,
            content: file?.content ?? '',
            diagnostics: check.diagnostics.filter((d) => d.file === info.path),
        });
    }
    return {
        course: course.name,
        exercise: exercise.name,
        student: { login: student.login, name: student.name },
        lastActivity: workspace.lastActivity?.toISOString() ?? null,
        errors: check.errors,
        warnings: check.warnings,
        files,
    };
}

function matches(ifNoneMatch: string | undefined, etag: string): boolean {
    if (!ifNoneMatch) return false;
    return ifNoneMatch
        .split(',')
        .map((t) => t.trim().replace(/^W\//, ''))
        .some((t) => t === etag || t === '*');
}

function send(res: ServerResponse, text: string, type: string, headers: Record<string, string>): void {
    res.writeHead(200, { ...headers, 'Content-Type': type, 'Content-Length': Buffer.byteLength(text) });
    res.end(text);
}
