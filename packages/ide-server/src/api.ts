import { readFile, stat } from 'node:fs/promises';
import path from 'node:path';
import { type AppPlatformInfo, listApps, readApp } from './apps.js';
import type { GenerationService } from './generation.js';
import {
    requests,
    type FilesAnswer,
    type GenerateAnswer,
    type OkAnswer,
    type SimStartAnswer,
    type SimStartRequest,
    type TopicMapAnswer,
} from '@maa/protocol';
import { HttpError, type Redact, readBody, readJsonObject, readRequest, requireQuery, sendJson, sendText } from './http-util.js';
import { ROSBRIDGE_PATH, VISER_PATH } from './proxy.js';
import { addRecordingRoutes } from './recording-routes.js';
import type { Recordings } from './recordings.js';
import { Router } from './router.js';
import { StreamTestService, streamTestRequest } from './stream-tests.js';
import { topicMap } from './topic-map.js';
import type { SimMode, SimSessions } from './sim-session.js';
import type { Workspace } from './workspace.js';

export interface ApiOptions {
    workspace: Workspace;
    generation: GenerationService;
    sims: SimSessions;
    /** Largest accepted file body (PUT /api/file). */
    maxFileBytes: number;
    /** What error bodies and simulator logs pass through (no absolute paths). */
    redact?: Redact;
    /** The workspace's recordings (record and replay, recordings.ts); absent: neither is offered (the lab). */
    recordings?: Recordings;
}

const OK: OkAnswer = { ok: true };

/** The generator family a simulation mode runs (docs/ide.md: lockstep = timesync, ros2 = ros2). */
const MODE_KIND: Record<SimMode, string> = { lockstep: 'timesync', ros2: 'ros2' };

/** The routes of docs/ide.md "Backend HTTP API". */
export function createApiRouter(options: ApiOptions): Router {
    const router = new Router(options.redact);
    addWorkspaceRoutes(router, options);
    addGenerationRoutes(router, options);
    addSimulationRoutes(router, options);
    addTestRoutes(router, options);
    if (options.recordings) addRecordingRoutes(router, options.recordings, options.sims);
    return router;
}

/** The model files of the workspace and its applications. */
function addWorkspaceRoutes(router: Router, { workspace, maxFileBytes }: ApiOptions): void {
    router.on('GET', '/api/files', async ({ res }) => {
        sendJson(res, 200, { root: workspace.name, entries: await workspace.list() } satisfies FilesAnswer);
    });

    router.on('GET', '/api/file', async ({ res, query }) => {
        sendText(res, 200, (await workspace.read(requireQuery(query, 'path'))).toString('utf8'));
    });
    router.on('PUT', '/api/file', async ({ req, res, query }) => {
        const rel = requireQuery(query, 'path');
        await workspace.write(rel, await readBody(req, maxFileBytes));
        sendJson(res, 200, OK);
    });
    router.on('DELETE', '/api/file', async ({ res, query }) => {
        await workspace.delete(requireQuery(query, 'path'));
        sendJson(res, 200, OK);
    });

    router.on('GET', '/api/apps', async ({ res }) => {
        sendJson(res, 200, { apps: await listApps(workspace) });
    });
}

/** Generating a platform and reading what it generated. */
function addGenerationRoutes(router: Router, { generation, redact }: ApiOptions): void {
    router.on('POST', '/api/generate', async ({ req, res }) => {
        const body = await readRequest(req, requests.generate);
        const { platformDir: _dir, ...answer } = await generation.generate(body.app, body.platform);
        // Diagnostics of a failed write name the output folder: no absolute paths in answers.
        sendJson(res, 200, (redact ? { ...answer, diagnostics: redact.value(answer.diagnostics) } : answer) satisfies GenerateAnswer);
    });
    router.on('GET', '/api/generated/file', async ({ res, query }) => {
        const root = generation.platformRoot(requireQuery(query, 'app'), requireQuery(query, 'platform'));
        const rel = requireQuery(query, 'path');
        const abs = await root.resolve(rel);
        const info = await stat(abs).catch(() => undefined);
        if (!info?.isFile()) throw new HttpError(404, `not generated: ${rel}`);
        sendText(res, 200, await readFile(abs, 'utf8'));
    });
    router.on('GET', '/api/generated/trace', async ({ res, query }) => {
        const app = requireQuery(query, 'app');
        const platform = requireQuery(query, 'platform');
        const abs = await generation.platformRoot(app, platform).resolve('.maa-trace.json');
        const text = await readFile(abs, 'utf8').catch(() => {
            throw new HttpError(404, `no trace: ${app} has not been generated for ${platform}`);
        });
        sendText(res, 200, text, 'application/json; charset=utf-8');
    });
}

