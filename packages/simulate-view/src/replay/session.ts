/**
 * An open replay (C6): the backend starts `maa-sim replay` for a recording; over its rosbridge
 * the view loads the recording's messages into the timeline store (C5) and, whenever the store's
 * cursor moves (the time slider, playing, or a click in a panel), moves the 3D scene there
 * (`/sim/seek`, one call at a time), hands the diagram the port values and active states
 * recorded at that time and has the port table show the recorded values there.
 */
import type { DiagramLiveLayer, Disposable } from '../contracts.js';
import type { SimApi, TopicMapAnswer } from '../backend.js';
import { errorText } from '../dom.js';
import { PortMap } from '../port-map.js';
import { RosConnection, type SimServiceResponse } from '../ros/index.js';
import type { SimStatus } from '../logic.js';
import type { StatusView } from '../status-view.js';
import type { TimedMessage, TimelineStore } from '../timeline/store.js';
import type { Viewer } from '../viewer.js';
import type { ReplayApi } from './api.js';
import type { ReplayBar } from './bar.js';
import { activeStatesAt, advance, arrowDirection, diagramValuesAt, LatestOnly, replayStatusLine } from './logic.js';

/** How often playing moves the cursor (the replay server's scene follows at this rate at most). */
const PLAY_PERIOD_MS = 33;
/** Topics not loaded into the store: the clock is the messages' own time. */
const NOT_LOADED = ['/clock'];
const CONNECT_ATTEMPTS = 5;

export interface ReplayParts {
    bar: ReplayBar;
    api: ReplayApi;
    /** The simulation API (status, the port topics of the recorded platform). */
    simApi: SimApi;
    rosbridge: string;
    store: TimelineStore;
    viewer: Viewer;
    diagram: DiagramLiveLayer;
    status: StatusView;
    notify(severity: 'info' | 'warning' | 'error', message: string): void;
    /** A run is starting or running (no replay then). */
    runActive(): boolean;
    /** The port table: it lists the recording's topics and shows their values at the cursor (inspector.ts). */
    inspector?: ReplayInspector;
    /** The panels over the store (timeline/feed.ts LiveTimeline): told when a replay starts and what its platform is. */
    timeline?: {
        runStarted(): void;
        runInfo(topicMap: unknown, instanceOf: (node: string) => string | undefined): void;
    };
}

/** What a replay asks of the port table (inspector.ts Inspector). */
export interface ReplayInspector {
    showRecording(name: string, topics: readonly string[], ports: PortMap | undefined): void;
    showAt(store: TimelineStore, t: number): void;
    clear(): void;
}

/** What `/sim/replay_messages` answers (maa_sim.replay). */
interface ReplayMessages {
    success?: boolean;
    message?: string;
    start?: number;
    end?: number;
    messages?: TimedMessage[];
}

/** What is known of the recording being replayed. */
interface Opened {
    name: string;
    app?: string;
    platform?: string;
}

export class ReplayController implements Disposable {
    private conn: RosConnection | undefined;
    private ports: PortMap | undefined;
    private opened: Opened | undefined;
    private start = 0;
    private end = 0;
    private playTimer: ReturnType<typeof setInterval> | undefined;
    private lastTick = 0;
    private readonly seeker = new LatestOnly((t) => this.seekScene(t));
    private readonly subs: Disposable[] = [];
    /** Bumped by every open and close: an open overtaken by another gives up. */
    private generation = 0;

    constructor(private readonly parts: ReplayParts) {
        const { bar } = parts;
        bar.replayBtn.addEventListener('click', () => void this.open(bar.recordingSelect.value));
        bar.recordingSelect.addEventListener('focus', () => void this.refresh());
        bar.recordingSelect.addEventListener('change', () => this.render());
        bar.closeBtn.addEventListener('click', () => void this.close());
        bar.playBtn.addEventListener('click', () => (this.playTimer ? this.pause() : this.play()));
        bar.slider.addEventListener('input', () => {
            this.pause();
            parts.store.cursor = Number(bar.slider.value);
        });
        bar.slider.addEventListener('keydown', (e) => this.stepKey(e));
        this.subs.push(parts.store.onChange((what) => (what === 'cursor' ? this.showCursor() : undefined)));
    }

