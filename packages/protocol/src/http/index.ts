/**
 * The HTTP API between ide-server and ide-web (docs/ide.md "Backend HTTP API"): request bodies
 * the server validates, answers the client validates where a bad one would crash it.
 */
import { contract } from '../contract.js';
import { AppsAnswer } from './apps.js';
import { ErrorAnswer } from './errors.js';
import { GenerateAnswer, GenerateRequest } from './generate.js';
import { SimRecordingsAnswer, SimReplayAnswer, SimReplayRequest, SimStartAnswer, SimStartRequest, SimStatusAnswer } from './sim.js';
import { FilesAnswer, OkAnswer } from './workspace.js';

export * from './apps.js';
export * from './errors.js';
export * from './generate.js';
export * from './sim.js';
export * from './workspace.js';

/** The request bodies, by route. */
export const requests = {
    generate: contract('POST /api/generate request', GenerateRequest),
    simStart: contract('POST /api/sim/start request', SimStartRequest),
    simReplay: contract('POST /api/sim/replay request', SimReplayRequest),
};

/** The answers, by route. */
export const answers = {
    files: contract('GET /api/files answer', FilesAnswer),
    ok: contract('answer', OkAnswer),
    apps: contract('GET /api/apps answer', AppsAnswer),
    generate: contract('POST /api/generate answer', GenerateAnswer),
    simStart: contract('POST /api/sim/start answer', SimStartAnswer),
    simStatus: contract('GET /api/sim/status answer', SimStatusAnswer),
    simRecordings: contract('GET /api/sim/recordings answer', SimRecordingsAnswer),
    simReplay: contract('POST /api/sim/replay answer', SimReplayAnswer),
    error: contract('error answer', ErrorAnswer),
};
