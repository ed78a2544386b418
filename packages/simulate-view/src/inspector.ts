/**
 * The port inspector: a row per topic of the run (ports first, platform topics on request), a
 * filter, the live value of each and, for watched rows, a plot. It decides which topics are
 * subscribed and hands the port values to the diagram. When the run ends the rows stay with their
 * last values, marked as the last run's ({@link Inspector.freeze}), until the next run starts.
 * During a replay the rows are the recording's topics and show the recorded values at the time
 * cursor ({@link Inspector.showRecording}, {@link Inspector.showAt}).
 */
import type { RosConnection, TopicInfo } from './ros/index.js';
import { el } from './dom.js';
import { EnumLiterals } from './enums.js';
import { formatRosValue, isEnumMessage } from './format.js';
import { inject } from './injection.js';
import { InspectorRow } from './inspector-row.js';
import type { PortMap } from './port-map.js';
import type { TimelineStore } from './timeline/store.js';

/** Unwatched topics arrive at most this often (the diagram's rate, 10 Hz). */
export const THROTTLE_MS = 100;
/** Topics the inspector does not list: the states go to the diagram, the clock to the status line. */
const HIDDEN_TOPICS = [/^\/maa\/automaton_states$/, /^\/clock$/, /^\/rosout/, /^\/parameter_events/];

export interface InspectorHost {
    /** The time of a sample: the simulation clock, else wall-clock seconds. */
    sampleTime(): number;
    /** The watch boxes or "all values on diagram" changed: the diagram's values are due now. */
    valuesChanged(): void;
    notify(severity: 'info' | 'warning' | 'error', message: string): void;
}

export class Inspector {
    readonly element: HTMLElement;
    private readonly filterInput = el('input', {
        type: 'search',
        placeholder: 'Filter ports…',
        class: 'maa-inspector-filter',
        'data-testid': 'port-filter',
    });
    private readonly allOnDiagram = el('input', { type: 'checkbox', 'data-testid': 'values-all' });
    private readonly showPlatform = el('input', { type: 'checkbox', 'data-testid': 'show-platform-topics' });
    private readonly tbody = el('tbody');
    private readonly empty = el('div', { class: 'maa-inspector-empty' }, 'Port topics appear here during a run.');
    /** Says that the rows are the last run's (hidden during a run). */
    private readonly staleNote = el('div', { class: 'maa-inspector-stale-note', 'data-testid': 'port-stale', hidden: '' });
    /** The run is over: the rows keep their last values, nothing is subscribed or updated. */
    private frozen = false;
    /** The recording whose values the rows show (a replay), `undefined` otherwise. */
    private recording: string | undefined;
    private readonly rows = new Map<string, InspectorRow>();
    private readonly enums = new EnumLiterals();
    private conn: RosConnection | undefined;
    private ports: PortMap | undefined;

    constructor(private readonly host: InspectorHost) {
        this.allOnDiagram.checked = true;
        const table = el(
            'table',
            { class: 'maa-inspector-table' },
            el(
                'thead',
                {},
                el(
                    'tr',
                    {},
                    el('th', { title: 'Watch: plot the value' }, 'Watch'),
                    el('th', {}, 'Port'),
                    el('th', {}, 'Value'),
                    el('th', {}, 'Inject'),
                ),
            ),
            this.tbody,
        );
        this.element = el(
            'div',
            { class: 'maa-sim-inspector', 'data-testid': 'port-inspector' },
            el(
                'div',
                { class: 'maa-inspector-header' },
                this.filterInput,
                el(
                    'label',
                    { title: 'Show every port value on the diagram (otherwise only watched ones)' },
                    this.allOnDiagram,
                    ' all values on diagram',
                ),
                el(
                    'label',
                    { title: 'Also list the simulator topics (/clock, /joint_states, sensors, actuators)' },
                    this.showPlatform,
                    ' platform topics',
                ),
            ),
            this.staleNote,
            this.empty,
            table,
        );
        this.filterInput.addEventListener('input', () => this.render());
        this.showPlatform.addEventListener('change', () => {
            this.render();
            this.updateSubscriptions();
        });
        this.allOnDiagram.addEventListener('change', () => {
            this.updateSubscriptions();
            this.host.valuesChanged();
        });
    }

