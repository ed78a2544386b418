import type { Point, SEdge, SLabel, SModelElement } from 'sprotty-protocol';
import type { ComponentNode, ConnectorEdge, MaaLabel, PortNode, StateNode, TransitionEdge } from '../model.js';
import type { DiagramGeometry } from './geometry.js';
import { classes, el, num, type XmlElement, type XmlNode } from './xml.js';

/**
 * The elements of the IDE's diagram views (packages/diagram-view/src: component-view.ts,
 * node-views.ts, edge-views.ts, label-view.ts) as the IDE's Export SVG holds them for a model
 * without a run: the same element structure, CSS classes and `data-*` hooks, and every model
 * element's `id` (the element id behind a prefix, as Sprotty's `<baseDiv>_<id>`). Live values,
 * the current state or mode, selection and hover are what the CLI has not, and are left out.
 */

export interface ViewContext {
    readonly geometry: DiagramGeometry;
    /** Put before every element id (Sprotty's DOM ids are `<baseDiv>_<id>`). */
    readonly idPrefix: string;
    renderChildren(element: SModelElement): XmlNode[];
}

/** The behavior badge texts (view-parts.ts BADGE_TEXT). */
export const BADGE_TEXT: Readonly<Record<string, string>> = {
    automaton: 'automaton',
    robotarm: 'RobotArm',
    compute: 'compute',
    handwritten: 'handwritten',
    composed: 'composed',
};

/** Sprotty's LocationPostprocessor: a located element is translated to its position. */
function translate(element: SModelElement): string | undefined {
    const p = (element as { position?: Point }).position;
    return p && (p.x !== 0 || p.y !== 0) ? `translate(${num(p.x)}, ${num(p.y)})` : undefined;
}

function severityClasses(severity: unknown): Record<string, boolean> {
    return { 'maa-error': severity === 'error', 'maa-warning': severity === 'warning' };
}

function sizeOf(element: SModelElement): { width: number; height: number } {
    return (element as { size?: { width: number; height: number } }).size ?? { width: 0, height: 0 };
}

/** The expand/collapse toggle of a decomposed subcomponent (right of its type). */
function expandToggle(path: string, expanded: boolean, w: number): XmlElement {
    return el(
        'g',
        { class: 'maa-expand-toggle', transform: `translate(${num(w - 20)},20)`, 'data-instance-path': path },
        el('title', {}, expanded ? 'collapse' : 'expand'),
        el('rect', { x: 0, y: 0, width: 14, height: 14, rx: 2, ry: 2 }),
        el('path', { d: expanded ? 'M 3,7 L 11,7' : 'M 3,7 L 11,7 M 7,3 L 7,11' }),
    );
}

export function componentView(node: ComponentNode, ctx: ViewContext): XmlElement {
    const { width: w, height: h } = sizeOf(node);
    const kind = node.behaviorKind ?? (node.composed ? 'composed' : '');
    const isRoot = !node.instancePath;
    const variation = node.variationPoint ? ` (variation point: varif (${node.variationPoint}))` : '';
    const cls = classes({
        'maa-component': true,
        'maa-root': isRoot,
        'maa-composed': !!node.composed,
        'maa-expanded': !!node.expanded,
        'maa-variable': !!node.variationPoint,
        [`maa-kind-${kind || 'none'}`]: true,
        ...severityClasses(node.severity),
        component: true, // Sprotty's sub-type class (node:component)
    });
    return el(
        'g',
        {
            id: ctx.idPrefix + node.id,
            class: cls,
            'data-instance-path': node.instancePath ?? '',
            'data-mode': node.mode,
            transform: translate(node),
        },
        el('title', {}, `${node.name ?? node.id}: ${node.componentType ?? ''}${variation}`),
        el('rect', { class: 'maa-component-body', x: 0, y: 0, width: Math.max(w, 0), height: Math.max(h, 0), rx: 6, ry: 6 }),
        node.composed && !isRoot ? expandToggle(node.instancePath, !!node.expanded, w) : undefined,
        ...ctx.renderChildren(node),
    );
}

export function portView(port: PortNode, ctx: ViewContext): XmlElement {
    const size = sizeOf(port);
    const dir = port.direction === 'out' ? 'out' : 'in';
    const variation = port.variationPoint ? ` (variation point: varif (${port.variationPoint}))` : '';
    return el(
        'g',
        {
            id: ctx.idPrefix + port.id,
            class: classes({
                'maa-port': true,
                [`maa-port-${dir}`]: true,
                'maa-variable': !!port.variationPoint,
                ...severityClasses(port.severity),
            }),
            'data-port-path': port.portPath ?? '',
            transform: translate(port),
        },
        el('title', {}, `${port.name ?? port.id}: ${port.portType ?? ''} (${dir})${variation}`),
        el('rect', {
            class: 'maa-port-shape',
            x: 0,
            y: 0,
            width: size.width > 0 ? size.width : 8,
            height: size.height > 0 ? size.height : 8,
        }),
        ...ctx.renderChildren(port),
    );
}

/** The initial marker left of an initial state's top: a dot and an arrow. */
function initialMarker(): XmlElement {
    return el(
        'g',
        { class: 'maa-initial-marker' },
        el('circle', { cx: -16, cy: 14, r: 4 }),
        el('path', { d: 'M -12,14 L -1,14', 'marker-end': '' }),
        el('path', { class: 'maa-initial-arrow', d: 'M 0,14 L -5,11 L -5,17 Z' }),
    );
}

