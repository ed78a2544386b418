/**
 * The timeline store: every message a session saw, by topic and simulated time, and the time
 * cursor the panels share. One store per session of the simulate view: a live run adds what it
 * receives (stamped with the latest `/clock`), a replay fills it from a recording and moves the
 * cursor. The panels (plots, state timeline, raw messages, log) and the diagram's live layer read
 * it at the cursor, or at the newest data while the cursor is `undefined` (following live). Pure
 * (no DOM).
 */
import type { Disposable } from '../contracts.js';

export interface TimedMessage {
    /** Simulated seconds. */
    t: number;
    topic: string;
    /** The message as rosbridge delivers it (JSON). */
    message: unknown;
}

export type TimelineChange = 'data' | 'cursor';

export interface TimelineStoreOptions {
    /**
     * The most messages kept per topic; beyond it the oldest tenth is dropped, so a long live
     * run cannot grow the page without bound. Default 100,000.
     */
    maxPerTopic?: number;
}

const DEFAULT_MAX_PER_TOPIC = 100_000;

/** Index of the first element whose `t` is greater than `t` (the insertion point after equals). */
function upperBound(list: readonly TimedMessage[], t: number): number {
    let lo = 0;
    let hi = list.length;
    while (lo < hi) {
        const mid = (lo + hi) >>> 1;
        if (list[mid]!.t <= t) lo = mid + 1;
        else hi = mid;
    }
    return lo;
}

/** Index of the first element whose `t` is at least `t`. */
function lowerBound(list: readonly TimedMessage[], t: number): number {
    let lo = 0;
    let hi = list.length;
    while (lo < hi) {
        const mid = (lo + hi) >>> 1;
        if (list[mid]!.t < t) lo = mid + 1;
        else hi = mid;
    }
    return lo;
}

export class TimelineStore {
    private readonly byTopic = new Map<string, TimedMessage[]>();
    private readonly listeners = new Set<(what: TimelineChange) => void>();
    private readonly maxPerTopic: number;
    private first: number | undefined;
    private last: number | undefined;
    private cursorTime: number | undefined;
    private gen = 0;

    constructor(options: TimelineStoreOptions = {}) {
        const max = options.maxPerTopic ?? DEFAULT_MAX_PER_TOPIC;
        if (!(max >= 1)) throw new Error('maxPerTopic must be at least 1');
        this.maxPerTopic = max;
    }

    /** The earliest time of any message kept, `undefined` when empty. */
    get start(): number | undefined {
        return this.first;
    }

    /** The latest time of any message kept, `undefined` when empty. */
    get end(): number | undefined {
        return this.last;
    }

    /** The shared time cursor; `undefined` follows the newest data (live). */
    get cursor(): number | undefined {
        return this.cursorTime;
    }

    set cursor(t: number | undefined) {
        if (t !== undefined && !Number.isFinite(t)) return;
        if (t === this.cursorTime) return;
        this.cursorTime = t;
        this.emit('cursor');
    }

    /**
     * Changes when messages already stored moved (cleared, an older message inserted before
     * newer ones, the oldest dropped): a reader that keeps a position into a topic
     * (`since`) starts over then. Appending at the end leaves it as it is.
     */
    get generation(): number {
        return this.gen;
    }

    /** The messages of `topic` from the `index`-th on (for readers that follow appends; see `generation`). */
    since(topic: string, index: number): TimedMessage[] {
        return this.byTopic.get(topic)?.slice(Math.max(0, index)) ?? [];
    }

    /** The time the panels show: the cursor, else the newest data. */
    get shownTime(): number | undefined {
        return this.cursorTime ?? this.last;
    }

    /** Appends a message (a message older than its topic's newest is inserted in time order). */
    add(m: TimedMessage): void {
        if (this.insert(m)) this.emit('data');
    }

    /** Adds many messages with one change notification (a replay's recording). */
    addAll(ms: Iterable<TimedMessage>): void {
        let any = false;
        for (const m of ms) any = this.insert(m) || any;
        if (any) this.emit('data');
    }

