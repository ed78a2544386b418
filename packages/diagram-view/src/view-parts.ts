/**
 * What the diagram's views share: the state they read from the mounted diagram ({@link ViewState}),
 * badge texts, severity classes, text metrics and polyline geometry. CSS classes per docs/ide.md
 * "DOM hooks".
 */
import { setClass, svg, type SModelElementImpl, type SParentElementImpl } from 'sprotty';
import type { DiagramHighlight } from './highlight.js';
import type { ComponentNode, ConnectorEdge, MaaPort } from './model.js';

export type VNode = ReturnType<typeof svg>;
export interface Point {
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
    /** The highlighted trace point of an instance (C&C view: its state chip). */
    highlightOf(instancePath: string | undefined): DiagramHighlight | undefined;
    /** The highlighted trace point of the automaton shown in the automaton view. */
    automatonHighlight(): DiagramHighlight | undefined;
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

export function severityClasses(vnode: VNode, severity: unknown): void {
    setClass(vnode, 'maa-error', severity === 'error');
    setClass(vnode, 'maa-warning', severity === 'warning');
}

export function textWidth(text: string, charWidth = 6): number {
    return Math.ceil(text.length * charWidth);
}

/** `text` cut short with `…` so that it takes at most `width` pixels at `charWidth` a character. */
export function fitText(text: string, width: number, charWidth: number): string {
    const max = Math.max(1, Math.floor(width / charWidth));
    return text.length <= max ? text : `${text.slice(0, Math.max(0, max - 1))}…`;
}

export function isLabelType(el: SModelElementImpl): boolean {
    const t = ((el as unknown as { maaType?: string }).maaType ?? el.type) as string;
    return t.startsWith('label');
}

/** Whether the node brings its own labels (in itself or its compartments). */
export function hasOwnLabels(node: SParentElementImpl): boolean {
    for (const c of node.children) {
        if (isLabelType(c)) return true;
        if (c.type.startsWith('comp') && 'children' in c && (c as SParentElementImpl).children.some(isLabelType)) return true;
    }
    return false;
}

/**
 * The port path whose value a connector carries: its `sourcePortPath`, or, when that is empty
 * (e.g. a connector from an in port of the shown component, fed from outside), the path of its
 * source port.
 */
export function connectorPortPath(edge: Readonly<ConnectorEdge>): string | undefined {
    if (edge.sourcePortPath) return edge.sourcePortPath;
    const source = edge.source as MaaPort | undefined;
    return source && source.type === 'port' && source.direction === 'in' ? source.portPath : undefined;
}

/**
 * The live value a connector carries: that of {@link connectorPortPath}; for a connector from an
 * in port of the shown component without a value of its own, that of its target port (the same
 * topic: on ROS 2 the topic map names the in ports reading a topic fed from outside, not the
 * root's port).
 */
export function connectorValue(state: ViewState, edge: Readonly<ConnectorEdge>): string | undefined {
    const value = state.liveValue(connectorPortPath(edge));
    if (value !== undefined || edge.sourcePortPath) return value;
    const target = edge.target as MaaPort | undefined;
    return target && target.type === 'port' ? state.liveValue(target.portPath) : undefined;
}

/** Whether the server sent a `label:badge` child (then the label view draws the badge). */
export function hasBadgeLabel(node: SParentElementImpl): boolean {
    return node.children.some((c) => ((c as unknown as { maaType?: string }).maaType ?? c.type) === 'label:badge');
}

export function polylineMidpoint(points: readonly Point[]): { p: Point; angle: number } | undefined {
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

export function arrowHead(segments: readonly Point[], cls: string): VNode[] {
    if (segments.length < 2) return [];
    const p = segments[segments.length - 1]!;
    const q = segments[segments.length - 2]!;
    const angle = (Math.atan2(p.y - q.y, p.x - q.x) * 180) / Math.PI;
    return [
        svg('path', { class: { [cls]: true }, d: 'M 0,0 L -9,-4.5 L -9,4.5 Z', transform: `translate(${p.x},${p.y}) rotate(${angle})` }),
    ];
}

/** A text with a rounded background box, centred on a point. */
export function boxedText(p: Point, text: string, boxClass: string, textClass: string, dy = 0): VNode {
    const w = textWidth(text, 6.2) + 8;
    const h = 14;
    return svg(
        'g',
        { class: { [boxClass]: true }, transform: `translate(${p.x},${p.y + dy})` },
        svg('rect', { x: -w / 2, y: -h / 2, width: w, height: h, rx: 3, ry: 3 }),
        svg('text', { class: { [textClass]: true }, x: 0, y: 4, 'text-anchor': 'middle' }, text),
    );
}

/** The current mode of the component node that declares an element (its parent), if it has one live. */
export function declaringMode(state: ViewState, parent: unknown): string | undefined {
    const owner = parent as Partial<ComponentNode> | undefined;
    return owner?.type === 'node:component' && owner.composed ? state.activeStateOf(owner.instancePath) : undefined;
}
