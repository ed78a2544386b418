/**
 * The panels of the simulate view (docs/ide.md "Panels"): a dock of tabs — plots, the state
 * timeline, raw messages, the log — over the session's timeline store, with a time bar (the
 * shown time, "Live" to follow the newest data again). They share the time window and cursor
 * (store.cursor) and the selected transition, whose reveal goes to the host (the VS Code
 * extension opens the source line and highlights the diagram).
 */
import './panels.css';
import type { Disposable } from '../contracts.js';
import { el } from '../dom.js';
import type { RevealMessage } from '../host-messages.js';
import type { AutomatonInfo } from '../timeline/automata.js';
import type { TimelineStore } from '../timeline/store.js';
import { lastAtOrBefore, TransitionIndex, type ProgramStep, type TakenTransition } from '../timeline/transitions.js';
import { TimeWindow, formatTime } from '../timeline/window.js';
import type { Panel, PanelContext } from './context.js';
import { LogPanel } from './log-panel.js';
import { MessagesPanel } from './messages-panel.js';
import { PlotsPanel } from './plots-panel.js';
import { revealProgramStep, revealTransition } from './reveal.js';
import { StatesPanel } from './states-panel.js';

/** New data redraws at most this often (a lock-step run delivers hundreds of messages a second). */
const DATA_REDRAW_MS = 100;

export interface PanelsHost {
    /** Shows a selected transition or program step in the model (absent: nothing to reveal in). */
    reveal?(message: RevealMessage): void;
}

export class Panels implements Disposable {
    readonly element: HTMLElement;
    private readonly window = new TimeWindow();
    private readonly index: TransitionIndex;
    private readonly panels: Panel[];
    private readonly tabs = new Map<string, HTMLButtonElement>();
    private active: Panel;
    private automata: readonly AutomatonInfo[] = [];
    private instanceOf: (node: string) => string | undefined = () => undefined;
    private selected: TakenTransition | undefined;
    private readonly timeLabel = el('span', { class: 'maa-panels-time', 'data-testid': 'panels-time' });
    private readonly liveBtn = el(
        'button',
        { type: 'button', 'data-testid': 'panels-live', title: 'Follow the newest data (clears the cursor)' },
        'Live',
    );
    private readonly fitBtn = el(
        'button',
        { type: 'button', 'data-testid': 'panels-fit', title: 'Show the whole run in the time window' },
        'All',
    );
    private readonly zoomInBtn = el(
        'button',
        { type: 'button', 'data-testid': 'panels-zoom-in', title: 'Zoom in (around the cursor; also the mouse wheel)' },
        '+',
    );
    private readonly zoomOutBtn = el(
        'button',
        { type: 'button', 'data-testid': 'panels-zoom-out', title: 'Zoom out (around the cursor; also the mouse wheel)' },
        '−',
    );
    private frame: number | undefined;
    private dataTimer: ReturnType<typeof setTimeout> | undefined;
    private readonly sub: Disposable;

    constructor(
        private readonly store: TimelineStore,
        private readonly host: PanelsHost,
    ) {
        this.index = new TransitionIndex(store);
        const ctx = this.context();
        this.panels = [new StatesPanel(ctx), new PlotsPanel(ctx), new MessagesPanel(ctx), new LogPanel(ctx)];
        this.active = this.panels[0]!;
        const tabBar = el('div', { class: 'maa-panels-tabs', role: 'tablist' });
        for (const p of this.panels) {
            const b = el('button', { type: 'button', role: 'tab', class: 'maa-panels-tab', 'data-testid': `panels-tab-${p.id}` }, p.title);
            b.addEventListener('click', () => this.show(p.id));
            this.tabs.set(p.id, b);
            tabBar.appendChild(b);
        }
        this.liveBtn.addEventListener('click', () => {
            store.cursor = undefined;
            this.window.follow();
            this.redraw();
        });
        this.fitBtn.addEventListener('click', () => {
            const { start, end } = store;
            if (start === undefined || end === undefined) return;
            this.window.set({ t0: start, t1: Math.max(end, start + 1) });
            this.redraw();
        });
        this.zoomInBtn.addEventListener('click', () => this.zoomBy(0.5));
        this.zoomOutBtn.addEventListener('click', () => this.zoomBy(2));
        this.element = el(
            'div',
            { class: 'maa-panels', 'data-testid': 'sim-panels' },
            el(
                'div',
                { class: 'maa-panels-bar' },
                tabBar,
                el('span', { class: 'maa-panels-spacer' }),
                this.timeLabel,
                this.zoomOutBtn,
                this.zoomInBtn,
                this.fitBtn,
                this.liveBtn,
            ),
            ...this.panels.map((p) => p.element),
        );
        this.sub = store.onChange((what) => {
            if (what === 'cursor') this.redraw();
            else this.dataChanged();
        });
        this.show(this.active.id);
    }

