/**
 * Views of the diagram's element types. They are created per mounted diagram
 * ({@link createViews}) so that they can read the live decorations (values, active states,
 * expansion) of that diagram. CSS classes per docs/ide.md "DOM hooks".
 */
import { decorate, injectable } from 'inversify';
import {
    PolylineEdgeView,
    RectangularNodeView,
    SCompartmentView,
    SGraphView,
    SLabelView,
    ShapeView,
    setClass,
    svg,
    type IViewArgs,
    type RenderingContext,
    type SEdgeImpl,
    type SLabelImpl,
    type SModelElementImpl,
    type SParentElementImpl,
} from 'sprotty';
import { stateActivity } from './schema.js';
import { modeActivity } from '../simulate/states.js';
import type { ComponentNode, ConnectorEdge, MaaGraph, MaaPort, StateNode, TransitionEdge } from './model.js';

type VNode = ReturnType<typeof svg>;
interface Point {
    x: number;
    y: number;
}

/** What the views read from the mounted diagram. */
export interface ViewState {
    liveValue(portPath: string | undefined): string | undefined;
    /** Active state of an instance (C&C view). */
    activeStateOf(instancePath: string | undefined): string | undefined;
    /** Active state path of the automaton shown in the automaton view. */
    automatonActiveState(): string | undefined;
    toggleExpanded(instancePath: string): void;
    openAutomaton(componentType: string): void;
}

export const BADGE_TEXT: Record<string, string> = {
    automaton: 'automaton',
    robotarm: 'RobotArm',
    compute: 'compute',
    handwritten: 'handwritten',
    composed: 'composed',
};

function severityClasses(vnode: VNode, severity: unknown): void {
    setClass(vnode, 'maa-error', severity === 'error');
    setClass(vnode, 'maa-warning', severity === 'warning');
}

function textWidth(text: string, charWidth = 6): number {
    return Math.ceil(text.length * charWidth);
}

function isLabelType(el: SModelElementImpl): boolean {
    const t = ((el as unknown as { maaType?: string }).maaType ?? el.type) as string;
    return t.startsWith('label');
}

/** Whether the node brings its own labels (in itself or its compartments). */
function hasOwnLabels(node: SParentElementImpl): boolean {
    for (const c of node.children) {
        if (isLabelType(c)) return true;
        if (c.type.startsWith('comp') && 'children' in c && (c as SParentElementImpl).children.some(isLabelType)) return true;
    }
    return false;
}

/**
 * The port path whose value a connector carries: its `sourcePortPath`, or, when that is empty
 * (e.g. a connector from an in port of the shown component, whose topic is `/<root>/<port>`),
 * the path of its source port.
 */
function connectorPortPath(edge: Readonly<ConnectorEdge>): string | undefined {
    if (edge.sourcePortPath) return edge.sourcePortPath;
    const source = edge.source as MaaPort | undefined;
    return source && source.type === 'port' && source.direction === 'in' ? source.portPath : undefined;
}

/** Whether the server sent a `label:badge` child (then the label view draws the badge). */
function hasBadgeLabel(node: SParentElementImpl): boolean {
    return node.children.some((c) => ((c as unknown as { maaType?: string }).maaType ?? c.type) === 'label:badge');
}

function polylineMidpoint(points: readonly Point[]): { p: Point; angle: number } | undefined {
    if (points.length < 2) return undefined;
    let total = 0;
    for (let i = 1; i < points.length; i++) total += Math.hypot(points[i]!.x - points[i - 1]!.x, points[i]!.y - points[i - 1]!.y);
    let half = total / 2;
    for (let i = 1; i < points.length; i++) {
        const a = points[i - 1]!;
        const b = points[i]!;
        const len = Math.hypot(b.x - a.x, b.y - a.y);
        if (len >= half && len > 0) {
            const f = half / len;
            return { p: { x: a.x + (b.x - a.x) * f, y: a.y + (b.y - a.y) * f }, angle: Math.atan2(b.y - a.y, b.x - a.x) };
        }
        half -= len;
    }
    return { p: points[points.length - 1]!, angle: 0 };
}

function arrowHead(segments: readonly Point[], cls: string): VNode[] {
    if (segments.length < 2) return [];
    const p = segments[segments.length - 1]!;
    const q = segments[segments.length - 2]!;
    const angle = (Math.atan2(p.y - q.y, p.x - q.x) * 180) / Math.PI;
    return [svg('path', { class: { [cls]: true }, d: 'M 0,0 L -9,-4.5 L -9,4.5 Z', transform: `translate(${p.x},${p.y}) rotate(${angle})` })];
}

