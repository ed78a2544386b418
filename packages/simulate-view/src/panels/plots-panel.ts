/**
 * The plots panel: plots of numeric message fields over simulated time, several series per plot
 * (picked by topic and field), all sharing the time window (wheel: zoom, drag: pan) and the time
 * cursor (click: set it, and show the transition taken last by then; "Live" in the time bar
 * follows again). The legend shows each series' value at the cursor.
 */
import { SVG_NS, el } from '../dom.js';
import { fieldValue, numericFields, seriesPath, seriesPoints, valueRange, type SeriesKey } from '../timeline/series.js';
import { formatTime, timeTicks, xOf } from '../timeline/window.js';
import type { Panel, PanelContext } from './context.js';
import { attachTimeInput } from './time-input.js';

const HEIGHT = 140;
const AXIS = 16;
const COLORS = ['#1f77b4', '#ff7f0e', '#2ca02c', '#d62728', '#9467bd', '#8c564b', '#e377c2', '#17becf'];

function svg<K extends keyof SVGElementTagNameMap>(tag: K, attrs: Record<string, string | number> = {}): SVGElementTagNameMap[K] {
    const e = document.createElementNS(SVG_NS, tag);
    for (const [k, v] of Object.entries(attrs)) e.setAttribute(k, String(v));
    return e;
}

/** A select's options, replaced only when they changed (keeps an open list and the choice). */
function setOptions(select: HTMLSelectElement, values: readonly string[], labels?: (v: string) => string): void {
    const key = values.join('\n');
    if (select.dataset['options'] === key) return;
    const chosen = select.value;
    select.replaceChildren(...values.map((v) => el('option', { value: v }, labels ? labels(v) : v)));
    select.dataset['options'] = key;
    if (values.includes(chosen)) select.value = chosen;
}

/** A series' colour in the legend (set through the CSSOM: the webview's CSP refuses style attributes). */
function swatch(color: string): HTMLElement {
    const s = el('span', { class: 'maa-plot-swatch' });
    s.style.background = color;
    return s;
}

class Plot {
    readonly series: SeriesKey[] = [];
    readonly element: HTMLElement;
    private readonly svgEl = svg('svg', { class: 'maa-plot-svg', height: HEIGHT });
    private readonly legend = el('div', { class: 'maa-plot-legend' });
    private readonly topicSelect = el('select', { 'data-testid': 'plot-topic', title: 'Topic' });
    private readonly fieldSelect = el('select', { 'data-testid': 'plot-field', title: 'Numeric field' });

    constructor(
        private readonly ctx: PanelContext,
        remove: () => void,
    ) {
        const add = el('button', { type: 'button', 'data-testid': 'plot-add-series', title: 'Plot this field' }, 'Add');
        const close = el('button', { type: 'button', class: 'maa-plot-close', title: 'Remove this plot' }, '×');
        this.element = el(
            'div',
            { class: 'maa-plot', 'data-testid': 'plot' },
            el('div', { class: 'maa-plot-picker' }, this.topicSelect, this.fieldSelect, add, close),
            this.legend,
            this.svgEl,
        );
        this.topicSelect.addEventListener('change', () => this.fillFields());
        add.addEventListener('click', () => this.addSeries({ topic: this.topicSelect.value, field: this.fieldSelect.value }));
        close.addEventListener('click', remove);
        attachTimeInput(this.svgEl, ctx);
    }

    addSeries(key: SeriesKey): void {
        if (!key.topic || this.series.some((s) => s.topic === key.topic && s.field === key.field)) return;
        this.series.push(key);
        this.ctx.redraw();
    }

    /** The topics with numeric fields, and the fields of the chosen one. */
    fillPicker(topics: readonly string[]): void {
        setOptions(this.topicSelect, topics);
        this.fillFields();
    }

    private fillFields(): void {
        const topic = this.topicSelect.value;
        const latest = topic ? this.ctx.store.latestAt(topic, Infinity) : undefined;
        setOptions(this.fieldSelect, latest ? numericFields(latest.message) : [], (f) => f || '(value)');
    }

