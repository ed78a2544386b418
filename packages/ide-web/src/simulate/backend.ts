/** The backend's simulation API (docs/ide.md "Backend HTTP API"). */
import { backendError, type SimMode } from './logic.js';

export interface SimStartAnswer {
    ok: boolean;
    session?: string;
    mode?: SimMode;
    rosbridge?: string;
    viser?: string;
}

export interface SimStatusAnswer {
    running: boolean;
    /** A ROS 2 start prepares its environment (venv, interface packages); progress in `log`. */
    preparing?: boolean;
    session?: string;
    mode?: SimMode;
    app?: string;
    platform?: string;
    exitCode?: number | null;
    log?: string[];
}

export class BackendError extends Error {
    constructor(message: string, readonly log: string[]) {
        super(message);
    }
}

async function call<T>(method: 'GET' | 'POST', url: string, body?: unknown): Promise<T> {
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
        /* keep text */
    }
    if (!res.ok || (json && typeof json === 'object' && (json as { ok?: unknown }).ok === false)) {
        const { message, log } = backendError(res.status, json);
        throw new BackendError(message, log);
    }
    return json as T;
}

export const simApi = {
    start: (app: string, platform: string, mode: SimMode, speed: number): Promise<SimStartAnswer> =>
        call<SimStartAnswer>('POST', '/api/sim/start', { app, platform, mode, speed }),
    stop: (): Promise<{ ok: boolean }> => call<{ ok: boolean }>('POST', '/api/sim/stop', {}),
    status: (): Promise<SimStatusAnswer> => call<SimStatusAnswer>('GET', '/api/sim/status'),
};
