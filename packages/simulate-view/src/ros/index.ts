/**
 * A small promise-based wrapper around roslib 2.x for the simulate panel: one connection to the
 * proxied rosbridge, service calls, topic listing, subscriptions and publishing.
 */
import { Ros, Service, Topic } from 'roslib';
import type { Disposable } from '../contracts.js';

export { rosbridgeUrl } from './url.js';

export interface TopicInfo {
    topic: string;
    type: string;
}

/** The answer of the simulator's control services (docs/simulation.md). */
export interface SimServiceResponse {
    success?: boolean;
    message?: string;
    status?: unknown;
}

/** One typedef of rosapi's `message_details` answer. */
export interface MessageTypedef {
    type?: string;
    fieldnames?: string[];
    fieldtypes?: string[];
    constnames?: string[];
    constvalues?: string[];
}

export type ConnectionState = 'connecting' | 'connected' | 'closed' | 'error';

export class RosConnection implements Disposable {
    readonly ros: Ros;
    private state: ConnectionState = 'connecting';
    private readonly listeners = new Set<(s: ConnectionState, detail?: string) => void>();
    private readonly topics = new Map<string, Topic<unknown>>();
    private readonly typeCache = new Map<string, string>();
    private disposed = false;

    constructor(readonly url: string) {
        this.ros = new Ros({});
        this.ros.on('connection', () => this.setState('connected'));
        this.ros.on('close', () => this.setState('closed'));
        this.ros.on('error', (ev: unknown) => this.setState('error', describeEvent(ev)));
        this.ros.connect(url).catch((e: unknown) => this.setState('error', String(e)));
    }

    get connectionState(): ConnectionState {
        return this.state;
    }

    onState(listener: (s: ConnectionState, detail?: string) => void): Disposable {
        this.listeners.add(listener);
        return { dispose: () => this.listeners.delete(listener) };
    }

    /** Resolves once connected; rejects on error/close or after `timeoutMs`. */
    whenConnected(timeoutMs = 10_000): Promise<void> {
        if (this.state === 'connected') return Promise.resolve();
        return new Promise((resolve, reject) => {
            const timer = setTimeout(() => {
                sub.dispose();
                reject(new Error(`rosbridge at ${this.url} did not answer within ${timeoutMs / 1000} s`));
            }, timeoutMs);
            const sub = this.onState((s, detail) => {
                if (s === 'connected') {
                    clearTimeout(timer);
                    sub.dispose();
                    resolve();
                } else if (s === 'error' || s === 'closed') {
                    clearTimeout(timer);
                    sub.dispose();
                    reject(new Error(`rosbridge at ${this.url}: ${detail ?? s}`));
                }
            });
        });
    }

    private setState(s: ConnectionState, detail?: string): void {
        if (this.disposed) return;
        this.state = s;
        for (const l of [...this.listeners]) l(s, detail);
    }

    /** Calls a service; rejects with the server's message on failure or after `timeoutMs`. */
    callService<TRes = SimServiceResponse>(name: string, args: Record<string, unknown> = {}, timeoutMs = 10_000): Promise<TRes> {
        const service = new Service<Record<string, unknown>, TRes>({ ros: this.ros, name, serviceType: '' });
        return new Promise<TRes>((resolve, reject) => {
            const timer = setTimeout(() => reject(new Error(`${name}: no answer within ${timeoutMs / 1000} s`)), timeoutMs);
            service.callService(
                args,
                (res) => {
                    clearTimeout(timer);
                    resolve(res);
                },
                (err) => {
                    clearTimeout(timer);
                    reject(new Error(`${name}: ${err}`));
                },
            );
        });
    }

    /**
     * The definition of a message type (`rosapi/message_details`): its typedefs, the message's
     * own first; each with `fieldnames` and, where rosapi reports them, `constnames`/`constvalues`.
     */
    async messageDetails(type: string, timeoutMs = 5000): Promise<MessageTypedef[]> {
        const res = await this.callService<{ typedefs?: MessageTypedef[] }>('/rosapi/message_details', { type }, timeoutMs);
        return Array.isArray(res?.typedefs) ? res.typedefs : [];
    }

    /** Every topic with its type (`rosapi/topics`). */
    listTopics(): Promise<TopicInfo[]> {
        return new Promise((resolve, reject) => {
            this.ros.getTopics(
                (res) => {
                    const topics = res.topics ?? [];
                    const types = res.types ?? [];
                    const list = topics.map((topic, i) => ({ topic, type: types[i] ?? '' }));
                    for (const t of list) if (t.type) this.typeCache.set(t.topic, t.type);
                    resolve(list);
                },
                (err) => reject(new Error(`rosapi/topics: ${err}`)),
            );
        });
    }

    /** A topic's type (`rosapi/topic_type`), cached; empty when unknown. */
    topicType(topic: string): Promise<string> {
        const cached = this.typeCache.get(topic);
        if (cached) return Promise.resolve(cached);
        return new Promise((resolve, reject) => {
            this.ros.getTopicType(
                topic,
                (type) => {
                    if (type) this.typeCache.set(topic, type);
                    resolve(type);
                },
                (err) => reject(new Error(`rosapi/topic_type ${topic}: ${err}`)),
            );
        });
    }

    /** Subscribes a topic (type optional when the server knows it); `throttleMs` between messages. */
    subscribe(topic: string, type: string | undefined, handler: (msg: unknown) => void, throttleMs = 0): Disposable {
        const t = new Topic<unknown>({
            ros: this.ros,
            name: topic,
            messageType: type ?? this.typeCache.get(topic) ?? '',
            throttle_rate: throttleMs,
            queue_length: 1,
        });
        t.subscribe(handler);
        let done = false;
        return {
            dispose: () => {
                if (done) return;
                done = true;
                try {
                    t.unsubscribe(handler);
                } catch {
                    /* connection gone */
                }
            },
        };
    }

    /** Publishes one message on a topic with the given type (advertised on first use). */
    publish(topic: string, type: string, message: Record<string, unknown>): void {
        let t = this.topics.get(topic);
        if (!t || t.messageType !== type) {
            t = new Topic<unknown>({ ros: this.ros, name: topic, messageType: type });
            t.advertise();
            this.topics.set(topic, t);
        }
        t.publish(message);
    }

    dispose(): void {
        if (this.disposed) return;
        for (const t of this.topics.values()) {
            try {
                t.unadvertise();
            } catch {
                /* ignore */
            }
        }
        this.topics.clear();
        this.disposed = true;
        this.listeners.clear();
        try {
            this.ros.close();
        } catch {
            /* ignore */
        }
    }
}

function describeEvent(ev: unknown): string {
    if (ev && typeof ev === 'object' && 'message' in ev) return String((ev as { message: unknown }).message);
    return 'connection error';
}
