/** The backend's recording routes (docs/ide.md "Record and replay"), answers checked against @maa/protocol. */
import { answers, type SimRecordingInfo, type SimReplayAnswer } from '@maa/protocol';
import { call } from '../backend.js';

export type { SimRecordingInfo, SimReplayAnswer };

export function createReplayApi(prefix: string) {
    return {
        /** The workspace's recordings, newest first (`GET /api/sim/recordings`). */
        recordings: async (): Promise<SimRecordingInfo[]> =>
            (await call('GET', `${prefix}/api/sim/recordings`, answers.simRecordings)).recordings,
        /** Starts a replay session of a recording (`POST /api/sim/replay`). */
        replay: (recording: string): Promise<SimReplayAnswer> => call('POST', `${prefix}/api/sim/replay`, answers.simReplay, { recording }),
        stop: async (): Promise<void> => {
            await call('POST', `${prefix}/api/sim/stop`, answers.ok, {});
        },
    };
}

export type ReplayApi = ReturnType<typeof createReplayApi>;
