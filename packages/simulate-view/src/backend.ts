/** The backend's simulation API (docs/ide.md "Backend HTTP API"); types and checks from @maa/protocol. */
import {
    type AppInfo,
    answers,
    formatIssues,
    topicMapContract,
    type Contract,
    type OkAnswer,
    type PortTopicEntry,
    type SimMode,
    type SimStartAnswer,
    type SimStatusAnswer,
    type Static,
    type TopicMapAnswer,
    type TSchema,
} from '@maa/protocol';
import { backendError } from './logic.js';

export type { PortTopicEntry, SimStartAnswer, SimStatusAnswer, TopicMapAnswer };

export class BackendError extends Error {
    constructor(
        message: string,
        readonly log: string[],
    ) {
        super(message);
    }
}

/**
 * A call of the backend whose answer is checked against its contract: an error status or
 * `ok: false` is a BackendError with the backend's message and log, a bad answer one naming the
 * field. The one request helper of the view's backend calls (the simulation's and the replay's).
 */
export async function call<T extends TSchema>(
    method: 'GET' | 'POST',
    url: string,
    contract: Contract<T>,
    body?: unknown,
): Promise<Static<T>> {
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
    const issues = contract.issues(json);
    if (issues.length > 0) throw new BackendError(`${method} ${url}: unexpected answer: ${formatIssues(issues)}`, []);
    return json as Static<T>;
}

/** The simulation API below a prefix (`''`: the page's origin; endpoints.ts). */
export function createSimApi(prefix: string) {
    return {
        /** `record`: the run is recorded (docs/ide.md "Record and replay"). */
        start: (app: string, platform: string, mode: SimMode, speed: number, record?: boolean): Promise<SimStartAnswer> =>
            call('POST', `${prefix}/api/sim/start`, answers.simStart, { app, platform, mode, speed, ...(record ? { record } : {}) }),
        /** The application configurations of the workspace (`GET /api/apps`). */
        apps: async (): Promise<AppInfo[]> => (await call('GET', `${prefix}/api/apps`, answers.apps)).apps,
        stop: (): Promise<OkAnswer> => call('POST', `${prefix}/api/sim/stop`, answers.ok, {}),
        status: (): Promise<SimStatusAnswer> => call('GET', `${prefix}/api/sim/status`, answers.simStatus),
        /** The port topics of a generated platform, as the generators wrote them (after a start, which generates). */
        topics: (app: string, platform: string): Promise<TopicMapAnswer> =>
            call(
                'GET',
                `${prefix}/api/sim/topics?app=${encodeURIComponent(app)}&platform=${encodeURIComponent(platform)}`,
                topicMapContract,
            ),
    };
}

export type SimApi = ReturnType<typeof createSimApi>;

/**
 * The topic map by topic: the port a topic carries (an out port's entry wins over the in ports
 * that read the same topic), for live values and input injection.
 */
export function portsByTopic(map: TopicMapAnswer): Map<string, PortTopicEntry> {
    const byTopic = new Map<string, PortTopicEntry>();
    for (const p of map.ports) {
        const known = byTopic.get(p.topic);
        if (!known || (known.direction === 'in' && p.direction === 'out')) byTopic.set(p.topic, p);
    }
    return byTopic;
}

/** The instance path of a node of `/maa/automaton_states` (`/toast_service_robot/ctrl` → `ctrl`), undefined for other nodes. */
export function instanceOfNode(map: TopicMapAnswer, node: string): string | undefined {
    const trimmed = node.replace(/\/+$/, '');
    return map.nodes.find((n) => n.node === trimmed)?.instancePath;
}