    /** The run's automata table and node names (from the backend's topic map). */
    setRunInfo(automata: readonly AutomatonInfo[], instanceOf: (node: string) => string | undefined): void {
        this.automata = automata;
        this.instanceOf = instanceOf;
        this.redraw();
    }

    /** Shows a tab (`states`, `plots`, `messages`, `log`). */
    show(id: string): void {
        const p = this.panels.find((x) => x.id === id);
        if (!p) return;
        this.active = p;
        for (const x of this.panels) x.element.hidden = x !== p;
        for (const [tid, b] of this.tabs) {
            b.classList.toggle('maa-selected', tid === id);
            b.setAttribute('aria-selected', String(tid === id));
        }
        this.redraw();
    }

    /** A new session: the selection and the window start over (the store is cleared by its owner). */
    reset(): void {
        this.selected = undefined;
        this.window.follow();
        this.redraw();
    }

    /** Draws the active panel at the next frame. */
    redraw(): void {
        if (this.frame !== undefined) return;
        const raf = globalThis.requestAnimationFrame ?? ((f: FrameRequestCallback) => setTimeout(() => f(0), 16));
        this.frame = raf(() => {
            this.frame = undefined;
            this.render();
        }) as number;
    }

    dispose(): void {
        this.sub.dispose();
        if (this.dataTimer !== undefined) clearTimeout(this.dataTimer);
        this.element.remove();
    }

    private dataChanged(): void {
        if (this.dataTimer !== undefined) return;
        this.dataTimer = setTimeout(() => {
            this.dataTimer = undefined;
            this.redraw();
        }, DATA_REDRAW_MS);
    }

    private render(): void {
        this.index.update();
        if (this.selected && !this.index.transitions(this.selected.node).includes(this.selected)) this.selected = undefined;
        const { store } = this;
        const t = store.shownTime;
        this.timeLabel.textContent = t === undefined ? '' : `${store.cursor === undefined ? 'live' : 'cursor'} ${formatTime(t)}`;
        this.liveBtn.disabled = store.cursor === undefined && this.window.following;
        // the time window drawn, for scripts and the e2e tests
        const span = this.window.span(store.start, store.end);
        this.element.dataset['window'] = `${span.t0} ${span.t1}`;
        this.active.render();
    }

    private context(): PanelContext {
        const self = this;
        return {
            store: this.store,
            window: this.window,
            index: this.index,
            automata: () => self.automata,
            instanceOf: (node) => self.instanceOf(node),
            get selected() {
                return self.selected;
            },
            select: (t) => self.select(t),
            pointAt: (t, node) => self.pointAt(t, node),
            selectStep: (s) => self.selectStep(s),
            redraw: () => self.redraw(),
        };
    }

    private select(t: TakenTransition): void {
        this.selected = t;
        this.store.cursor = t.t;
        this.keepInWindow(t.t);
        const message = revealTransition(this.automata, t);
        if (message) this.host.reveal?.(message);
        this.redraw();
    }

    private pointAt(t: number, node?: string): void {
        this.store.cursor = t;
        const of = node ?? this.selected?.node;
        const last = lastAtOrBefore(of ? this.index.transitions(of) : this.index.allTransitions(), t);
        if (last && last !== this.selected) {
            this.selected = last;
            const message = revealTransition(this.automata, last);
            if (message) this.host.reveal?.(message);
        }
        this.redraw();
    }

    private selectStep(step: ProgramStep): void {
        this.store.cursor = step.t;
        this.keepInWindow(step.t);
        const message = revealProgramStep(step);
        if (message) this.host.reveal?.(message);
        this.redraw();
    }

    /** Zooms the time window by `factor` around the cursor (else its middle). */
    private zoomBy(factor: number): void {
        const span = this.window.span(this.store.start, this.store.end);
        const cursor = this.store.cursor;
        const anchor = cursor !== undefined && cursor >= span.t0 && cursor <= span.t1 ? cursor : (span.t0 + span.t1) / 2;
        this.window.zoom(span, factor, anchor);
        this.redraw();
    }

    /** Moves the window so that `t` is in it (stepping to a transition off screen). */
    private keepInWindow(t: number): void {
        const span = this.window.span(this.store.start, this.store.end);
        if (t >= span.t0 && t <= span.t1) return;
        const w = span.t1 - span.t0;
        this.window.set({ t0: t - w / 2, t1: t + w / 2 });
    }
}

export type { RevealMessage };
