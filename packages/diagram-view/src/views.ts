/**
 * Views of the diagram's element types. They are created per mounted diagram
 * ({@link createViews}) so that they can read the live decorations (values, active states,
 * expansion) of that diagram: component-view.ts, node-views.ts, edge-views.ts, label-view.ts,
 * with what they share in view-parts.ts. CSS classes per docs/ide.md "DOM hooks".
 */
import { decorate, injectable } from 'inversify';
import type { PolylineEdgeView, RectangularNodeView, SCompartmentView, SGraphView, SLabelView, ShapeView } from 'sprotty';
import { componentView } from './component-view.js';
import { connectorView, genericEdgeView, transitionView } from './edge-views.js';
import { labelView } from './label-view.js';
import { compartmentView, genericNodeView, graphView, portView, stateView } from './node-views.js';
import type { ViewState } from './view-parts.js';

export { BADGE_TEXT, type ViewState } from './view-parts.js';

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
    const classes: ViewClasses = {
        GraphView: graphView(),
        ComponentView: componentView(state),
        PortView: portView(state),
        ConnectorView: connectorView(state),
        StateView: stateView(state),
        TransitionView: transitionView(state),
        LabelView: labelView(state),
        CompartmentView: compartmentView(),
        GenericNodeView: genericNodeView(),
        GenericEdgeView: genericEdgeView(),
    };
    for (const c of Object.values(classes)) decorate(injectable(), c);
    return classes;
}
