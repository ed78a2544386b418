/**
 * The state timeline: per automaton instance a row of bands named by the state held over
 * simulated time, in the shared time window (wheel: zoom, drag: pan, click: cursor). A marker
 * at each transition taken shows it on hover; clicking a marker (or a band's start) selects that
 * transition (cursor there, source line and diagram highlight). Previous/next (buttons, ←/→ on
 * the panel) step through the transitions of the selected row.
 */
import { el } from '../dom.js';
import { stateAt, stepTransition, type NodeHistory, type TakenTransition } from '../timeline/transitions.js';
import { formatTime, xOf, type TimeSpan } from '../timeline/window.js';
import { nodeLabel, type Panel, type PanelContext } from './context.js';
import { attachTimeInput } from './time-input.js';

/** Transition marks closer than this are drawn once. */
const MIN_MARK_GAP_PX = 4;

/** Pastel fills by state name, stable across runs (a hash of the name). */
function bandHue(state: string): number {
    let h = 0;
    for (let i = 0; i < state.length; i++) h = (h * 31 + state.charCodeAt(i)) >>> 0;
    return h % 360;
}

export function transitionTitle(ctx: PanelContext, t: TakenTransition): string {
    const a = ctx.automata().find((x) => x.node === t.node);
    const label = a?.transitions.find((x) => (t.index !== undefined ? x.index === t.index : x.from === t.from && x.to === t.to))?.label;
    return `${nodeLabel(ctx, t.node)}: ${t.from} → ${t.to}${label ? ` (${label})` : ''} at ${formatTime(t.t)}`;
}

export class StatesPanel implements Panel {
    readonly id = 'states';
    readonly title = 'States';
    readonly element: HTMLElement;
    private readonly rows = el('div', { class: 'maa-states-rows' });
    private readonly empty = el('div', { class: 'maa-panel-empty' }, 'Automaton states appear here during a run.');
    private readonly info = el('span', { class: 'maa-states-info', 'data-testid': 'states-selected' });
    /** The node whose transitions previous/next step through (the selected transition's, or the row clicked last). */
    private focusNode: string | undefined;

    constructor(private readonly ctx: PanelContext) {
        const prev = el(
            'button',
            { type: 'button', 'data-testid': 'transition-prev', title: 'Previous transition of the selected component (←)' },
            '◀',
        );
        const next = el(
            'button',
            { type: 'button', 'data-testid': 'transition-next', title: 'Next transition of the selected component (→)' },
            '▶',
        );
        prev.addEventListener('click', () => this.step(-1));
        next.addEventListener('click', () => this.step(1));
        this.element = el(
            'div',
            { class: 'maa-panel maa-states-panel', 'data-testid': 'states-panel', tabindex: '0' },
            el('div', { class: 'maa-panel-toolbar' }, prev, next, this.info),
            this.empty,
            this.rows,
        );
        this.element.addEventListener('keydown', (e) => {
            if (e.key === 'ArrowLeft' || e.key === 'ArrowRight') {
                e.preventDefault();
                this.step(e.key === 'ArrowLeft' ? -1 : 1);
            }
        });
    }

    /** Selects the transition before or after the selected one of the focused component. */
    step(direction: 1 | -1): void {
        const { ctx } = this;
        const node = ctx.selected?.node ?? this.focusNode ?? ctx.index.histories()[0]?.node;
        if (!node) return;
        const t = ctx.store.shownTime ?? 0;
        const target = stepTransition(ctx.index.transitions(node), ctx.selected?.node === node ? ctx.selected : undefined, t, direction);
        if (target) ctx.select(target);
    }

    render(): void {
        const { ctx } = this;
        const histories = ctx.index.histories();
        this.empty.hidden = histories.length > 0;
        const span = ctx.window.span(ctx.store.start, ctx.store.end);
        const end = ctx.store.end ?? span.t1;
        // rows are kept by node, so a hover or focus survives a redraw
        const existing = new Map([...this.rows.children].map((r) => [(r as HTMLElement).dataset['node'], r as HTMLElement]));
        const rows = histories.map((h) => {
            const row = existing.get(h.node) ?? this.newRow(h.node);
            this.fillRow(row, h, span, end);
            return row;
        });
        if (rows.length !== this.rows.children.length || rows.some((r, i) => this.rows.children[i] !== r))
            this.rows.replaceChildren(...rows);
        const sel = ctx.selected;
        this.info.textContent = sel ? transitionTitle(ctx, sel) : 'Click a transition (a band boundary) to show it in the model.';
    }

