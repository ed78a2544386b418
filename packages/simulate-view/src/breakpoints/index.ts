/**
 * The breakpoints list of the simulate view (docs/simulation.md "Breakpoints"): once a run's
 * automata table is there, every automaton instance with its states and transitions, each with
 * a checkbox. A change sends the checked ones to the simulator (`/sim/set_breakpoints`, lock-step
 * runs only); while any is set, the simulator's status tells which one the run paused at, and
 * the list marks it. It keeps its own rosbridge connection to the run (services and status only),
 * so it depends on nothing but the run's rosbridge URL and the table; the checks survive the
 * next run of the same application.
 */
import './breakpoints.css';
import type { Breakpoint } from '@maa/protocol';
import type { Disposable } from '../contracts.js';
import { el, errorText } from '../dom.js';
import { RosConnection, type SimServiceResponse } from '../ros/index.js';
import { type AutomatonInfo, instanceLabel } from '../timeline/automata.js';
import {
    breakpointOfStatus,
    breakpointRows,
    breakpointsRequest,
    describeHit,
    rowKeyOf,
    type AutomatonRows,
    type BreakpointRow,
} from './model.js';

const STATUS_PERIOD_MS = 500;

export interface BreakpointsHost {
    notify(severity: 'info' | 'warning' | 'error', message: string): void;
}

export class BreakpointsView implements Disposable {
    readonly element: HTMLDetailsElement;
    private readonly summary = el('summary', {}, 'Breakpoints');
    private readonly hitLine = el('div', { class: 'maa-bp-hit-line', 'data-testid': 'breakpoint-hit' });
    private readonly list = el('div', { class: 'maa-bp-list' });
    private rows: AutomatonRows[] = [];
    private readonly checked = new Set<string>();
    private readonly boxes = new Map<string, HTMLLabelElement>();
    private conn: RosConnection | undefined;
    private timer: ReturnType<typeof setInterval> | undefined;
    private hit: Breakpoint | undefined;

    constructor(private readonly host: BreakpointsHost) {
        this.element = el('details', { class: 'maa-breakpoints', 'data-testid': 'breakpoints' }, this.summary, this.hitLine, this.list);
        this.element.hidden = true;
    }

    /** A live run's automata table arrived: lists it and sends the checks kept from before to the run at `rosbridge`. */
    attach(automata: readonly AutomatonInfo[], rosbridge: string): void {
        this.detach();
        this.rows = breakpointRows(automata);
        const keys = new Set(this.rows.flatMap((a) => [...a.states, ...a.transitions].map((r) => r.key)));
        for (const k of [...this.checked]) if (!keys.has(k)) this.checked.delete(k);
        this.render();
        this.element.hidden = this.rows.length === 0;
        if (this.rows.length === 0) return;
        const conn = new RosConnection(rosbridge);
        this.conn = conn;
        // the run's end closes the endpoint: no status to follow any more
        conn.onState((state) => {
            if ((state === 'closed' || state === 'error') && this.conn === conn) this.detach();
        });
        conn.whenConnected(10_000).then(
            () => {
                if (this.conn !== conn) return;
                if (this.checked.size > 0) void this.send();
                this.timer = setInterval(() => void this.pollStatus(), STATUS_PERIOD_MS);
            },
            (e: unknown) => this.host.notify('warning', `Breakpoints: no connection to the simulator (${errorText(e)})`),
        );
    }

    /** The run is over: no connection, no status; the list and its checks stay. */
    detach(): void {
        if (this.timer !== undefined) clearInterval(this.timer);
        this.timer = undefined;
        this.conn?.dispose();
        this.conn = undefined;
        this.showHit(undefined);
    }

    dispose(): void {
        this.detach();
        this.element.remove();
    }

    private render(): void {
        this.boxes.clear();
        const sections = this.rows.map((a) =>
            el(
                'div',
                { class: 'maa-bp-automaton', 'data-testid': `breakpoints-${a.instancePath}` },
                el('div', { class: 'maa-bp-title' }, `${instanceLabel(a.instancePath)}: ${a.component}`),
                el('div', { class: 'maa-bp-group' }, ...a.states.map((r) => this.row(a, r))),
                el('div', { class: 'maa-bp-group' }, ...a.transitions.map((r) => this.row(a, r))),
            ),
        );
        this.list.replaceChildren(...sections);
        this.renderSummary();
    }

    private row(a: AutomatonRows, r: BreakpointRow): HTMLLabelElement {
        const box = el('input', { type: 'checkbox', 'data-testid': `bp-${a.instancePath}-${r.id}` });
        box.checked = this.checked.has(r.key);
        box.addEventListener('change', () => {
            if (box.checked) this.checked.add(r.key);
            else this.checked.delete(r.key);
            this.renderSummary();
            void this.send();
        });
        const label = el('label', { class: 'maa-bp-row', title: r.detail || r.text }, box, el('span', {}, r.text));
        if (r.detail) label.append(el('span', { class: 'maa-bp-detail' }, r.detail));
        this.boxes.set(r.key, label);
        return label;
    }

    private renderSummary(): void {
        this.summary.textContent = this.checked.size > 0 ? `Breakpoints (${this.checked.size})` : 'Breakpoints';
    }

    /** Sends the checked breakpoints (the whole set); a refusal (a ROS 2 run) is told. */
    private async send(): Promise<void> {
        const conn = this.conn;
        if (conn?.connectionState !== 'connected') return;
        try {
            const res = await conn.callService<SimServiceResponse>('/sim/set_breakpoints', breakpointsRequest(this.rows, this.checked));
            if (res && res.success === false) this.host.notify('warning', `Breakpoints: ${res.message ?? 'refused'}`);
        } catch (e) {
            this.host.notify('warning', `Breakpoints: ${errorText(e)}`);
        }
    }

    private async pollStatus(): Promise<void> {
        const conn = this.conn;
        if (conn?.connectionState !== 'connected') return;
        try {
            const answer = await conn.callService<unknown>('/sim/get_status', {}, 5000);
            if (conn === this.conn) this.showHit(breakpointOfStatus(answer));
        } catch {
            /* the next poll tries again; a stopped run detaches */
        }
    }

    private showHit(bp: Breakpoint | undefined): void {
        const same = JSON.stringify(bp) === JSON.stringify(this.hit);
        if (same) return;
        this.hit = bp;
        for (const label of this.boxes.values()) label.classList.remove('maa-bp-hit');
        this.hitLine.textContent = bp ? describeHit(this.rows, bp) : '';
        const key = bp ? rowKeyOf(this.rows, bp) : undefined;
        if (key) this.boxes.get(key)?.classList.add('maa-bp-hit');
        if (bp) this.element.open = true;
    }
}