    /** Removes every message and the cursor (a new session). */
    clear(): void {
        const had = this.byTopic.size > 0;
        const hadCursor = this.cursorTime !== undefined;
        this.byTopic.clear();
        this.first = undefined;
        this.last = undefined;
        this.cursorTime = undefined;
        this.gen++;
        if (had) this.emit('data');
        if (hadCursor) this.emit('cursor');
    }

    /** The last message of `topic` with time ≤ `t`. */
    latestAt(topic: string, t: number): TimedMessage | undefined {
        const list = this.byTopic.get(topic);
        if (!list) return undefined;
        const i = upperBound(list, t);
        return i > 0 ? list[i - 1] : undefined;
    }

    /** The messages of `topic` with `t0` ≤ time ≤ `t1`, oldest first. */
    range(topic: string, t0: number, t1: number): TimedMessage[] {
        const list = this.byTopic.get(topic);
        if (!list || t1 < t0) return [];
        return list.slice(lowerBound(list, t0), upperBound(list, t1));
    }

    /**
     * The messages of `topic` around `t`: up to `before` messages before the last one at or
     * before `t`, that one, and up to `after` later ones, oldest first (a window: the topic's
     * whole history is not copied).
     */
    around(topic: string, t: number, before: number, after: number): TimedMessage[] {
        const list = this.byTopic.get(topic);
        if (!list) return [];
        const i = upperBound(list, t); // list[i - 1] is the one in effect at t
        return list.slice(Math.max(0, i - 1 - Math.max(0, before)), i + Math.max(0, after));
    }

    /**
     * The time of the nearest message of any topic after `t` (`direction` 1) or before it (-1),
     * `undefined` when there is none: a replay's arrow keys step from event to event.
     */
    adjacentTime(t: number, direction: 1 | -1): number | undefined {
        let best: number | undefined;
        for (const list of this.byTopic.values()) {
            const candidate = direction > 0 ? list[upperBound(list, t)]?.t : list[lowerBound(list, t) - 1]?.t;
            if (candidate === undefined) continue;
            if (best === undefined || (direction > 0 ? candidate < best : candidate > best)) best = candidate;
        }
        return best;
    }

    /** How many messages of `topic` are kept. */
    count(topic: string): number {
        return this.byTopic.get(topic)?.length ?? 0;
    }

    /** The topics with messages, sorted. */
    topics(): string[] {
        return [...this.byTopic.keys()].sort();
    }

    onChange(listener: (what: TimelineChange) => void): Disposable {
        this.listeners.add(listener);
        return { dispose: () => this.listeners.delete(listener) };
    }

    /** Stores one message; false when it is not one (no topic, no finite time). */
    private insert(m: TimedMessage): boolean {
        if (!m || typeof m.topic !== 'string' || m.topic.length === 0 || !Number.isFinite(m.t)) return false;
        let list = this.byTopic.get(m.topic);
        if (!list) {
            list = [];
            this.byTopic.set(m.topic, list);
        }
        const entry: TimedMessage = { t: m.t, topic: m.topic, message: m.message };
        if (list.length === 0 || list[list.length - 1]!.t <= m.t) list.push(entry);
        else {
            list.splice(upperBound(list, m.t), 0, entry);
            this.gen++;
        }
        if (list.length > this.maxPerTopic) {
            // a tenth at a time: dropping one per message would shift the whole array each time
            list.splice(0, list.length - this.maxPerTopic + Math.floor(this.maxPerTopic / 10));
            this.gen++;
            this.recomputeStart();
        } else if (this.first === undefined || m.t < this.first) this.first = m.t;
        if (this.last === undefined || m.t > this.last) this.last = m.t;
        return true;
    }

    private recomputeStart(): void {
        let min: number | undefined;
        for (const list of this.byTopic.values()) {
            const t = list[0]?.t;
            if (t !== undefined && (min === undefined || t < min)) min = t;
        }
        this.first = min;
    }

    private emit(what: TimelineChange): void {
        for (const l of [...this.listeners]) l(what);
    }
}