    /** A replay is open. */
    get active(): boolean {
        return this.opened !== undefined;
    }

    /** The scene is where the cursor is (no seek under way or pending): for tests. */
    get settled(): boolean {
        return this.seeker.idle;
    }

    /** Lists the recordings, then reattaches to a replay the backend still serves (a reloaded view). */
    async mount(): Promise<void> {
        await this.refresh();
        try {
            const st = await this.parts.simApi.status();
            if (st.running && st.replay) await this.attach({ name: st.replay, app: st.app, platform: st.platform });
        } catch {
            /* no backend session API */
        }
    }

    async refresh(): Promise<void> {
        try {
            this.parts.bar.setRecordings(await this.parts.api.recordings());
        } catch (e) {
            this.parts.bar.setRecordings([]);
            console.warn(`recordings: ${errorText(e)}`);
        }
        this.render();
    }

    /** Enables what the state allows (call when a run starts or ends). */
    render(): void {
        this.parts.bar.render(this.parts.runActive());
    }

    /** Starts a replay session of the recording and opens it. */
    async open(name: string): Promise<void> {
        if (!name || this.parts.runActive()) return;
        const { api, status, notify } = this.parts;
        this.leave();
        status.showError(undefined);
        status.set(`Opening the recording ${name}…`);
        try {
            const answer = await api.replay(name);
            await this.attach({ name, app: answer.recording.app, platform: answer.recording.platform });
        } catch (e) {
            this.leave();
            status.showError(`Replay failed: ${errorText(e)}`, 'log' in (e as object) ? ((e as { log: string[] }).log ?? []) : []);
            notify('error', `Replay of ${name} failed: ${errorText(e)}`);
            status.set('Not running');
        }
    }

    /** Closes the replay and ends its session. */
    async close(): Promise<void> {
        if (!this.opened) return;
        this.leave();
        this.parts.status.set('Replay closed');
        try {
            await this.parts.api.stop();
        } catch (e) {
            this.parts.notify('warning', `Stopping the replay: ${errorText(e)}`);
        }
    }

    /** A run starts: the backend ends the replay session itself; the view lets go of it. */
    leaveForRun(): void {
        if (this.opened) this.leave();
    }

    dispose(): void {
        this.leave();
        for (const s of this.subs.splice(0)) s.dispose();
    }

    play(): void {
        if (!this.opened || this.playTimer) return;
        const { store } = this.parts;
        if ((store.cursor ?? this.start) >= this.end) store.cursor = this.start; // from the start again
        this.lastTick = performance.now();
        this.playTimer = setInterval(() => this.playTick(), PLAY_PERIOD_MS);
        this.parts.bar.setPlaying(true);
    }

    pause(): void {
        if (this.playTimer) clearInterval(this.playTimer);
        this.playTimer = undefined;
        this.parts.bar.setPlaying(false);
    }

    /** An arrow key on the slider: the cursor goes to the next or previous recorded message (of any topic). */
    private stepKey(e: KeyboardEvent): void {
        const direction = arrowDirection(e.key);
        if (direction === undefined || !this.opened) return;
        e.preventDefault();
        this.pause();
        const { store } = this.parts;
        const next = store.adjacentTime(store.cursor ?? this.start, direction);
        if (next !== undefined) store.cursor = Math.min(this.end, Math.max(this.start, next));
    }

    private playTick(): void {
        const now = performance.now();
        const { cursor, ended } = advance(
            this.parts.store.cursor ?? this.start,
            (now - this.lastTick) / 1000,
            this.parts.bar.speed,
            this.end,
        );
        this.lastTick = now;
        this.parts.store.cursor = cursor;
        if (ended) this.pause();
    }