    private newRow(node: string): HTMLElement {
        const label = el('div', { class: 'maa-states-label', title: node }, nodeLabel(this.ctx, node));
        const track = el('div', { class: 'maa-states-track', 'data-testid': 'states-track' });
        const row = el('div', { class: 'maa-states-row', 'data-testid': 'states-row' }, label, track);
        row.dataset['node'] = node;
        label.addEventListener('click', () => {
            this.focusNode = node;
            this.ctx.redraw();
        });
        attachTimeInput(track, this.ctx, (ev, t) => {
            const hit = (ev.target as HTMLElement | null)?.closest?.('[data-transition]') as HTMLElement | null;
            const i = hit ? Number(hit.dataset['transition']) : Number.NaN;
            const taken = this.ctx.index.transitions(node)[i];
            this.focusNode = node;
            if (taken) this.ctx.select(taken);
            else this.ctx.pointAt(t, node); // a point in the row: the row's transition taken by then
            return true;
        });
        return row;
    }

    private fillRow(row: HTMLElement, h: NodeHistory, span: TimeSpan, end: number): void {
        const { ctx } = this;
        const track = row.querySelector('.maa-states-track') as HTMLElement;
        const label = row.querySelector('.maa-states-label') as HTMLElement;
        // the state held at the shown time by name: a state entered at the newest time has no width yet
        const at = ctx.store.cursor ?? end;
        const held = stateAt(h, at);
        label.textContent = held ? `${nodeLabel(ctx, h.node)} · ${held}` : nodeLabel(ctx, h.node);
        label.dataset['state'] = held ?? '';
        row.classList.toggle('maa-states-focus', (ctx.selected?.node ?? this.focusNode) === h.node);
        const w = span.t1 - span.t0;
        const pct = (t: number): number => Math.max(-1, Math.min(101, xOf(t, span, 100)));
        const parts: HTMLElement[] = [];
        for (const b of h.bands) {
            const t1 = b.t1 ?? end;
            if (t1 < span.t0 || b.t0 > span.t1) continue;
            const left = pct(b.t0);
            const band = el(
                'div',
                {
                    class: 'maa-states-band',
                    'data-testid': 'state-band',
                    title: `${b.state}: ${formatTime(b.t0, w)} – ${b.t1 === undefined ? 'now' : formatTime(b.t1, w)}`,
                },
                b.state,
            );
            // through the CSSOM: the webview's CSP refuses style attributes
            band.style.left = `${left}%`;
            band.style.width = `${Math.max(0, pct(t1) - left)}%`;
            band.style.background = `hsl(${bandHue(b.state)} 60% 80%)`;
            band.dataset['state'] = b.state;
            parts.push(band);
        }
        const transitions = ctx.index.transitions(h.node);
        // Marks closer than a few pixels are drawn once: a self-loop taken every period (the
        // toaster's On -> On) would otherwise paint its band black. Stepping still reaches each.
        // (a track without a layout, in a hidden tab, thins nothing: it is drawn again when shown)
        const minGap = track.clientWidth > 0 ? (100 * MIN_MARK_GAP_PX) / track.clientWidth : 0;
        let lastDrawn = Number.NEGATIVE_INFINITY;
        transitions.forEach((t, i) => {
            if (t.t < span.t0 || t.t > span.t1) return;
            const x = pct(t.t);
            if (t !== ctx.selected && x - lastDrawn < minGap) return;
            lastDrawn = x;
            const mark = el('div', {
                class: `maa-states-mark${t === ctx.selected ? ' maa-selected' : ''}`,
                'data-testid': 'transition-mark',
                'data-transition': String(i),
                'data-from': t.from,
                'data-to': t.to,
                title: transitionTitle(ctx, t),
            });
            mark.style.left = `${x}%`;
            parts.push(mark);
        });
        if (ctx.store.cursor !== undefined && ctx.store.cursor >= span.t0 && ctx.store.cursor <= span.t1) {
            const cursor = el('div', { class: 'maa-states-cursor' });
            cursor.style.left = `${pct(ctx.store.cursor)}%`;
            parts.push(cursor);
        }
        track.replaceChildren(...parts);
    }
}
