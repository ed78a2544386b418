/** The views of connectors (live values at their middle), transitions and other edges. */
import { PolylineEdgeView, setClass, svg, type IViewArgs, type RenderingContext, type SEdgeImpl } from 'sprotty';
import type { ConnectorEdge, TransitionEdge } from './model.js';
import { modeActivity } from './schema.js';
import {
    arrowHead,
    connectorValue,
    declaringMode,
    hasOwnLabels,
    polylineMidpoint,
    severityClasses,
    textWidth,
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

        protected override renderAdditionals(edge: SEdgeImpl, segments: Point[], _context: RenderingContext): VNode[] {
            const out = arrowHead(segments, 'maa-arrow');
            const value = connectorValue(state, edge as ConnectorEdge);
            if (value !== undefined) {
                const mid = polylineMidpoint(segments);
                if (mid) {
                    out.push(
                        svg(
                            'g',
                            { class: { 'maa-value-label': true }, transform: `translate(${mid.p.x},${mid.p.y - 9})` },
                            svg('rect', {
                                x: -(textWidth(value, 6.2) + 8) / 2,
                                y: -7,
                                width: textWidth(value, 6.2) + 8,
                                height: 14,
                                rx: 3,
                                ry: 3,
                            }),
                            svg('text', { class: { 'maa-value': true }, x: 0, y: 4, 'text-anchor': 'middle' }, value),
                        ),
                    );
                }
            }
            return out;
        }
    };
}

export function transitionView(): new () => PolylineEdgeView {
    return class TransitionView extends PolylineEdgeView {
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