    /** Connects to the replay session, loads the recording into the store and shows it at its start. */
    private async attach(opened: Opened): Promise<void> {
        const generation = ++this.generation;
        const { store, viewer, bar, status } = this.parts;
        const conn = await connect(this.parts.rosbridge);
        if (generation !== this.generation) {
            conn.dispose();
            return;
        }
        this.conn = conn;
        status.set(`Loading the recording ${opened.name}…`);
        const loaded = await conn.callService<ReplayMessages>('/sim/replay_messages', { exclude: NOT_LOADED }, 120_000);
        if (generation !== this.generation) return;
        if (!loaded.success || !Array.isArray(loaded.messages)) throw new Error(loaded.message ?? 'the replay server sent no messages');
        const topicMap = await this.topicMap(opened);
        if (generation !== this.generation) return;
        const ports = topicMap ? new PortMap(topicMap) : undefined;
        this.ports = ports;
        this.opened = opened;
        this.start = loaded.start ?? 0;
        this.end = loaded.end ?? 0;
        this.parts.timeline?.runStarted();
        store.clear();
        store.addAll(loaded.messages);
        if (topicMap && ports) this.parts.timeline?.runInfo(topicMap, (node) => ports.instanceOf(node));
        this.parts.inspector?.showRecording(opened.name, store.topics(), ports);
        viewer.show();
        bar.open(opened.name, this.start, this.end);
        status.set(`Replaying ${opened.name} (${loaded.messages.length} messages, ${(this.end - this.start).toFixed(2)} s)`);
        store.cursor = this.start;
        this.render();
    }

    /** The port topics of the recorded platform (the diagram's values need them); undefined for a recording from elsewhere. */
    private async topicMap(opened: Opened): Promise<TopicMapAnswer | undefined> {
        if (!opened.app || !opened.platform) return undefined;
        try {
            return await this.parts.simApi.topics(opened.app, opened.platform);
        } catch (e) {
            this.parts.notify('warning', `The diagram shows no values of this replay: ${errorText(e)}`);
            return undefined;
        }
    }

    /** The cursor moved: the slider, the diagram and (one call at a time) the 3D scene follow. */
    private showCursor(): void {
        const t = this.parts.store.cursor;
        if (!this.opened || t === undefined) return;
        this.parts.bar.show(t, this.end);
        this.seeker.request(t);
        this.parts.inspector?.showAt(this.parts.store, t);
        const ports = this.ports;
        if (!ports) return;
        const { diagram, store } = this.parts;
        try {
            diagram.setLiveValues(diagramValuesAt(store, ports, t));
            diagram.setActiveStates(activeStatesAt(store, ports, t));
        } catch {
            /* the diagram may be gone */
        }
    }

    /** Moves the 3D scene to `t`; the status line then says what the scene shows there (the toast). */
    private async seekScene(t: number): Promise<void> {
        const conn = this.conn;
        if (!conn) return;
        const res = await conn.callService<SimServiceResponse>('/sim/seek', { time: t }, 10_000);
        if (conn !== this.conn || !this.opened) return;
        if (res.success === false) this.parts.notify('warning', `/sim/seek: ${res.message ?? 'failed'}`);
        else if (res.status && typeof res.status === 'object')
            this.parts.status.set(replayStatusLine(this.opened.name, res.status as SimStatus));
    }

    /** Lets go of the replay: the connection, the time bar, the store's data, the diagram's values, the 3D view. */
    private leave(): void {
        this.generation++;
        this.pause();
        const was = this.opened;
        this.opened = undefined;
        this.conn?.dispose();
        this.conn = undefined;
        this.ports = undefined;
        this.parts.bar.close();
        if (!was) return;
        this.parts.store.clear();
        this.parts.inspector?.clear();
        this.parts.viewer.hide();
        try {
            this.parts.diagram.setLiveValues(new Map());
            this.parts.diagram.setActiveStates(new Map());
        } catch {
            /* the diagram may be gone */
        }
        this.render();
    }
}

/** A connection to the replay's rosbridge, retried while the proxied endpoint comes up. */
async function connect(url: string): Promise<RosConnection> {
    for (let attempt = 1; ; attempt++) {
        const conn = new RosConnection(url);
        try {
            await conn.whenConnected(10_000);
            return conn;
        } catch (e) {
            conn.dispose();
            if (attempt >= CONNECT_ATTEMPTS) throw e;
            await new Promise((r) => setTimeout(r, 500 * attempt));
        }
    }
}