/** The stream tests of an application (docs/ide.md; the answer of `maa-gen test --format json`). */
function addTestRoutes(router: Router, { workspace, generation, redact }: ApiOptions): void {
    const tests = new StreamTestService(workspace, generation);
    router.on('POST', '/api/test', async ({ req, res }) => {
        const request = streamTestRequest(await readJsonObject(req));
        // A client that goes away (a cancelled test run) stops the Python run.
        const abort = new AbortController();
        res.on('close', () => abort.abort());
        const answer = await tests.run(request, abort.signal);
        sendJson(res, 200, redact ? redact.value(answer) : answer);
    });
}

/** Running a generated platform in the simulator. */
function addSimulationRoutes(router: Router, options: ApiOptions): void {
    const { sims, redact } = options;
    router.on('POST', '/api/sim/start', async ({ req, res }) => {
        sendJson(res, 200, (await startSimulation(options, await readRequest(req, requests.simStart))) satisfies SimStartAnswer);
    });
    // The port topics of a generated platform (run /api/generate or /api/sim/start first).
    router.on('GET', '/api/sim/topics', async ({ res, query }) => {
        const answer = await platformTopics(options, requireQuery(query, 'app'), requireQuery(query, 'platform'));
        sendJson(res, 200, answer satisfies TopicMapAnswer);
    });
    router.on('POST', '/api/sim/stop', async ({ res }) => {
        await sims.stop();
        sendJson(res, 200, OK);
    });
    router.on('GET', '/api/sim/status', ({ res }) => {
        const status = sims.status();
        sendJson(res, 200, redact ? { ...status, log: redact.value(status.log) } : status);
    });
}

/** Checks the mode against the platform's kind, generates the platform (409 if that fails) and starts a session. */
export async function startSimulation(
    { workspace, generation, sims, recordings }: ApiOptions,
    request: SimStartRequest,
): Promise<SimStartAnswer> {
    const { app: appPath, platform: platformName, speed, record, ...body } = request;
    if (record && !recordings) throw new HttpError(400, 'recording is not offered here');
    const platform = await platformOf(workspace, appPath, platformName);
    const mode = body.mode ?? (platform.kind === 'ros2' ? 'ros2' : 'lockstep');
    if (platform.kind !== MODE_KIND[mode]) {
        throw new HttpError(
            400,
            `${mode} mode needs a ${MODE_KIND[mode]} platform; '${platformName}' is a ${platform.kind || 'unknown'} platform`,
        );
    }
    const generated = await generation.generate(appPath, platformName);
    if (!generated.ok) {
        const errors = generated.diagnostics.filter((d) => d.severity === 'error').length;
        throw new HttpError(409, `generating ${platformName} failed with ${errors} error${errors === 1 ? '' : 's'}`, {
            diagnostics: generated.diagnostics,
        });
    }
    const target = record && recordings ? await recordings.newTarget({ app: appPath, platform: platformName, mode }) : undefined;
    const { session } = await sims.start({
        app: appPath,
        platform: platformName,
        mode,
        speed,
        platformDir: generated.platformDir,
        ...(target ? { record: target.file } : {}),
    });
    return { ok: true, session, mode, rosbridge: ROSBRIDGE_PATH, viser: `${VISER_PATH}/` };
}

/** The port → topic map of a platform the simulator runs, read from its generated files. */
async function platformTopics({ workspace, generation }: ApiOptions, appPath: string, platformName: string): Promise<TopicMapAnswer> {
    const platform = await platformOf(workspace, appPath, platformName);
    const mode = (Object.keys(MODE_KIND) as SimMode[]).find((m) => MODE_KIND[m] === platform.kind);
    if (!mode)
        throw new HttpError(400, `'${platformName}' is a ${platform.kind || 'unknown'} platform, which does not run in the simulator`);
    generation.platformRoot(appPath, platformName); // checks the app path and the platform name
    const platformDir = path.join(generation.appOutDir(appPath), platformName);
    // the automata table names model files relative to the model root; the IDE opens them in the workspace
    const modelRoot = path.relative(workspace.root, generation.modelRootOf(await workspace.confined.resolve(appPath, 'app')));
    return topicMap(platformDir, appPath, platformName, mode, modelRoot.split(path.sep).join('/'));
}

/** The platform `platformName` of the application `appPath` (400 if there is none). */
async function platformOf(workspace: Workspace, appPath: string, platformName: string): Promise<AppPlatformInfo> {
    const app = await readApp(workspace, appPath);
    const platform = app?.platforms.find((p) => p.name === platformName);
    if (!app || !platform) throw new HttpError(400, `${appPath} has no platform '${platformName}'`);
    return platform;
}
