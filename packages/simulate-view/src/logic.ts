/** Small pure pieces of the simulate panel: modes, status text, backend answers. */
import type { SimMode, SimulatorStatus } from '@maa/protocol';
import type { AppInfo } from './contracts.js';
import { formatNumber } from './format.js';

export type { SimMode };

/** The simulator mode of a platform kind: `timesync` → lock-step, `ros2` → ROS 2; others cannot run. */
export function platformMode(kind: string): SimMode | undefined {
    if (kind === 'timesync') return 'lockstep';
    if (kind === 'ros2') return 'ros2';
    return undefined;
}

export interface RunChoice {
    app: string;
    platform: string;
    mode: SimMode;
}

/** The runnable (app, platform) pairs; lock-step platforms first (they start fastest). */
export function runChoices(apps: readonly AppInfo[]): RunChoice[] {
    const out: RunChoice[] = [];
    for (const a of apps) {
        for (const p of a.platforms) {
            const mode = platformMode(p.kind);
            if (mode) out.push({ app: a.path, platform: p.name, mode });
        }
    }
    return out;
}

/** The default platform of an app: its first lock-step platform, else its first runnable one. */
export function defaultPlatform(app: AppInfo): string | undefined {
    return (app.platforms.find((p) => platformMode(p.kind) === 'lockstep') ?? app.platforms.find((p) => platformMode(p.kind)))?.name;
}

/** The simulator's `/sim/get_status` answer (@maa/protocol's SimulatorStatus; docs/simulation.md), possibly wrapped in `{status}`: read field by field. */
export type SimStatus = Partial<SimulatorStatus>;

export function unwrapStatus(res: unknown): SimStatus {
    if (!res || typeof res !== 'object') return {};
    const r = res as Record<string, unknown>;
    if (r['status'] && typeof r['status'] === 'object' && !('time' in r)) return r['status'] as SimStatus;
    return r as SimStatus;
}

/** One status line: `running · t 12.34 s · RTF 0.98 · speed 1× · toast 0.52`. `clock` (from /clock) wins over the status's time. */
export function statusLine(status: SimStatus, clock?: number): string {
    const parts: string[] = [];
    parts.push(status.finished ? `finished (${status.finished})` : status.paused ? 'paused' : 'running');
    const t = clock ?? status.time;
    if (typeof t === 'number') parts.push(`t ${t.toFixed(2)} s`);
    if (typeof status.real_time_factor === 'number' && Number.isFinite(status.real_time_factor))
        parts.push(`RTF ${formatNumber(Number(status.real_time_factor.toFixed(2)))}`);
    if (typeof status.speed === 'number') parts.push(`speed ${status.speed === 0 ? 'max' : `${formatNumber(status.speed)}×`}`);
    if (typeof status.toast_level === 'number')
        parts.push(`toast ${status.toast_level.toFixed(2)}${status.toast_on_plate ? ' on plate' : ''}`);
    return parts.join(' · ');
}

/** The backend's `/api/sim/status` as far as the start's progress goes. */
export interface StartProgress {
    running?: boolean;
    preparing?: boolean;
    log?: readonly string[];
}

/**
 * The status line while a start request is open: what happens, the elapsed seconds and, while
 * the backend prepares a ROS 2 environment, its last log line (`maa-ide: still building … (45 s)`).
 */
export function preparingLine(label: string, seconds: number, status?: StartProgress): string {
    const elapsed = `${seconds} s`;
    if (status?.preparing) {
        const last = [...(status.log ?? [])].reverse().find((l) => l.trim() !== '');
        return `Preparing ${label} (ROS 2 environment, ${elapsed})${last ? ` · ${last.trim().slice(0, 160)}` : ''}`;
    }
    if (status?.running) return `Starting ${label}: waiting for the simulator (${elapsed})…`;
    return `Starting ${label} (generating, ${elapsed})…`;
}

/** The message and log tail of a failed backend answer (`{"error": ..., "log"?: [...]}`). */
export function backendError(status: number, body: unknown): { message: string; log: string[] } {
    let message = `HTTP ${status}`;
    let log: string[] = [];
    if (body && typeof body === 'object') {
        const b = body as Record<string, unknown>;
        if (typeof b['error'] === 'string') message = b['error'];
        else if (typeof b['message'] === 'string') message = b['message'];
        if (Array.isArray(b['log'])) log = b['log'].map(String);
        else if (typeof b['log'] === 'string') log = b['log'].split('\n');
    } else if (typeof body === 'string' && body.trim()) {
        message = body.trim().slice(0, 500);
    }
    return { message, log };
}

/** How a run's connection ended: stopped by the user, ended by the simulator, or replaced. */
export type RunEnd = 'stopped' | 'ended' | 'over';

/** The note over the port table once a run is over: whose values these are, and when they were sent. */
export function lastRunNote(end: RunEnd, clock?: number): string {
    const run = end === 'stopped' ? 'the stopped run' : end === 'ended' ? 'the run that ended' : 'the last run';
    const at = typeof clock === 'number' && Number.isFinite(clock) ? ` (t ${clock.toFixed(2)} s)` : '';
    return `Last values of ${run}${at}: they update again when a simulation runs.`;
}
