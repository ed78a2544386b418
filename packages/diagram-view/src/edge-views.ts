/** The views of connectors (live values at their middle), transitions and other edges. */
import { PolylineEdgeView, setAttr, setClass, svg, type IViewArgs, type RenderingContext, type SEdgeImpl } from 'sprotty';
import type { ConnectorEdge, TransitionEdge } from './model.js';
import { modeActivity } from './schema.js';
import {
    arrowHead,
    connectorValue,
    declaringMode,
    hasOwnLabels,
    polylineMidpoint,
    severityClasses,
    type Point,
    type VNode,
    type ViewState,
} from './view-parts.js';

export function connectorView(state: ViewState): new () => PolylineEdgeView {
    return class ConnectorView extends PolylineEdgeView {
        override render(edge: Readonly<ConnectorEdge>, context: RenderingContext, args?: IViewArgs): VNode | undefined {
            const vnode = super.render(edge, context, args);
            if (vnode) {
                setClass(vnode, 'maa-connector', true);
                setClass(vnode, 'maa-connector-live', connectorValue(state, edge) !== undefined);
                const inMode = modeActivity(edge.mode, edge.mode ? declaringMode(state, edge.parent) : undefined);
                setClass(vnode, 'maa-mode-active', inMode === 'active');
                setClass(vnode, 'maa-mode-inactive', inMode === 'inactive');
                severityClasses(vnode, edge.severity);
            }
            return vnode;
        }

        protected override renderAdditionals(_edge: SEdgeImpl, segments: Point[], _context: RenderingContext): VNode[] {
            // The value a connector carries is drawn beside its source port (label-view.ts, `label:value`).
            return arrowHead(segments, 'maa-arrow');
        }
    };
}

export function transitionView(state: ViewState): new () => PolylineEdgeView {
    return class TransitionView extends PolylineEdgeView {
        override render(edge: Readonly<TransitionEdge>, context: RenderingContext, args?: IViewArgs): VNode | undefined {
            const vnode = super.render(edge, context, args);
            if (vnode) {
                setClass(vnode, 'maa-transition', true);
                // The transition a highlighted trace point took (its index in allTransitions order).
                const taken = state.automatonHighlight()?.transition;
                setClass(vnode, 'maa-transition-highlight', taken !== undefined && taken.index === edge.transitionIndex);
                if (edge.transitionIndex !== undefined) setAttr(vnode, 'data-transition-index', edge.transitionIndex);
                severityClasses(vnode, edge.severity);
            }
            return vnode;
        }

        protected override renderAdditionals(edge: SEdgeImpl, segments: Point[], _context: RenderingContext): VNode[] {
            const out = arrowHead(segments, 'maa-arrow');
            const t = edge as TransitionEdge;
            if (t.label && !hasOwnLabels(edge)) {
                const mid = polylineMidpoint(segments);
                if (mid)
                    out.push(
                        svg(
                            'text',
                            { class: { 'maa-transition-label': true }, x: mid.p.x, y: mid.p.y - 5, 'text-anchor': 'middle' },
                            t.label,
                        ),
                    );
            }
            return out;
        }
    };
}

export function genericEdgeView(): new () => PolylineEdgeView {
    return class GenericEdgeView extends PolylineEdgeView {
        protected override renderAdditionals(_edge: SEdgeImpl, segments: Point[], _context: RenderingContext): VNode[] {
            return arrowHead(segments, 'maa-arrow');
        }
    };
}
