/** The views of the graph, ports, automaton states, compartments and other nodes. */
import { RectangularNodeView, SCompartmentView, SGraphView, ShapeView, setClass, svg, type RenderingContext } from 'sprotty';
import type { MaaGraph, MaaPort, StateNode } from './model.js';
import { stateActivity } from './schema.js';
import { hasOwnLabels, severityClasses, type VNode, type ViewState } from './view-parts.js';

export function graphView(): new () => SGraphView {
    return class GraphView extends SGraphView {
        override render(model: Readonly<MaaGraph>, context: RenderingContext): VNode {
            const vnode = super.render(model, context);
            setClass(vnode, 'maa-graph', true);
            setClass(vnode, 'maa-graph-automaton', model.diagramType === 'maa-automaton');
            return vnode;
        }
    };
}

export function portView(state: ViewState): new () => ShapeView {
    return class PortView extends ShapeView {
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
                    class: {
                        'maa-port': true,
                        [`maa-port-${dir}`]: true,
                        'maa-port-live': value !== undefined,
                        'maa-variable': !!port.variationPoint,
                        selected: port.selected,
                        mouseover: port.hoverFeedback,
                    },
                    'data-port-path': port.portPath ?? '',
                },
                svg('title', {}, title),
                svg('rect', { class: { 'maa-port-shape': true }, x: 0, y: 0, width: w, height: h }),
                ...context.renderChildren(port),
            );
            severityClasses(vnode, port.severity);
            return vnode;
        }
    };
}

export function stateView(state: ViewState): new () => ShapeView {
    return class StateView extends ShapeView {
        override render(node: Readonly<StateNode>, context: RenderingContext): VNode | undefined {
            if (!this.isVisible(node, context)) return undefined;
            const w = node.size.width;
            const h = node.size.height;
            const activity = stateActivity(node.statePath ?? node.name, state.automatonActiveState());
            const highlighted = stateActivity(node.statePath ?? node.name, state.automatonHighlight()?.state) === 'active';
            const parts: VNode[] = [
                svg('title', {}, node.statePath ?? node.name ?? ''),
                svg('rect', { class: { 'maa-state-body': true }, x: 0, y: 0, width: w, height: h, rx: 10, ry: 10 }),
            ];
            if (!hasOwnLabels(node))
                parts.push(svg('text', { class: { 'maa-state-name': true }, x: w / 2, y: 16, 'text-anchor': 'middle' }, node.name ?? ''));
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
                        'maa-state-highlight': highlighted,
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
    };
}

export function compartmentView(): new () => SCompartmentView {
    return class CompartmentView extends SCompartmentView {};
}

export function genericNodeView(): new () => RectangularNodeView {
    return class GenericNodeView extends RectangularNodeView {};
}
