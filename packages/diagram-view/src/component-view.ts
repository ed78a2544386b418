/** The view of a component node: body, names, behavior badge, live state or mode, expand toggle. */
import { ShapeView, svg, type RenderingContext } from 'sprotty';
import type { ComponentNode } from './model.js';
import { modeActivity } from './schema.js';
import {
    BADGE_TEXT,
    declaringMode,
    hasBadgeLabel,
    hasOwnLabels,
    severityClasses,
    textWidth,
    type VNode,
    type ViewState,
} from './view-parts.js';

type Handlers = Record<string, (e: Event) => void>;

/** The behavior kind a node shows (`composed` for a decomposed one without another). */
function kindOf(node: Readonly<ComponentNode>): string {
    return node.behaviorKind ?? (node.composed ? 'composed' : '');
}

/** Title, body and, when the server sent no labels, name and type. */
function bodyParts(node: Readonly<ComponentNode>, w: number, h: number): VNode[] {
    const parts: VNode[] = [
        svg(
            'title',
            {},
            `${node.name ?? node.id}: ${node.componentType ?? ''}${node.variationPoint ? ` (variation point: varif (${node.variationPoint}))` : ''}`,
        ),
        svg('rect', { class: { 'maa-component-body': true }, x: 0, y: 0, width: w, height: h, rx: 6, ry: 6 }),
    ];
    if (!hasOwnLabels(node)) {
        parts.push(svg('text', { class: { 'maa-component-name': true }, x: 8, y: 16 }, node.name ?? ''));
        if (node.componentType)
            parts.push(svg('text', { class: { 'maa-component-type': true }, x: 8, y: 30 }, node.componentType.split('.').pop() ?? ''));
    }
    return parts;
}

/** The behavior badge at the top right, unless the server sent a `label:badge`. */
function badgePart(node: Readonly<ComponentNode>, kind: string, w: number): VNode | undefined {
    const badge = hasBadgeLabel(node) ? undefined : BADGE_TEXT[kind];
    if (!badge) return undefined;
    const bw = textWidth(badge, 5.2) + 10;
    return svg(
        'g',
        { class: { 'maa-badge': true, [`maa-badge-${kind}`]: true }, transform: `translate(${w - bw - 6},-7)` },
        svg('title', {}, `behavior: ${badge}`),
        svg('rect', { x: 0, y: 0, width: bw, height: 14, rx: 7, ry: 7 }),
        svg('text', { x: bw / 2, y: 10, 'text-anchor': 'middle' }, badge),
    );
}

/** The expand/collapse toggle of a decomposed subcomponent, in the header right of the type (the server's layout keeps that room free). */
function expandToggle(path: string, expanded: boolean, w: number, state: ViewState): VNode {
    return svg(
        'g',
        {
            class: { 'maa-expand-toggle': true },
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
    );
}

/** A double click on a subcomponent with an automaton or a mode automaton opens it. */
function openHandlers(node: Readonly<ComponentNode>, kind: string, isRoot: boolean, state: ViewState): Handlers {
    const on: Handlers = {};
    if ((kind === 'automaton' || node.modeAutomaton) && node.componentType && !isRoot) {
        const type = node.componentType;
        on['dblclick'] = (e: Event) => {
            e.stopPropagation();
            state.openAutomaton(type);
        };
    }
    return on;
}

export function componentView(state: ViewState): new () => ShapeView {
    return class ComponentView extends ShapeView {
        override render(node: Readonly<ComponentNode>, context: RenderingContext): VNode | undefined {
            if (!this.isVisible(node, context)) return undefined;
            const w = Math.max(node.size.width, 0);
            const h = Math.max(node.size.height, 0);
            const kind = kindOf(node);
            const isRoot = !node.instancePath;
            const parts = bodyParts(node, w, h);
            const badge = badgePart(node, kind, w);
            if (badge) parts.push(badge);
            // The current state or mode is drawn in the room the server's layout keeps for it (label-view.ts, `label:chip`).
            // A decomposed component's live state is its current mode (mode automata).
            const currentMode = node.composed ? state.activeStateOf(node.instancePath) : undefined;
            if (node.composed && !isRoot && node.instancePath) parts.push(expandToggle(node.instancePath, !!node.expanded, w, state));
            const inMode = modeActivity(node.mode, node.mode ? declaringMode(state, node.parent) : undefined);
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
                    on: openHandlers(node, kind, isRoot, state),
                },
                ...parts,
                ...context.renderChildren(node),
            );
            severityClasses(vnode, node.severity);
            return vnode;
        }
    };
}