    render(): void {
        const { store, window } = this.ctx;
        const width = Math.max(50, Math.floor(this.svgEl.getBoundingClientRect().width || this.element.clientWidth || 300));
        const h = HEIGHT - AXIS;
        const span = window.span(store.start, store.end);
        const points = this.series.map((s) => seriesPoints(store, s, span));
        const range = valueRange(points);
        const children: SVGElement[] = [];
        for (const t of timeTicks(span, Math.max(2, Math.floor(width / 90)))) {
            const x = xOf(t, span, width);
            children.push(svg('line', { class: 'maa-plot-grid', x1: x, x2: x, y1: 0, y2: h }));
            const label = svg('text', { class: 'maa-plot-tick', x, y: HEIGHT - 3 });
            label.textContent = formatTime(t, span.t1 - span.t0);
            children.push(label);
        }
        if (range) {
            for (const [i, pts] of points.entries()) {
                const d = seriesPath(pts, span, range, width, h);
                if (d) children.push(svg('path', { class: 'maa-plot-line', d, stroke: COLORS[i % COLORS.length]! }));
            }
            for (const [v, y] of [
                [range.max, 10],
                [range.min, h - 3],
            ] as const) {
                const label = svg('text', { class: 'maa-plot-value', x: 3, y });
                label.textContent = String(Number(v.toPrecision(4)));
                children.push(label);
            }
        }
        if (store.cursor !== undefined) {
            const x = xOf(store.cursor, span, width);
            children.push(svg('line', { class: 'maa-plot-cursor', x1: x, x2: x, y1: 0, y2: h }));
        }
        this.svgEl.setAttribute('viewBox', `0 0 ${width} ${HEIGHT}`);
        this.svgEl.replaceChildren(...children);
        this.renderLegend();
    }

    private renderLegend(): void {
        const { store } = this.ctx;
        const t = store.shownTime;
        this.legend.replaceChildren(
            ...this.series.map((s, i) => {
                const m = t === undefined ? undefined : store.latestAt(s.topic, t);
                const v = m ? fieldValue(m.message, s.field) : undefined;
                const remove = el('button', { type: 'button', class: 'maa-plot-close', title: 'Remove this series' }, '×');
                remove.addEventListener('click', () => {
                    this.series.splice(this.series.indexOf(s), 1);
                    this.ctx.redraw();
                });
                return el(
                    'span',
                    { class: 'maa-plot-series', 'data-testid': 'plot-series' },
                    swatch(COLORS[i % COLORS.length]!),
                    `${s.topic}${s.field ? ` ${s.field}` : ''} = `,
                    el('b', { 'data-testid': 'plot-series-value' }, v === undefined ? '–' : String(Number(v.toPrecision(6)))),
                    remove,
                );
            }),
        );
    }
}

export class PlotsPanel implements Panel {
    readonly id = 'plots';
    readonly title = 'Plots';
    readonly element: HTMLElement;
    private readonly plots: Plot[] = [];
    private readonly list = el('div', { class: 'maa-plots' });

    constructor(private readonly ctx: PanelContext) {
        const add = el('button', { type: 'button', 'data-testid': 'plot-new', title: 'Add a plot' }, '+ Plot');
        add.addEventListener('click', () => this.addPlot());
        this.element = el(
            'div',
            { class: 'maa-panel maa-plots-panel', 'data-testid': 'plots-panel' },
            el(
                'div',
                { class: 'maa-panel-toolbar' },
                add,
                el('span', { class: 'maa-panel-hint' }, 'wheel: zoom · drag: pan · click: the cursor and the transition taken by then'),
            ),
            this.list,
        );
        this.addPlot();
    }

    addPlot(): void {
        const plot = new Plot(this.ctx, () => {
            this.plots.splice(this.plots.indexOf(plot), 1);
            plot.element.remove();
        });
        this.plots.push(plot);
        this.list.appendChild(plot.element);
        this.ctx.redraw();
    }

    render(): void {
        const { store } = this.ctx;
        const topics = store.topics().filter((t) => {
            const m = store.latestAt(t, Infinity);
            return m !== undefined && numericFields(m.message).length > 0;
        });
        for (const p of this.plots) {
            p.fillPicker(topics);
            p.render();
        }
    }
}
