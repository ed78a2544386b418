/**
 * The panel's connection to a running simulator: rosbridge (retried while the proxied endpoint
 * comes up), the clock, the active automaton states and modes, the simulator's status, the
 * topic list for the inspector, and the 10 Hz hand-over of values and states to the diagram.
 * One instance per attached run; `dispose` ends it and clears what it showed.
 */
import { AUTOMATON_STATES_TOPIC } from '@maa/protocol';
import type { DiagramLiveLayer, Disposable } from './contracts.js';
import { RosConnection, type SimServiceResponse, type TopicInfo } from './ros/index.js';
import { errorText } from './dom.js';
import { clockSeconds } from './format.js';
import type { Inspector } from './inspector.js';
import { statusLine, unwrapStatus, type SimStatus } from './logic.js';
import type { SimApi } from './backend.js';
import { PortMap } from './port-map.js';
import { parseAutomatonStates } from './states.js';
import type { StatusView } from './status-view.js';
import { TimelineFeed, type LiveTimeline } from './timeline/feed.js';
import { activeStatesAt, diagramValuesAt } from './replay/logic.js';

const DIAGRAM_PERIOD_MS = 100; // 10 Hz
const STATUS_PERIOD_MS = 1000;
const TOPICS_PERIOD_MS = 3000;
const CONNECT_ATTEMPTS = 4;

export interface LiveRunHost {
    /** The running application (`.arcapp` path) and platform: the backend serves their port topics. */
    app: string;
    platform: string;
    /** The backend's simulation API and the rosbridge URL (endpoints.ts). */
    api: SimApi;
    rosbridge: string;
    diagram: DiagramLiveLayer;
    inspector: Inspector;
    status: StatusView;
    /** The session still runs (the status line then follows the simulator). */
    running(): boolean;
    /** The connection or the simulator's status changed: the controls render again. */
    changed(): void;
    notify(severity: 'info' | 'warning' | 'error', message: string): void;
    /** The session's timeline: the run's messages go to its store (panels, docs/ide.md "Panels"). */
    timeline?: LiveTimeline;
}

export class LiveRun implements Disposable {
    private ros: RosConnection | undefined;
    private clock: number | undefined;
    /** The port topics, once the backend served them. */
    private ports: PortMap | undefined;
    private portsLoading = false;
    /** The last message of `/maa/automaton_states` (states publish at a switch only on ROS 2). */
    private statesMessage: unknown;
    private simStatus: SimStatus = {};
    private activeStates = new Map<string, string>();
    private statesDirty = false;
    private disposed = false;
    private readonly subs: Disposable[] = [];
    private feed: TimelineFeed | undefined;
    /** The cursor time the diagram shows (`undefined`: the newest values). */
    private shownCursor: number | undefined;
    private readonly timers: ReturnType<typeof setInterval>[] = [];

    constructor(private readonly host: LiveRunHost) {
        host.timeline?.runStarted();
        const url = host.rosbridge;
        this.connect(url, 1).catch((e: unknown) => {
            if (!this.disposed) host.status.showError(`Could not connect to the simulator's rosbridge at ${url}: ${errorText(e)}`);
        });
        this.timers.push(setInterval(() => void this.pollStatus(), STATUS_PERIOD_MS));
        this.timers.push(setInterval(() => void this.refreshTopics(), TOPICS_PERIOD_MS));
        this.timers.push(setInterval(() => this.tick(), DIAGRAM_PERIOD_MS));
    }

    /** A rosbridge connection exists (the run controls work). */
    get connected(): boolean {
        return this.ros !== undefined;
    }

    /** The simulation time from `/clock`, `undefined` before the first message. */
    get clockSeconds(): number | undefined {
        return this.clock;
    }

    get paused(): boolean {
        return !!this.simStatus.paused;
    }

    /** Calls a simulator service (`/sim/pause`, `/sim/step`, …, docs/simulation.md) and shows the new status. */
    async control(service: string, args: Record<string, unknown> = {}): Promise<void> {
        const conn = this.ros;
        if (!conn) return;
        try {
            const res = await conn.callService<SimServiceResponse>(service, args, service === '/sim/reset' ? 60_000 : 10_000);
            if (res && res.success === false) this.host.notify('warning', `${service}: ${res.message ?? 'failed'}`);
            // a reset starts the clock at 0 again: the answer's time counts until /clock sends the next one
            if (service === '/sim/reset' && res?.success !== false) this.clock = undefined;
            if (service === '/sim/reset' && res?.success !== false) {
                // the timeline starts over with the simulation's time
                this.feed?.restart();
                this.host.timeline?.runStarted();
            }
            const st = res?.status;
            if (st && typeof st === 'object') this.simStatus = unwrapStatus(st);
            await this.pollStatus();
        } catch (e) {
            this.host.notify('error', errorText(e));
        }
    }

    /** Shows new inspector values and hands values and states to the diagram (`force`: values even when unchanged). */
    tick(force = false): void {
        const { inspector, diagram } = this.host;
        const valuesChanged = inspector.flush() || force;
        if (this.showCursor()) return;
        if (valuesChanged) diagram.setLiveValues(inspector.diagramValues());
        if (this.statesDirty) {
            this.statesDirty = false;
            diagram.setActiveStates(this.activeStates);
        }
        if (this.clock !== undefined && this.host.running() && this.ros?.connectionState === 'connected')
            this.host.status.set(statusLine(this.simStatus, this.clock));
    }

