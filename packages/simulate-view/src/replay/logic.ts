/**
 * What a replay shows at the time cursor, computed from the timeline store (C5): the diagram's
 * port values and active states, and the playback clock that moves the cursor. Pure (no DOM).
 */
import { AUTOMATON_STATES_TOPIC } from '@maa/protocol';
import { formatRosValue } from '../format.js';
import type { SimStatus } from '../logic.js';
import type { PortMap } from '../port-map.js';
import { parseAutomatonStates } from '../states.js';
import type { TimedMessage, TimelineStore } from '../timeline/store.js';

/** The length of a value on the diagram (as a live run's, inspector.ts). */
const DIAGRAM_VALUE_LENGTH = 28;

/** The port values at `t` by diagram port path: each port topic's last message at or before `t`. */
export function diagramValuesAt(store: TimelineStore, ports: PortMap, t: number): Map<string, string> {
    const values = new Map<string, string>();
    for (const topic of store.topics()) {
        const paths = ports.diagramPaths(topic);
        if (paths.length === 0) continue;
        const last = store.latestAt(topic, t);
        if (!last) continue;
        const text = formatRosValue(last.message, DIAGRAM_VALUE_LENGTH);
        for (const path of paths) values.set(path, text);
    }
    return values;
}

/**
 * The active state of each automaton at `t` by instance path. A message may name only some nodes
 * (ROS 2: each node publishes its own at a switch), so the messages up to `t` are read newest
 * first until every node of the recording is known.
 */
export function activeStatesAt(store: TimelineStore, ports: PortMap, t: number): Map<string, string> {
    const start = store.start;
    if (start === undefined) return new Map();
    const messages: TimedMessage[] = store.range(AUTOMATON_STATES_TOPIC, start, t);
    const states = new Map<string, string>();
    const nodes = allNodes(store);
    for (let i = messages.length - 1; i >= 0; i--) {
        for (const [inst, state] of parseAutomatonStates(messages[i]!.message, (node) => ports.instanceOf(node))) {
            if (!states.has(inst)) states.set(inst, state);
        }
        if (states.size >= nodes) break;
    }
    return states;
}

/** The number of nodes the states messages name, by store; counted again when the topic's messages change. */
const nodeCounts = new WeakMap<TimelineStore, { messages: number; nodes: number }>();

/** How many nodes the store's automaton states name in all (the walk above stops once it knows them all). */
function allNodes(store: TimelineStore): number {
    const messages = store.count(AUTOMATON_STATES_TOPIC);
    const known = nodeCounts.get(store);
    if (known?.messages === messages) return known.nodes;
    const nodes = new Set<string>();
    for (const m of store.range(AUTOMATON_STATES_TOPIC, Number.NEGATIVE_INFINITY, Number.POSITIVE_INFINITY)) {
        const data = (m.message as { data?: unknown } | undefined)?.data;
        if (typeof data !== 'string') continue;
        try {
            const parsed: unknown = JSON.parse(data);
            if (parsed && typeof parsed === 'object') for (const node of Object.keys(parsed)) nodes.add(node);
        } catch {
            /* not JSON: names no node */
        }
    }
    nodeCounts.set(store, { messages, nodes: nodes.size });
    return nodes.size;
}

/** The cursor after `wallSeconds` of playing at `speed` from `cursor`, and whether the end was reached. */
export function advance(cursor: number, wallSeconds: number, speed: number, end: number): { cursor: number; ended: boolean } {
    const next = cursor + Math.max(0, wallSeconds) * speed;
    return next >= end ? { cursor: end, ended: true } : { cursor: next, ended: false };
}

/** The status line of a replay: `replay TR-….mcap · t 12.34 s · toast 1.02 on plate` (from the replay server's status). */
export function replayStatusLine(name: string, status: SimStatus): string {
    const parts = [`replay ${name}`];
    if (typeof status.time === 'number') parts.push(`t ${status.time.toFixed(2)} s`);
    if (typeof status.toast_level === 'number')
        parts.push(`toast ${status.toast_level.toFixed(2)}${status.toast_on_plate ? ' on plate' : ''}`);
    return parts.join(' · ');
}

/** The direction a key steps the replay's cursor in: → and ↑ to the next recorded message, ← and ↓ to the previous. */
export function arrowDirection(key: string): 1 | -1 | undefined {
    if (key === 'ArrowRight' || key === 'ArrowUp') return 1;
    if (key === 'ArrowLeft' || key === 'ArrowDown') return -1;
    return undefined;
}

/** `12.34 s / 30.00 s` */
export function timeLabel(t: number | undefined, end: number | undefined): string {
    const f = (v: number | undefined): string => (v === undefined ? '–' : `${v.toFixed(2)} s`);
    return `${f(t)} / ${f(end)}`;
}

/**
 * Calls `seek` with the newest time asked for, one call at a time: while a call is under way
 * only the latest request waits (a slider dragged faster than the replay server answers skips
 * the times in between, never queues them).
 */
export class LatestOnly {
    private running = false;
    private pending: number | undefined;

    constructor(private readonly seek: (t: number) => Promise<unknown>) {}

    request(t: number): void {
        this.pending = t;
        if (!this.running) void this.pump();
    }

    /** Settles once no call is under way or pending (tests, the e2e). */
    get idle(): boolean {
        return !this.running && this.pending === undefined;
    }

    private async pump(): Promise<void> {
        this.running = true;
        try {
            while (this.pending !== undefined) {
                const t = this.pending;
                this.pending = undefined;
                try {
                    await this.seek(t);
                } catch {
                    /* the next request tries again; the view says what failed */
                }
            }
        } finally {
            this.running = false;
        }
    }
}