export function stateView(node: StateNode, ctx: ViewContext): XmlElement {
    const { width: w, height: h } = sizeOf(node);
    return el(
        'g',
        {
            id: ctx.idPrefix + node.id,
            class: classes({ 'maa-state': true, 'maa-state-initial': !!node.initial, ...severityClasses(node.severity), state: true }),
            'data-state-path': node.statePath ?? '',
            transform: translate(node),
        },
        el('title', {}, node.statePath ?? node.name ?? ''),
        el('rect', { class: 'maa-state-body', x: 0, y: 0, width: w, height: h, rx: 10, ry: 10 }),
        node.initial ? initialMarker() : undefined,
        ...ctx.renderChildren(node),
    );
}

/** The arrow head at the end of a route (view-parts.ts arrowHead). */
function arrowHead(route: readonly Point[]): XmlElement | undefined {
    if (route.length < 2) return undefined;
    const p = route[route.length - 1]!;
    const q = route[route.length - 2]!;
    const angle = (Math.atan2(p.y - q.y, p.x - q.x) * 180) / Math.PI;
    return el('path', {
        class: 'maa-arrow',
        d: 'M 0,0 L -9,-4.5 L -9,4.5 Z',
        transform: `translate(${num(p.x)},${num(p.y)}) rotate(${num(angle)})`,
    });
}

/** A connector or transition: Sprotty's PolylineEdgeView with the IDE's classes and arrow head. */
export function edgeView(edge: ConnectorEdge | TransitionEdge | SEdge, ctx: ViewContext): XmlElement | undefined {
    const route = ctx.geometry.route(edge);
    if (route.length === 0) return undefined; // an end is missing: nothing to draw
    const d = route.map((p, i) => `${i === 0 ? 'M' : 'L'} ${num(p.x)},${num(p.y)}`).join(' ');
    const kind = edge.type === 'edge:connector' ? 'maa-connector' : edge.type === 'edge:transition' ? 'maa-transition' : undefined;
    // Sprotty's sub-type class: that of the type the IDE registers the edge as (others are `edge:generic`).
    const subType = kind ? edge.type.slice('edge:'.length) : 'generic';
    return el(
        'g',
        {
            id: ctx.idPrefix + edge.id,
            ...(edge.type === 'edge:transition' && typeof (edge as Partial<TransitionEdge>).transitionIndex === 'number'
                ? { 'data-transition-index': (edge as TransitionEdge).transitionIndex }
                : {}),
            class: classes({
                'sprotty-edge': true,
                ...(kind ? { [kind]: true } : {}),
                ...severityClasses((edge as { severity?: unknown }).severity),
                [subType]: true,
            }),
        },
        el('path', { d }),
        arrowHead(route),
        ...ctx.renderChildren(edge),
    );
}

export function labelView(label: SLabel & Partial<MaaLabel>, ctx: ViewContext): XmlElement {
    const type = label.type;
    const cls = `maa-${type.replace(/[^A-Za-z0-9_-]/g, '-')}`;
    const size = sizeOf(label);
    const h = size.height > 0 ? size.height : 16;
    const w = size.width > 0 ? size.width : Math.ceil(label.text.length * 7) + 4;
    // The server lays out label boxes (top left): the baseline about three quarters down the box.
    const y = Math.round(h * 0.75);
    const common = { id: ctx.idPrefix + label.id, transform: translate(label) };
    // Labels are registered as `label:text` in the IDE: Sprotty adds the sub-type class `text`.
    if (type === 'label:badge') {
        const text = BADGE_TEXT[label.text] ?? label.text;
        return el(
            'g',
            {
                ...common,
                class: classes({ 'maa-badge': true, [`maa-badge-${label.text}`]: true, 'maa-label': true, [cls]: true, text: true }),
            },
            el('title', {}, `behavior: ${text}`),
            el('rect', { x: 0, y: 1, width: w, height: h - 2, rx: (h - 2) / 2, ry: (h - 2) / 2 }),
            el('text', { x: w / 2, y: y - 1, 'text-anchor': 'middle' }, text),
        );
    }
    const full = typeof label.fullText === 'string' && label.fullText !== label.text ? label.fullText : undefined;
    // A behavior line that opens the automaton view is a link in the IDE (label-view.ts behaviorLink).
    if (label.opens === 'automaton')
        return el(
            'text',
            { ...common, class: `sprotty-label maa-label ${cls} maa-behavior-link text`, y },
            el('title', {}, 'open the automaton view'),
            label.text,
        );
    if (full === undefined) return el('text', { ...common, class: `sprotty-label maa-label ${cls} text`, y }, label.text);
    return el(
        'text',
        { ...common, class: `sprotty-label maa-label maa-label-shortened ${cls} text`, y, 'data-full-text': full },
        el('title', {}, full),
        label.text,
    );
}

/** An element of another type: a node's box, an edge's line, a compartment's group (Sprotty's generic views). */
export function genericView(element: SModelElement, ctx: ViewContext): XmlElement | undefined {
    const kind = element.type.split(':')[0];
    if (kind === 'edge') return edgeView(element as SEdge, ctx);
    const id = ctx.idPrefix + element.id;
    if (kind === 'node') {
        const { width, height } = sizeOf(element);
        return el(
            'g',
            { id, class: 'generic', transform: translate(element) },
            el('rect', { class: 'sprotty-node', x: 0, y: 0, width, height }),
            ...ctx.renderChildren(element),
        );
    }
    return el('g', { id, class: 'default', transform: translate(element) }, ...ctx.renderChildren(element));
}