    /** The rosbridge connection topics are subscribed on (`undefined`: none yet). */
    connect(conn: RosConnection | undefined): void {
        this.conn = conn;
    }

    /**
     * The run's topics: new rows for new topics; `ports` says which topic carries which port. A
     * port's row stays when its topic leaves the list (ROS 2 nodes restarting at a reset, or
     * ending at a stop), with its last value; other topics that left are removed.
     */
    update(list: readonly TopicInfo[], ports: PortMap | undefined): void {
        if (this.frozen) return;
        this.ports = ports;
        const seen = new Set<string>();
        for (const info of list) {
            if (HIDDEN_TOPICS.some((re) => re.test(info.topic))) continue;
            seen.add(info.topic);
            const port = ports?.portOf(info.topic);
            const existing = this.rows.get(info.topic);
            if (existing) {
                existing.info = info;
                if (port) existing.port = port;
                continue;
            }
            this.rows.set(
                info.topic,
                new InspectorRow(
                    info,
                    port,
                    (row) => this.watchChanged(row),
                    (row, text) => this.inject(row, text),
                ),
            );
        }
        for (const [topic, r] of this.rows) {
            if (!seen.has(topic) && !r.port) {
                r.sub?.dispose();
                r.tr.remove();
                this.rows.delete(topic);
            }
        }
        this.render();
        this.updateSubscriptions();
    }

    /** Shows the values that arrived since the last call; true when a port's shown value changed. */
    flush(): boolean {
        let changed = false;
        for (const r of this.rows.values()) if (r.flush(this.enums)) changed = true;
        return changed;
    }

    /** The values for the diagram by port path: every port's, or only the watched ones. */
    diagramValues(): Map<string, string> {
        const values = new Map<string, string>();
        for (const r of this.rows.values()) {
            if (!r.port || r.lastText === undefined) continue;
            if (!this.allOnDiagram.checked && !r.watched) continue;
            const text = formatRosValue(r.last, 28, this.enums.formatOptions(r.info.type));
            for (const path of this.ports?.diagramPaths(r.info.topic) ?? [r.port.portPath]) values.set(path, text);
        }
        return values;
    }

    /** Forgets the plotted samples (the simulation went back to its start). */
    clearSamples(): void {
        for (const r of this.rows.values()) r.plot.samples.clear();
    }

    /** Removes every row and subscription (a new run starts). */
    clear(): void {
        for (const r of this.rows.values()) r.sub?.dispose();
        this.rows.clear();
        this.tbody.replaceChildren();
        this.conn = undefined;
        this.ports = undefined;
        this.frozen = false;
        this.recording = undefined;
        this.element.classList.remove('maa-inspector-stale');
        this.staleNote.hidden = true;
        this.render();
    }

    /**
     * The run is over (stopped or ended): every subscription ends, the rows keep their last
     * values, and a note says whose they are (`note`: "Last values of the stopped run (t 12.34 s)").
     */
    freeze(note: string): void {
        for (const r of this.rows.values()) {
            r.sub?.dispose();
            r.sub = undefined;
            r.flush(this.enums); // values that arrived since the last tick
        }
        this.conn = undefined;
        this.frozen = true;
        this.element.classList.add('maa-inspector-stale');
        this.staleNote.textContent = note;
        this.staleNote.hidden = this.rows.size === 0;
        this.render();
    }

