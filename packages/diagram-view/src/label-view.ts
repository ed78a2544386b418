/**
 * The view of labels: text placed by the server's layout, behavior badges, shortened labels with
 * their full text, behavior lines (one opens the automaton view), and the rooms the server keeps
 * for a run: a port's live value (`label:value`) and a component's current state or mode
 * (`label:chip`), drawn only while there is one.
 */
import { SLabelView, svg, type RenderingContext, type SLabelImpl } from 'sprotty';
import type { ComponentNode, MaaPort } from './model.js';
import { BADGE_TEXT, fitText, textWidth, type VNode, type ViewState } from './view-parts.js';

/** Advance of a character of the live value's monospace font (10.5px) and of the chip's text. */
const VALUE_CHAR = 6.4;
const CHIP_CHAR = 6.6;

/** A text in a rounded box filling the label's room, cut short to fit (whole in its tooltip). */
function pill(w: number, h: number, text: string, charWidth: number, boxClass: string, textClass: string, title: string): VNode {
    return svg(
        'g',
        { class: { [boxClass]: true } },
        svg('title', {}, title),
        svg('rect', { x: 0, y: 0, width: w, height: h, rx: 3, ry: 3 }),
        svg('text', { class: { [textClass]: true }, x: w / 2, y: h - 3.5, 'text-anchor': 'middle' }, fitText(text, w - 6, charWidth)),
    );
}

/** A port's live value in its room beside the port's name. */
function valueView(label: Readonly<SLabelImpl>, state: ViewState, w: number, h: number): VNode | undefined {
    const port = label.parent as unknown as MaaPort | undefined;
    const value = port ? portValue(port, state) : undefined;
    if (value === undefined) return undefined;
    return pill(w, h, value, VALUE_CHAR, 'maa-value-label', 'maa-value', `${port?.name ?? ''} = ${value}`);
}

/**
 * The live value of a port; for an in port of the shown component without one of its own, that
 * of a port its connectors feed (on ROS 2 the topic map names the in ports that read a topic fed
 * from outside, not the root's port).
 */
function portValue(port: MaaPort, state: ViewState): string | undefined {
    const own = state.liveValue(port.portPath);
    if (own !== undefined || port.direction !== 'in') return own;
    for (const edge of port.outgoingEdges) {
        const target = edge.target as MaaPort | undefined;
        const value = target?.type === 'port' ? state.liveValue(target.portPath) : undefined;
        if (value !== undefined) return value;
    }
    return undefined;
}

/** A component's current state or mode (or a highlighted trace point's state) in its room at the bottom. */
function chipView(label: Readonly<SLabelImpl>, state: ViewState, w: number, h: number): VNode | undefined {
    const node = label.parent as unknown as ComponentNode | undefined;
    const highlight = state.highlightOf(node?.instancePath);
    const current = state.activeStateOf(node?.instancePath) ?? highlight?.state;
    if (current === undefined) return undefined;
    const mode = !!node?.composed;
    const text = `▶ ${mode ? 'mode ' : ''}${current}`;
    const vnode = mode
        ? pill(w, h, text, CHIP_CHAR, 'maa-current-mode', 'maa-mode-current', text)
        : pill(w, h, text, CHIP_CHAR, 'maa-current-state', 'maa-state-active', text);
    // The instance of a highlighted trace point: its chip is marked (showing the run's state at the cursor, else the highlighted one).
    if (highlight && vnode.data?.class) vnode.data.class['maa-chip-highlight'] = true;
    return vnode;
}

export function labelView(state: ViewState): new () => SLabelView {
    return class LabelView extends SLabelView {
        override render(label: Readonly<SLabelImpl>, context: RenderingContext): VNode | undefined {
            if (!this.isVisible(label, context)) return undefined;
            const type = (label as unknown as { maaType?: string }).maaType ?? label.type;
            const cls = `maa-${type.replace(/[^A-Za-z0-9_-]/g, '-')}`;
            const h = label.size.height > 0 ? label.size.height : 16;
            const w = label.size.width > 0 ? label.size.width : textWidth(label.text, 7) + 4;
            if (type === 'label:value') return valueView(label, state, w, h);
            if (type === 'label:chip') return chipView(label, state, w, h);
            // the server lays out label boxes (top left); without client layout there is no
            // baseline alignment, so the text's baseline goes about three quarters down the box
            const aligned = !!label.alignment && (label.alignment.x !== 0 || label.alignment.y !== 0);
            const y = aligned ? 0 : Math.round(h * 0.75);
            if (type === 'label:badge') {
                const kind = label.text;
                return svg(
                    'g',
                    { class: { 'maa-badge': true, [`maa-badge-${kind}`]: true, 'maa-label': true, [cls]: true } },
                    svg('title', {}, `behavior: ${BADGE_TEXT[kind] ?? kind}`),
                    svg('rect', { x: 0, y: 1, width: w, height: h - 2, rx: (h - 2) / 2, ry: (h - 2) / 2 }),
                    svg('text', { x: w / 2, y: y - 1, 'text-anchor': 'middle' }, BADGE_TEXT[kind] ?? kind),
                );
            }
            if ((label as unknown as { opens?: unknown }).opens === 'automaton') return behaviorLink(label, state, cls, y);
            // a shortened label (a long transition label) carries its whole text for a tooltip
            const fullText = (label as unknown as { fullText?: unknown }).fullText;
            const full = typeof fullText === 'string' && fullText !== label.text ? fullText : undefined;
            if (full === undefined) return svg('text', { class: { 'sprotty-label': true, 'maa-label': true, [cls]: true }, y }, label.text);
            return svg(
                'text',
                {
                    class: { 'sprotty-label': true, 'maa-label': true, 'maa-label-shortened': true, [cls]: true },
                    y,
                    'data-full-text': full,
                },
                svg('title', {}, full),
                label.text,
            );
        }
    };
}

/** The behavior line of an atomic component shown on its own that opens its automaton view on a click. */
function behaviorLink(label: Readonly<SLabelImpl>, state: ViewState, cls: string, y: number): VNode {
    const node = label.parent as unknown as ComponentNode | undefined;
    const type = node?.componentType;
    return svg(
        'text',
        {
            class: { 'sprotty-label': true, 'maa-label': true, [cls]: true, 'maa-behavior-link': true },
            y,
            on: {
                mousedown: (e: Event) => e.stopPropagation(),
                click: (e: Event) => {
                    e.stopPropagation();
                    if (type) state.openAutomaton(type);
                },
            },
        },
        svg('title', {}, 'open the automaton view'),
        label.text,
    );
}
