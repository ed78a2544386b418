/**
 * The Sprotty container of one mounted diagram: the element types with their model classes and
 * views (views.ts), the viewer options, the diagram's commands and the selection handler.
 */
import { Container, ContainerModule } from 'inversify';
import {
    SCompartmentImpl,
    SEdgeImpl,
    SLabelImpl,
    SNodeImpl,
    TYPES,
    configureActionHandler,
    configureCommand,
    configureModelElement,
    configureViewerOptions,
    edgeLayoutFeature,
    editFeature,
    loadDefaultModules,
    moveFeature,
    popupFeature,
    updateModule,
    type IActionDispatcher,
    type IActionHandler,
} from 'sprotty';
import { SelectAction } from 'sprotty-protocol';
import { ClearHiddenCommand, GuardedUpdateModelCommand, RedrawCommand } from './commands.js';
import { ComponentNode, ConnectorEdge, MaaGraph, MaaPort, StateNode, TransitionEdge } from './model.js';
import { CachedSModelFactory } from './model-factory.js';
import { MaaDiagramProxy } from './proxy.js';
import { StandaloneSvgExporter } from './svg-exporter.js';
import type { createViews } from './views.js';

export const ZOOM_LIMITS = { min: 0.01, max: 5 };
const SELECTION_HANDLER = Symbol('MaaSelectionHandler');

export interface DiagramContainer {
    proxy: MaaDiagramProxy;
    dispatcher: IActionDispatcher;
}

/** A container rendering into the element with id `baseDiv` (hidden and popup divs next to it). */
export function createDiagramContainer(
    baseDiv: string,
    views: ReturnType<typeof createViews>,
    selectionHandler: IActionHandler,
): DiagramContainer {
    const diagramModule = new ContainerModule((bind, unbind, isBound, rebind) => {
        const context = { bind, unbind, isBound, rebind };
        bind(TYPES.ModelSource).to(MaaDiagramProxy).inSingletonScope();
        rebind(TYPES.SvgExporter).to(StandaloneSvgExporter).inSingletonScope();
        rebind(TYPES.IModelFactory).to(CachedSModelFactory).inSingletonScope();
        const fixed = { disable: [moveFeature, popupFeature] };
        const fixedEdge = { disable: [moveFeature, editFeature, popupFeature] };
        configureModelElement(context, 'graph', MaaGraph, views.GraphView);
        configureModelElement(context, 'node:component', ComponentNode, views.ComponentView, fixed);
        configureModelElement(context, 'port', MaaPort, views.PortView, fixed);
        configureModelElement(context, 'edge:connector', ConnectorEdge, views.ConnectorView, fixedEdge);
        configureModelElement(context, 'node:state', StateNode, views.StateView, fixed);
        configureModelElement(context, 'edge:transition', TransitionEdge, views.TransitionView, fixedEdge);
        // Labels stand where the server's layout put them: without the edge-layout feature, Sprotty
        // would re-place the transition labels (ELK edge labels) at the middle of their edges.
        configureModelElement(context, 'label:text', SLabelImpl, views.LabelView, {
            disable: [moveFeature, popupFeature, edgeLayoutFeature],
        });
        configureModelElement(context, 'comp:default', SCompartmentImpl, views.CompartmentView, fixed);
        configureModelElement(context, 'node:generic', SNodeImpl, views.GenericNodeView, fixed);
        configureModelElement(context, 'edge:generic', SEdgeImpl, views.GenericEdgeView, fixedEdge);
        configureViewerOptions(context, {
            needsClientLayout: false,
            needsServerLayout: true,
            baseDiv,
            hiddenDiv: `${baseDiv}-hidden`,
            popupDiv: `${baseDiv}-popup`,
            zoomLimits: ZOOM_LIMITS,
        });
        // In place of Sprotty's updateModule (excluded below): see GuardedFadeAnimation.
        configureCommand(context, GuardedUpdateModelCommand);
        configureCommand(context, RedrawCommand);
        configureCommand(context, ClearHiddenCommand);
        bind(SELECTION_HANDLER).toConstantValue(selectionHandler);
        configureActionHandler(context, SelectAction.KIND, SELECTION_HANDLER);
    });
    const di = new Container();
    loadDefaultModules(di, { exclude: [updateModule] });
    di.load(diagramModule);
    const proxy = di.get<MaaDiagramProxy>(TYPES.ModelSource);
    proxy.clientId = baseDiv;
    return { proxy, dispatcher: di.get<IActionDispatcher>(TYPES.IActionDispatcher) };
}