    /**
     * While the panels' time cursor is set, the diagram shows the values and states at the cursor
     * (from the timeline store) instead of the newest; true then. When the cursor is cleared, the
     * newest values and states are sent again.
     */
    private showCursor(): boolean {
        const cursor = this.host.timeline?.store.cursor;
        const ports = this.ports;
        if (cursor === undefined || !ports || !this.host.timeline) {
            if (this.shownCursor !== undefined) {
                this.shownCursor = undefined;
                this.statesDirty = true;
                this.host.diagram.setLiveValues(this.host.inspector.diagramValues());
            }
            return false;
        }
        if (cursor !== this.shownCursor) {
            const { store } = this.host.timeline;
            this.shownCursor = cursor;
            this.host.diagram.setLiveValues(diagramValuesAt(store, ports, cursor));
            this.host.diagram.setActiveStates(activeStatesAt(store, ports, cursor));
        }
        return true;
    }

    /**
     * Disconnects and clears the diagram's live decorations; the inspector keeps the run's last
     * values (the controller marks them as the last run's, and clears them when a run starts).
     */
    dispose(): void {
        if (this.disposed) return;
        this.disposed = true;
        for (const t of this.timers.splice(0)) clearInterval(t);
        for (const s of this.subs.splice(0)) s.dispose();
        this.feed?.dispose();
        this.feed = undefined;
        this.ros?.dispose();
        this.ros = undefined;
        try {
            this.host.diagram.setLiveValues(new Map());
            this.host.diagram.setActiveStates(new Map());
        } catch {
            /* the diagram may be gone */
        }
    }

    /** Connects, retrying a few times: the proxied endpoint may need a moment after a start. */
    private async connect(url: string, attempt: number): Promise<void> {
        const conn = new RosConnection(url);
        this.ros = conn;
        this.host.changed();
        try {
            await conn.whenConnected(10_000);
        } catch (e) {
            conn.dispose();
            if (this.ros === conn) this.ros = undefined;
            if (this.disposed) return;
            if (attempt >= CONNECT_ATTEMPTS) throw e;
            this.host.status.set(`Connecting to the simulator (attempt ${attempt + 1})…`);
            await new Promise((r) => setTimeout(r, 1000 * attempt));
            if (!this.disposed) await this.connect(url, attempt + 1);
            return;
        }
        if (this.disposed) {
            conn.dispose();
            return;
        }
        this.host.status.set('Connected');
        this.host.inspector.connect(conn);
        this.host.changed();
        this.subscribe(conn);
        if (this.host.timeline) this.feed = new TimelineFeed(conn, this.host.timeline.store);
        void this.refreshTopics();
        void this.pollStatus();
    }

    private subscribe(conn: RosConnection): void {
        this.subs.push(
            conn.onState((s, detail) => {
                if ((s === 'error' || s === 'closed') && this.host.running() && !this.disposed)
                    this.host.status.set(`rosbridge ${s}${detail ? `: ${detail}` : ''}`);
            }),
            conn.subscribe(
                '/clock',
                'rosgraph_msgs/msg/Clock',
                (m) => {
                    const t = clockSeconds(m);
                    if (t !== undefined) this.clock = t;
                },
                100,
            ),
            conn.subscribe(
                AUTOMATON_STATES_TOPIC,
                'std_msgs/msg/String',
                (m) => {
                    this.statesMessage = m;
                    this.mapStates();
                },
                DIAGRAM_PERIOD_MS,
            ),
        );
    }

    private async pollStatus(): Promise<void> {
        const conn = this.ros;
        if (conn?.connectionState !== 'connected') return;
        try {
            this.simStatus = unwrapStatus(await conn.callService('/sim/get_status', {}, 5000));
            if (this.disposed) return;
            this.host.status.set(statusLine(this.simStatus, this.clock));
            this.host.changed();
        } catch {
            if (this.clock !== undefined && !this.disposed) this.host.status.set(statusLine(this.simStatus, this.clock));
        }
    }

    private async refreshTopics(): Promise<void> {
        const conn = this.ros;
        if (conn?.connectionState !== 'connected') return;
        let list: TopicInfo[];
        try {
            list = await conn.listTopics();
        } catch {
            return;
        }
        const ports = this.ports ?? (await this.loadPorts());
        if (conn !== this.ros || !ports) return;
        this.host.inspector.update(list, ports);
        this.feed?.follow(list, (topic) => ports.portOf(topic) !== undefined);
    }

    /** The last `/maa/automaton_states` message by instance path, once the port map is there. */
    private mapStates(): void {
        const ports = this.ports;
        if (!ports || this.statesMessage === undefined || this.disposed) return;
        this.activeStates = parseAutomatonStates(this.statesMessage, (node) => ports.instanceOf(node));
        this.statesDirty = true;
    }

    /** Asks the backend for the port topics (once they arrived, they stay for the run); `undefined` until then. */
    private async loadPorts(): Promise<PortMap | undefined> {
        if (this.portsLoading) return undefined;
        this.portsLoading = true;
        try {
            const answer = await this.host.api.topics(this.host.app, this.host.platform);
            const ports = new PortMap(answer);
            this.ports = ports;
            this.mapStates(); // states that arrived before the map
            if (!this.disposed) this.host.timeline?.runInfo(answer, (node) => ports.instanceOf(node));
        } catch (e) {
            // asked again at the next topic refresh
            console.warn(`port topics of ${this.host.app} on ${this.host.platform}: ${errorText(e)}`);
        } finally {
            this.portsLoading = false;
        }
        return this.disposed ? undefined : this.ports;
    }
}
