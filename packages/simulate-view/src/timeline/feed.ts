/**
 * A live run's feed of the timeline store: subscribes the run's port topics, the simulator's
 * platform topics and the `/maa/` event topics, unthrottled, and adds each message stamped with
 * the latest `/clock` time (rosbridge delivers a connection's messages in order, so that is the
 * period they belong to). Heavy topics (images, point clouds, the scene's poses) stay out.
 */
import { SIMULATOR_TOPICS } from '@maa/protocol';
import type { Disposable } from '../contracts.js';
import { clockSeconds } from '../format.js';
import type { RosConnection, TopicInfo } from '../ros/index.js';
import type { TimelineStore } from './store.js';

const PLATFORM_TOPICS = new Set(SIMULATOR_TOPICS.map((t) => t.name).filter((n) => n !== '/clock'));
const HEAVY_TYPES = /\/(Image|CompressedImage|PointCloud2?|LaserScan|OccupancyGrid)$/;

/** Whether the feed records a topic: a port's, a platform topic, or one of the `/maa/` topics (states, transitions, program steps). */
export function feedsTopic(info: TopicInfo, isPortTopic: (topic: string) => boolean): boolean {
    if (HEAVY_TYPES.test(info.type)) return false;
    return isPortTopic(info.topic) || PLATFORM_TOPICS.has(info.topic) || info.topic.startsWith('/maa/');
}

export class TimelineFeed implements Disposable {
    private clock: number | undefined;
    private readonly subs = new Map<string, Disposable>();
    private readonly clockSub: Disposable;

    constructor(
        private readonly conn: RosConnection,
        private readonly store: TimelineStore,
    ) {
        this.clockSub = conn.subscribe('/clock', 'rosgraph_msgs/msg/Clock', (m) => {
            const t = clockSeconds(m);
            if (t !== undefined) this.clock = t;
        });
    }

    /** Subscribes the topics of `list` the feed records and does not record yet. */
    follow(list: readonly TopicInfo[], isPortTopic: (topic: string) => boolean): void {
        for (const info of list) {
            if (this.subs.has(info.topic) || !feedsTopic(info, isPortTopic)) continue;
            const topic = info.topic;
            this.subs.set(
                topic,
                this.conn.subscribe(topic, info.type || undefined, (message) => {
                    // before the first /clock there is no simulated time to file it under
                    if (this.clock !== undefined) this.store.add({ t: this.clock, topic, message });
                }),
            );
        }
    }

    /** The simulation was reset: messages wait for the next `/clock` (the old time no longer holds). */
    restart(): void {
        this.clock = undefined;
    }

    dispose(): void {
        this.clockSub.dispose();
        for (const s of this.subs.values()) s.dispose();
        this.subs.clear();
    }
}

/** What a live run gives the session's timeline (index.ts wires it to the store and the panels). */
export interface LiveTimeline {
    readonly store: TimelineStore;
    /** A run starts: the last session's messages and selection go. */
    runStarted(): void;
    /** The backend's topic map arrived: the automata table (raw, parsed by the panels) and the node names. */
    runInfo(topicMap: unknown, instanceOf: (node: string) => string | undefined): void;
}
