// Generation, stream tests and simulation of a lab workspace (docs/ide.md "Backend HTTP API",
// below the workspace's prefix), on its materialized folder with the IDE backend's services:
// the generation and simulation routes are maa-ide's own router; the test run and the
// simulation start are wrapped to check the exercise's platforms and the quotas and to record
// their results in LabStore.
import type { ServerResponse } from 'node:http';
import { type GenerateAnswer, requests } from '@maa/protocol';
import { HttpError, readJsonObject, sendJson } from '@maa/ide-server/http';
import { readRequest, type StreamTestAnswer, streamTestRequest } from '@maa/ide-server';
import type { AuthedRequest, LabRoutes } from '../http/routes.js';
import type { LabStore } from '../storage/index.js';
import type { RuntimePool } from './pool.js';
import { type OpenedWorkspace, openWorkspaceFor, requireOwner, requirePlatform, WS_PREFIX } from './resolve.js';
import type { WorkspaceRuntime } from './runtime.js';
import type { LabSimulations } from './simulations.js';

type RunHandler = (r: AuthedRequest, opened: OpenedWorkspace, runtime: WorkspaceRuntime) => Promise<void>;

export function addRunRoutes(routes: LabRoutes, pool: RuntimePool, sims: LabSimulations): void {
    const route = (method: string, path: string, handler: RunHandler) =>
        routes.add({
            method,
            path: `${WS_PREFIX}${path}`,
            access: 'user',
            handler: async (r) => {
                const opened = await openWorkspaceFor(r.store, r.auth, r.params);
                if (method !== 'GET') requireOwner(opened, `${method} ${path}`);
                const runtime = pool.get(opened);
                if (path.startsWith('/sim/')) runtime.sims.signOfLife();
                await runtime
                    .use(() => handler(r, opened, runtime))
                    .catch((e: unknown) => {
                        // No absolute path of the server's folders reaches the student.
                        if (e instanceof HttpError)
                            throw new HttpError(e.status, runtime.redact.text(e.message), runtime.redact.value(e.extra));
                        throw e;
                    });
            },
        });
    // maa-ide's own routes, on the workspace's folder.
    for (const path of ['/generated/file', '/generated/trace', '/sim/topics', '/sim/status'])
        route('GET', path, async ({ req, res, url }, _opened, runtime) => {
            await runtime.router.dispatch(req, res, `/api${path}`, url.searchParams);
        });

    route('POST', '/generate', async ({ req, res }, opened, runtime) => {
        const body = await readRequest(req, requests.generate);
        requirePlatform(opened, body.platform);
        await runtime.folder.sync();
        const { platformDir: _dir, ...answer } = await runtime.generation.generate(body.app, body.platform);
        sendJson(res, 200, { ...answer, diagnostics: runtime.redact.value(answer.diagnostics) } satisfies GenerateAnswer);
    });
    route('POST', '/test', async ({ req, res, store }, opened, runtime) => {
        const request = streamTestRequest(await readJsonObject(req));
        requirePlatform(opened, request.platform ?? 'timesync');
        await runtime.folder.sync();
        const abort = new AbortController();
        res.on('close', () => abort.abort());
        const answer = runtime.redact.value(await runtime.tests.run(request, abort.signal));
        if (answer.ok) await recordTests(store, opened, answer);
        sendJson(res, 200, answer);
    });
    route('POST', '/sim/start', async ({ req, res, auth }, opened, runtime) => {
        const request = await readRequest(req, requests.simStart);
        requirePlatform(opened, request.platform);
        sendJson(res, 200, await withRetryAfter(res, () => sims.start(opened, runtime, auth, request)));
    });
    route('POST', '/sim/stop', async ({ res }, _opened, runtime) => {
        await sims.stop(runtime, 'stopped by its student');
        sendJson(res, 200, { ok: true });
    });
}

/** Stores a test run's counts and answer as the workspace's newest test result. */
async function recordTests(store: LabStore, opened: OpenedWorkspace, answer: StreamTestAnswer): Promise<void> {
    await store.recordTestResult({
        workspaceId: opened.workspace.id,
        submissionId: null,
        passed: answer.summary.passed,
        failed: answer.summary.failed,
        skipped: 0,
        details: answer,
    });
}

/** A 429 of a quota carries Retry-After (the seconds until it frees). */
async function withRetryAfter<T>(res: ServerResponse, body: () => Promise<T>): Promise<T> {
    try {
        return await body();
    } catch (e) {
        const seconds = e instanceof HttpError ? e.extra?.['retryAfterSeconds'] : undefined;
        if (typeof seconds === 'number') res.setHeader('Retry-After', String(seconds));
        throw e;
    }
}