    /**
     * A replay opens: a row per topic of the recording (`ports`: its platform's port topics,
     * `undefined` for a recording from elsewhere), nothing subscribed, no injection; the rows
     * show the recorded values at the time {@link showAt} gives.
     */
    showRecording(name: string, topics: readonly string[], ports: PortMap | undefined): void {
        this.clear();
        this.update(
            topics.map((topic) => ({ topic, type: ports?.portOf(topic)?.type ?? '' })),
            ports,
        );
        for (const r of this.rows.values()) r.withoutInjection();
        this.recording = name;
        this.frozen = true;
        this.element.classList.add('maa-inspector-stale');
    }

    /** A replay's cursor moved to `t`: each row shows its topic's last recorded message at or before `t` ("–" before the first). */
    showAt(store: TimelineStore, t: number): void {
        if (this.recording === undefined) return;
        for (const r of this.rows.values()) r.showRecorded(store.latestAt(r.info.topic, t)?.message, this.enums);
        this.staleNote.textContent = `Recorded values at ${t.toFixed(2)} s (replay of ${this.recording})`;
        this.staleNote.hidden = this.rows.size === 0;
    }

    /** The rows show a replay's recorded values (see {@link showRecording}). */
    get replaying(): boolean {
        return this.recording !== undefined;
    }

    /** The rows are the last run's (see {@link freeze}). */
    get stale(): boolean {
        return this.frozen && this.recording === undefined;
    }

    private watchChanged(row: InspectorRow): void {
        // resubscribe: watched topics arrive unthrottled
        row.sub?.dispose();
        row.sub = undefined;
        this.updateSubscriptions();
        this.host.valuesChanged();
    }

    private inject(row: InspectorRow, text: string): void {
        const conn = this.conn;
        if (this.frozen) return;
        if (!conn || this.rows.get(row.info.topic) !== row) return;
        void inject(conn, { topic: row.info.topic, type: row.info.type, label: row.label }, text, this.enums, (severity, message) =>
            this.host.notify(severity, message),
        );
    }

    private visible(r: InspectorRow): boolean {
        if (!r.port && !this.showPlatform.checked && !r.watched) return false;
        const f = this.filterInput.value.trim().toLowerCase();
        return !f || r.info.topic.toLowerCase().includes(f) || (r.port?.portPath.toLowerCase().includes(f) ?? false);
    }

    private render(): void {
        const sorted = [...this.rows.values()].sort((a, b) => Number(!a.port) - Number(!b.port) || a.label.localeCompare(b.label));
        const visible = sorted.filter((r) => this.visible(r));
        this.tbody.replaceChildren(...visible.map((r) => r.tr));
        this.empty.hidden = visible.length > 0;
        this.empty.textContent = emptyText(this.rows.size, this.filterInput.value);
    }

    /** Subscribed: watched rows, port rows when all values go to the diagram or the row is visible, platform rows when listed. */
    private updateSubscriptions(): void {
        const conn = this.conn;
        if (!conn || this.frozen) return;
        for (const r of this.rows.values()) {
            const want =
                r.watched ||
                (!!r.port && this.allOnDiagram.checked) ||
                (!r.port && this.showPlatform.checked) ||
                (!!r.port && this.visible(r));
            if (want && !r.sub) {
                r.sub = conn.subscribe(r.info.topic, r.info.type || undefined, (m) => this.receive(r, m), r.watched ? 0 : THROTTLE_MS);
            } else if (!want && r.sub) {
                r.sub.dispose();
                r.sub = undefined;
            }
        }
    }

    private receive(r: InspectorRow, m: unknown): void {
        r.receive(m, this.host.sampleTime());
        if (isEnumMessage(m)) {
            this.enums.lookUp(this.conn, r.info.type, (type) => {
                for (const row of this.rows.values()) if (row.info.type === type) row.touch();
            });
        }
    }
}

/** What the table says when it shows no row: nothing yet, nothing matches the filter, or only platform topics. */
export function emptyText(rows: number, filter: string): string {
    if (rows === 0) return 'Port topics appear here during a run.';
    if (filter.trim() !== '') return 'No topic matches the filter.';
    return 'No port topics yet ("platform topics" lists the simulator\'s).';
}