/** A text with a rounded background box, centred on a point. */
function boxedText(p: Point, text: string, boxClass: string, textClass: string, dy = 0): VNode {
    const w = textWidth(text, 6.2) + 8;
    const h = 14;
    return svg(
        'g',
        { class: { [boxClass]: true }, transform: `translate(${p.x},${p.y + dy})` },
        svg('rect', { x: -w / 2, y: -h / 2, width: w, height: h, rx: 3, ry: 3 }),
        svg('text', { class: { [textClass]: true }, x: 0, y: 4, 'text-anchor': 'middle' }, text),
    );
}

export interface ViewClasses {
    GraphView: new () => SGraphView;
    ComponentView: new () => ShapeView;
    PortView: new () => ShapeView;
    ConnectorView: new () => PolylineEdgeView;
    StateView: new () => ShapeView;
    TransitionView: new () => PolylineEdgeView;
    LabelView: new () => SLabelView;
    CompartmentView: new () => SCompartmentView;
    GenericNodeView: new () => RectangularNodeView;
    GenericEdgeView: new () => PolylineEdgeView;
}

export function createViews(state: ViewState): ViewClasses {
    /** The current mode of the component node that declares an element (its parent), if it has one live. */
    const modeOf = (parent: unknown): string | undefined => {
        const owner = parent as Partial<ComponentNode> | undefined;
        return owner?.type === 'node:component' && owner.composed ? state.activeStateOf(owner.instancePath) : undefined;
    };

    class GraphView extends SGraphView {
        override render(model: Readonly<MaaGraph>, context: RenderingContext): VNode {
            const vnode = super.render(model, context);
            setClass(vnode, 'maa-graph', true);
            setClass(vnode, 'maa-graph-automaton', model.diagramType === 'maa-automaton');
            return vnode;
        }
    }

    class ComponentView extends ShapeView {
        override render(node: Readonly<ComponentNode>, context: RenderingContext): VNode | undefined {
            if (!this.isVisible(node, context)) return undefined;
            const w = Math.max(node.size.width, 0);
            const h = Math.max(node.size.height, 0);
            const kind = node.behaviorKind ?? (node.composed ? 'composed' : '');
            const isRoot = !node.instancePath;
            const parts: VNode[] = [
                svg('title', {}, `${node.name ?? node.id}: ${node.componentType ?? ''}${node.variationPoint ? ` (variation point: varif (${node.variationPoint}))` : ''}`),
                svg('rect', { class: { 'maa-component-body': true }, x: 0, y: 0, width: w, height: h, rx: 6, ry: 6 }),
            ];
            if (!hasOwnLabels(node)) {
                parts.push(svg('text', { class: { 'maa-component-name': true }, x: 8, y: 16 }, node.name ?? ''));
                if (node.componentType) parts.push(svg('text', { class: { 'maa-component-type': true }, x: 8, y: 30 }, node.componentType.split('.').pop() ?? ''));
            }
            const badge = hasBadgeLabel(node) ? undefined : BADGE_TEXT[kind];
            if (badge) {
                const bw = textWidth(badge, 5.2) + 10;
                parts.push(
                    svg(
                        'g',
                        { class: { 'maa-badge': true, [`maa-badge-${kind}`]: true }, transform: `translate(${w - bw - 6},-7)` },
                        svg('title', {}, `behavior: ${badge}`),
                        svg('rect', { x: 0, y: 0, width: bw, height: 14, rx: 7, ry: 7 }),
                        svg('text', { x: bw / 2, y: 10, 'text-anchor': 'middle' }, badge),
                    ),
                );
            }
            const active = kind === 'automaton' ? state.activeStateOf(node.instancePath) : undefined;
            if (active) {
                parts.push(boxedText({ x: w / 2, y: h - 10 }, `▶ ${active}`, 'maa-current-state', 'maa-state-active'));
            }
            // A decomposed component's live state is its current mode (mode automata).
            const currentMode = node.composed ? state.activeStateOf(node.instancePath) : undefined;
            if (currentMode) {
                parts.push(boxedText({ x: w / 2, y: h - 10 }, `▶ mode ${currentMode}`, 'maa-current-mode', 'maa-mode-current'));
            }
            const inMode = modeActivity(node.mode, node.mode ? modeOf(node.parent) : undefined);
            if (node.composed && !isRoot && node.instancePath) {
                const path = node.instancePath;
                const expanded = !!node.expanded;
                parts.push(
                    svg(
                        'g',
                        {
                            class: { 'maa-expand-toggle': true },
                            // In the header, right of the type: the server's layout keeps that room free.
                            transform: `translate(${w - 20},20)`,
                            'data-instance-path': path,
                            on: {
                                mousedown: (e: Event) => e.stopPropagation(),
                                click: (e: Event) => {
                                    e.stopPropagation();
                                    state.toggleExpanded(path);
                                },
                            },
                        },
                        svg('title', {}, expanded ? 'collapse' : 'expand'),
                        svg('rect', { x: 0, y: 0, width: 14, height: 14, rx: 2, ry: 2 }),
                        svg('path', { d: expanded ? 'M 3,7 L 11,7' : 'M 3,7 L 11,7 M 7,3 L 7,11' }),
                    ),
                );
            }
            const on: Record<string, (e: Event) => void> = {};
            if ((kind === 'automaton' || node.modeAutomaton) && node.componentType && !isRoot) {
                const type = node.componentType;
                on['dblclick'] = (e: Event) => {
                    e.stopPropagation();
                    state.openAutomaton(type);
                };
            }
            const vnode = svg(
                'g',
                {
                    class: {
                        'maa-component': true,
                        'maa-root': isRoot,
                        'maa-composed': !!node.composed,
                        'maa-expanded': !!node.expanded,
                        'maa-variable': !!node.variationPoint,
                        'maa-mode-active': inMode === 'active',
                        'maa-mode-inactive': inMode === 'inactive',
                        [`maa-kind-${kind || 'none'}`]: true,
                        selected: node.selected,
                        mouseover: node.hoverFeedback,
                    },
                    'data-instance-path': node.instancePath ?? '',
                    ...(node.mode ? { 'data-mode': node.mode } : {}),
                    ...(currentMode ? { 'data-current-mode': currentMode } : {}),
                    on,
                },
                ...parts,
                ...context.renderChildren(node),
            );
            severityClasses(vnode, node.severity);
            return vnode;
        }
    }

    class PortView extends ShapeView {
        override render(port: Readonly<MaaPort>, context: RenderingContext): VNode | undefined {
            if (!this.isVisible(port, context)) return undefined;
            const w = port.size.width > 0 ? port.size.width : 8;
            const h = port.size.height > 0 ? port.size.height : 8;
            const dir = port.direction === 'out' ? 'out' : 'in';
            const value = state.liveValue(port.portPath);
            const title = `${port.name ?? port.id}: ${port.portType ?? ''}${dir === 'in' ? ' (in)' : ' (out)'}${value !== undefined ? ` = ${value}` : ''}${port.variationPoint ? ` (variation point: varif (${port.variationPoint}))` : ''}`;
            const vnode = svg(
                'g',
                {
                    class: { 'maa-port': true, [`maa-port-${dir}`]: true, 'maa-port-live': value !== undefined, 'maa-variable': !!port.variationPoint, selected: port.selected, mouseover: port.hoverFeedback },
                    'data-port-path': port.portPath ?? '',
                },
                svg('title', {}, title),
                svg('rect', { class: { 'maa-port-shape': true }, x: 0, y: 0, width: w, height: h }),
                ...context.renderChildren(port),
            );
            severityClasses(vnode, port.severity);
            return vnode;
        }
    }

    class ConnectorView extends PolylineEdgeView {
        override render(edge: Readonly<ConnectorEdge>, context: RenderingContext, args?: IViewArgs): VNode | undefined {
            const vnode = super.render(edge, context, args);
            if (vnode) {
                setClass(vnode, 'maa-connector', true);
                setClass(vnode, 'maa-connector-live', state.liveValue(connectorPortPath(edge)) !== undefined);
                const inMode = modeActivity(edge.mode, edge.mode ? modeOf(edge.parent) : undefined);
                setClass(vnode, 'maa-mode-active', inMode === 'active');
                setClass(vnode, 'maa-mode-inactive', inMode === 'inactive');
                severityClasses(vnode, edge.severity);
            }
            return vnode;
        }

        protected override renderAdditionals(edge: SEdgeImpl, segments: Point[], _context: RenderingContext): VNode[] {
            const out = arrowHead(segments, 'maa-arrow');
            const value = state.liveValue(connectorPortPath(edge as ConnectorEdge));
            if (value !== undefined) {
                const mid = polylineMidpoint(segments);
                if (mid) {
                    out.push(
                        svg(
                            'g',
                            { class: { 'maa-value-label': true }, transform: `translate(${mid.p.x},${mid.p.y - 9})` },
                            svg('rect', { x: -(textWidth(value, 6.2) + 8) / 2, y: -7, width: textWidth(value, 6.2) + 8, height: 14, rx: 3, ry: 3 }),
                            svg('text', { class: { 'maa-value': true }, x: 0, y: 4, 'text-anchor': 'middle' }, value),
                        ),
                    );
                }
            }
            return out;
        }
    }

    class StateView extends ShapeView {
        override render(node: Readonly<StateNode>, context: RenderingContext): VNode | undefined {
            if (!this.isVisible(node, context)) return undefined;
            const w = node.size.width;
            const h = node.size.height;
            const activity = stateActivity(node.statePath ?? node.name, state.automatonActiveState());
            const parts: VNode[] = [
                svg('title', {}, node.statePath ?? node.name ?? ''),
                svg('rect', { class: { 'maa-state-body': true }, x: 0, y: 0, width: w, height: h, rx: 10, ry: 10 }),
            ];
            if (!hasOwnLabels(node)) parts.push(svg('text', { class: { 'maa-state-name': true }, x: w / 2, y: 16, 'text-anchor': 'middle' }, node.name ?? ''));
            if (node.initial) {
                parts.push(
                    svg(
                        'g',
                        { class: { 'maa-initial-marker': true } },
                        svg('circle', { cx: -16, cy: 14, r: 4 }),
                        svg('path', { d: 'M -12,14 L -1,14', 'marker-end': '' }),
                        svg('path', { class: { 'maa-initial-arrow': true }, d: 'M 0,14 L -5,11 L -5,17 Z' }),
                    ),
                );
            }
            const vnode = svg(
                'g',
                {
                    class: {
                        'maa-state': true,
                        'maa-state-initial': !!node.initial,
                        'maa-state-active': activity === 'active',
                        'maa-state-active-parent': activity === 'ancestor',
                        selected: node.selected,
                        mouseover: node.hoverFeedback,
                    },
                    'data-state-path': node.statePath ?? '',
                },
                ...parts,
                ...context.renderChildren(node),
            );
            severityClasses(vnode, node.severity);
            return vnode;
        }
    }

    class TransitionView extends PolylineEdgeView {
        override render(edge: Readonly<TransitionEdge>, context: RenderingContext, args?: IViewArgs): VNode | undefined {
            const vnode = super.render(edge, context, args);
            if (vnode) {
                setClass(vnode, 'maa-transition', true);
                severityClasses(vnode, edge.severity);
            }
            return vnode;
        }

        protected override renderAdditionals(edge: SEdgeImpl, segments: Point[], _context: RenderingContext): VNode[] {
            const out = arrowHead(segments, 'maa-arrow');
            const t = edge as TransitionEdge;
            if (t.label && !hasOwnLabels(edge)) {
                const mid = polylineMidpoint(segments);
                if (mid) out.push(svg('text', { class: { 'maa-transition-label': true }, x: mid.p.x, y: mid.p.y - 5, 'text-anchor': 'middle' }, t.label));
            }
            return out;
        }
    }

    class LabelView extends SLabelView {
        override render(label: Readonly<SLabelImpl>, context: RenderingContext): VNode | undefined {
            if (!this.isVisible(label, context)) return undefined;
            const type = (label as unknown as { maaType?: string }).maaType ?? label.type;
            const cls = `maa-${type.replace(/[^A-Za-z0-9_-]/g, '-')}`;
            const h = label.size.height > 0 ? label.size.height : 16;
            const w = label.size.width > 0 ? label.size.width : textWidth(label.text, 7) + 4;
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
            // a shortened label (a long transition label) carries its whole text for a tooltip
            const fullText = (label as unknown as { fullText?: unknown }).fullText;
            const full = typeof fullText === 'string' && fullText !== label.text ? fullText : undefined;
            if (full === undefined) return svg('text', { class: { 'sprotty-label': true, 'maa-label': true, [cls]: true }, y }, label.text);
            return svg('text', { class: { 'sprotty-label': true, 'maa-label': true, 'maa-label-shortened': true, [cls]: true }, y, 'data-full-text': full }, svg('title', {}, full), label.text);
        }
    }

    class CompartmentView extends SCompartmentView {}
    class GenericNodeView extends RectangularNodeView {}
    class GenericEdgeView extends PolylineEdgeView {
        protected override renderAdditionals(_edge: SEdgeImpl, segments: Point[], _context: RenderingContext): VNode[] {
            return arrowHead(segments, 'maa-arrow');
        }
    }

    const classes: ViewClasses = {
        GraphView,
        ComponentView,
        PortView,
        ConnectorView,
        StateView,
        TransitionView,
        LabelView,
        CompartmentView,
        GenericNodeView,
        GenericEdgeView,
    };
    for (const c of Object.values(classes)) decorate(injectable(), c);
    return classes;
}
