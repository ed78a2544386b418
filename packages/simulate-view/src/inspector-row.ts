/** One row of the port inspector: a topic, its port (when it is one), the last value and its plot. */
import type { Disposable } from './contracts.js';
import type { TopicInfo } from './ros/index.js';
import { el } from './dom.js';
import type { EnumLiterals } from './enums.js';
import { formatRosValue, numericValue } from './format.js';
import { injectControls } from './injection.js';
import { Sparkline } from './plots.js';
import type { PortTopicEntry } from './backend.js';

export class InspectorRow {
    readonly tr: HTMLTableRowElement;
    readonly watch: HTMLInputElement;
    readonly plot = new Sparkline();
    sub?: Disposable;
    /** The last message. */
    last?: unknown;
    /** The last value as the inspector shows it. */
    lastText?: string;
    private readonly valueText = el('div', { class: 'maa-port-value-text' }, '–');
    private readonly injectCell = el('td', { class: 'maa-port-inject' });
    private dirty = false;
    private numeric = false;

    /**
     * `onWatch` runs when the watch box changes; `onInject` gets the text of the inject field, which
     * only ports fed from outside offer (no port of the application publishes their topic).
     */
    constructor(
        public info: TopicInfo,
        public port: PortTopicEntry | undefined,
        onWatch: (row: InspectorRow) => void,
        onInject: (row: InspectorRow, text: string) => void,
    ) {
        this.watch = el('input', { type: 'checkbox', title: 'Watch this port (plot)', 'data-topic': info.topic, class: 'maa-watch' });
        const valueCell = el('td', { class: 'maa-port-value', 'data-testid': 'port-value' }, this.valueText, this.plot.element);
        const nameCell = el(
            'td',
            { class: 'maa-port-name', title: `${info.topic}  (${info.type || 'type unknown'})` },
            port ? port.portPath : info.topic,
        );
        const injectCell = this.injectCell;
        if (port?.external) injectCell.append(...injectControls(info.topic, info.type, (text) => onInject(this, text)));
        this.tr = el(
            'tr',
            { class: port ? 'maa-port-row' : 'maa-platform-row', 'data-topic': info.topic, 'data-port-path': port?.portPath ?? '' },
            el('td', {}, this.watch),
            nameCell,
            valueCell,
            injectCell,
        );
        this.watch.addEventListener('change', () => {
            this.tr.classList.toggle('maa-watched', this.watch.checked);
            if (!this.watch.checked) this.plot.samples.clear();
            onWatch(this);
        });
    }

    get watched(): boolean {
        return this.watch.checked;
    }

    /** What the port path or topic sorts and filters by. */
    get label(): string {
        return this.port?.portPath ?? this.info.topic;
    }

    /** A message arrived: kept for the next {@link flush}; a numeric value of a watched row is sampled at `time`. */
    receive(m: unknown, time: number): void {
        this.last = m;
        this.dirty = true;
        const v = numericValue(m);
        if (v !== undefined) {
            this.numeric = true;
            if (this.watch.checked) this.plot.samples.push(time, v);
        }
    }

    /** The value must be shown again (its enum literals became known). */
    touch(): void {
        if (this.last !== undefined) this.dirty = true;
    }

    /** Removes the inject field (a replay's row: a recording takes no input). */
    withoutInjection(): void {
        this.injectCell.replaceChildren();
    }

    /** Shows a recorded message (a replay at its cursor); `undefined`: none recorded yet ("–"). */
    showRecorded(m: unknown, enums: EnumLiterals): void {
        this.last = m;
        this.dirty = false;
        const text = m === undefined ? undefined : formatRosValue(m, 120, enums.formatOptions(this.info.type));
        if (text === this.lastText) return;
        this.lastText = text;
        this.valueText.textContent = text ?? '–';
        this.valueText.title = text ?? 'nothing recorded yet at this time';
    }

    /** Shows a new value and the plot; true when the shown text of a port changed. */
    flush(enums: EnumLiterals): boolean {
        let changed = false;
        if (this.dirty) {
            this.dirty = false;
            const text = formatRosValue(this.last, 120, enums.formatOptions(this.info.type));
            if (text !== this.lastText) {
                this.lastText = text;
                this.valueText.textContent = text;
                this.valueText.title = text;
                if (this.port) changed = true;
            }
            if (this.watch.checked && this.numeric) this.plot.draw();
        }
        if (!this.watch.checked) this.plot.erase();
        return changed;
    }
}
