/** The backend's recording routes (docs/ide.md "Record and replay"), answers checked against @maa/protocol. */
import { answers, formatIssues, type SimRecordingInfo, type SimReplayAnswer } from '@maa/protocol';
import { BackendError } from '../backend.js';
import { backendError } from '../logic.js';

export type { SimRecordingInfo, SimReplayAnswer };

async function request(method: 'GET' | 'POST', url: string, body?: unknown): Promise<unknown> {
    const res = await fetch(url, {
        method,
        headers: body === undefined ? {} : { 'content-type': 'application/json' },
        body: body === undefined ? undefined : JSON.stringify(body),
    });
    const text = await res.text();
    let json: unknown = text;
    try {
        json = text ? JSON.parse(text) : {};
    } catch {
        /* keep the text */
    }
    if (!res.ok) {
        const { message, log } = backendError(res.status, json);
        throw new BackendError(message, log);
    }
    return json;
}

export function createReplayApi(prefix: string) {
    return {
        /** The workspace's recordings, newest first (`GET /api/sim/recordings`). */
        recordings: async (): Promise<SimRecordingInfo[]> => {
            const json = await request('GET', `${prefix}/api/sim/recordings`);
            const issues = answers.simRecordings.issues(json);
            if (issues.length > 0) throw new BackendError(`unexpected recordings answer: ${formatIssues(issues)}`, []);
            return (json as { recordings: SimRecordingInfo[] }).recordings;
        },
        /** Starts a replay session of a recording (`POST /api/sim/replay`). */
        replay: async (recording: string): Promise<SimReplayAnswer> => {
            const json = await request('POST', `${prefix}/api/sim/replay`, { recording });
            const issues = answers.simReplay.issues(json);
            if (issues.length > 0) throw new BackendError(`unexpected replay answer: ${formatIssues(issues)}`, []);
            return json as SimReplayAnswer;
        },
        stop: async (): Promise<void> => {
            await request('POST', `${prefix}/api/sim/stop`, {});
        },
    };
}

export type ReplayApi = ReturnType<typeof createReplayApi>;
