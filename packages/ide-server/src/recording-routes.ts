/**
 * `GET /api/sim/recordings` and `POST /api/sim/replay` (docs/ide.md "Record and replay"). A replay
 * is a simulation session like a run's (one at a time, the same proxy, idle time and stop): maa-sim
 * `replay FILE.mcap`, whose rosbridge offers the seek service and whose viser shows the scene.
 */
import type { SimRecordingsAnswer, SimReplayAnswer } from '@maa/protocol';
import { requests } from '@maa/protocol';
import { readRequest, sendJson } from './http-util.js';
import { ROSBRIDGE_PATH, VISER_PATH } from './proxy.js';
import type { Recordings } from './recordings.js';
import type { Router } from './router.js';
import type { SimSessions } from './sim-session.js';

export function addRecordingRoutes(router: Router, recordings: Recordings, sims: SimSessions): void {
    router.on('GET', '/api/sim/recordings', async ({ res }) => {
        sendJson(res, 200, { recordings: await recordings.list() } satisfies SimRecordingsAnswer);
    });
    router.on('POST', '/api/sim/replay', async ({ req, res }) => {
        const { recording } = await readRequest(req, requests.simReplay);
        const { file, info } = await recordings.resolve(recording);
        const { session } = await sims.start({
            app: info.app ?? '',
            platform: info.platform ?? '',
            mode: info.mode ?? 'lockstep',
            platformDir: '',
            replay: file,
        });
        sendJson(res, 200, {
            ok: true,
            session,
            recording: info,
            rosbridge: ROSBRIDGE_PATH,
            viser: `${VISER_PATH}/`,
        } satisfies SimReplayAnswer);
    });
}
