/**
 * The Sprotty diagram of the browser IDE: `mountDiagram(container, host)` (contracts.ts).
 *
 * The model comes from the diagram server in the language server worker (langium-sprotty,
 * server-side ELK layout, docs/ide.md "Diagram protocol"); the client only renders it. Action
 * messages travel through the shell's {@link DiagramHost} channel (LSP notifications
 * `diagram/accept`) via {@link MaaDiagramProxy}, a `DiagramServerProxy` over that channel.
 */
import 'reflect-metadata';
import 'sprotty/css/sprotty.css';
import './diagram.css';
import { Container, ContainerModule, decorate, inject, injectable } from 'inversify';
import {
    DiagramServerProxy,
    HiddenCommand,
    SCompartmentImpl,
    SEdgeImpl,
    SLabelImpl,
    SNodeImpl,
    SystemCommand,
    TYPES,
    configureActionHandler,
    configureCommand,
    configureModelElement,
    configureViewerOptions,
    editFeature,
    loadDefaultModules,
    moveFeature,
    edgeLayoutFeature,
    popupFeature,
    type CommandExecutionContext,
    type IActionDispatcher,
    type IActionHandler,
    type SModelRootImpl,
} from 'sprotty';
import {
    CenterAction,
    GetViewportAction,
    RequestExportSvgAction,
    RequestModelAction,
    SelectAction,
    SelectAllAction,
    SetViewportAction,
    type Action,
    type ActionMessage,
    type ExportSvgAction,
    type Viewport,
    type ViewportResult,
} from 'sprotty-protocol';
import type { DiagramHost, DiagramTarget, DiagramView, Disposable, TextPosition } from '../contracts.js';
import {
    ALL_VARIATION_POINTS, chooseFeature, configurationStatus, featureChecked, featuresOption, graphFeatureInfo, showAll, type FeatureSelection
} from './configuration.js';
import { ComponentNode, ConnectorEdge, MaaGraph, MaaPort, StateNode, TransitionEdge } from './model.js';
import {
    absoluteBounds,
    boundsInside,
    activeStateForType,
    instancePrefix,
    instanceTypesOf,
    lookupLiveValue,
    normalizeSchemaTypes,
    portPathsOf,
    shownComponentNode,
    snakePath,
    visibleArea,
    walkSchema,
    type SchemaElement,
} from './schema.js';
import { findInnermostElement, type TracedElement } from './trace.js';
import { fitViewport, unionBounds } from './viewport.js';
import { createViews, type ViewState } from './views.js';

export { parseTrace, findInnermostElement, normalizeUri, rangeContains } from './trace.js';

/** The mounted diagram with the extras the simulate panel uses (duck-typed there). */
export interface MaaDiagramView extends DiagramView {
    /** Port paths of the shown C&C diagram (for topic ↔ port mapping). */
    knownPortPaths(): string[];
    /** Instance paths of the last C&C diagram. */
    knownInstancePaths(): string[];
    /** The target currently shown. */
    currentTarget(): DiagramTarget | undefined;
    /** Called whenever a new model arrived (set or update). */
    onModelChanged(handler: () => void): Disposable;
}

type ModelListener = (root: SchemaElement, kind: string) => void;

/** A `DiagramServerProxy` whose channel is the shell's `DiagramHost`. */
export class MaaDiagramProxy extends DiagramServerProxy {
    private host?: DiagramHost;
    private subscription?: Disposable;
    readonly modelListeners = new Set<ModelListener>();

    connect(host: DiagramHost): void {
        this.host = host;
        this.subscription = host.onDiagramMessage((message) => this.messageReceived(message));
    }

    disconnect(): void {
        this.subscription?.dispose();
        this.subscription = undefined;
        this.host = undefined;
    }

    protected sendMessage(message: ActionMessage): void {
        this.host?.sendDiagramMessage(message);
    }

    protected override messageReceived(data: unknown): void {
        const object = (typeof data === 'string' ? JSON.parse(data) : data) as ActionMessage | undefined;
        const action = object?.action as (Action & { newRoot?: SchemaElement }) | undefined;
        const mine = !object?.clientId || object.clientId === this.clientId;
        if (mine && action && (action.kind === 'setModel' || action.kind === 'updateModel') && action.newRoot) {
            normalizeSchemaTypes(action.newRoot);
            super.messageReceived(object);
            for (const l of [...this.modelListeners]) l(action.newRoot, action.kind);
            return;
        }
        super.messageReceived(object);
    }
}
decorate(injectable(), MaaDiagramProxy);

/** Re-renders the current model (live values and active states changed; the model did not). */
export class RedrawCommand extends SystemCommand {
    static readonly KIND = 'maaRedraw';
    constructor(readonly action: Action) {
        super();
    }
    execute(context: CommandExecutionContext): SModelRootImpl {
        return context.root;
    }
    undo(context: CommandExecutionContext): SModelRootImpl {
        return context.root;
    }
    redo(context: CommandExecutionContext): SModelRootImpl {
        return context.root;
    }
}
decorate(injectable(), RedrawCommand);
decorate(inject(TYPES.Action), RedrawCommand, 0);

/**
 * Empties Sprotty's hidden rendering (the export renders the diagram there, in `document.body`),
 * so that no second copy of the diagram's elements stays in the page.
 */
export class ClearHiddenCommand extends HiddenCommand {
    static readonly KIND = 'maaClearHidden';
    constructor(readonly action: Action) {
        super();
    }
    execute(context: CommandExecutionContext): SModelRootImpl {
        return context.modelFactory.createRoot({ type: 'NONE', id: 'EMPTY' });
    }
    override undo(context: CommandExecutionContext): SModelRootImpl {
        return context.root;
    }
    override redo(context: CommandExecutionContext): SModelRootImpl {
        return context.root;
    }
}
decorate(injectable(), ClearHiddenCommand);
decorate(inject(TYPES.Action), ClearHiddenCommand, 0);

const SELECTION_HANDLER = Symbol('MaaSelectionHandler');
const ZOOM_LIMITS = { min: 0.01, max: 5 };
/** Element types that can be selected (labels and compartments select their parent). */
const SELECTABLE_TYPES = new Set(['node:component', 'port', 'edge:connector', 'node:state', 'edge:transition', 'node:generic', 'edge:generic']);
let mountCounter = 0;

function button(label: string, title: string, testid: string, onClick: () => void): HTMLButtonElement {
    const b = document.createElement('button');
    b.type = 'button';
    b.textContent = label;
    b.title = title;
    b.className = 'maa-diagram-button';
    b.dataset['testid'] = testid;
    b.addEventListener('click', onClick);
    return b;
}

function targetKey(t: DiagramTarget): string {
    return `${t.diagramType}|${t.uri}|${t.component ?? ''}`;
}

/** Mounts the diagram into `container`; the shell calls `show` with what to display. */
export function mountDiagram(container: HTMLElement, host: DiagramHost): MaaDiagramView {
    const n = ++mountCounter;
    const baseDiv = `maa-diagram-${n}`;
    container.dataset['testid'] = 'diagram';
    container.classList.add('maa-diagram');

    const toolbar = document.createElement('div');
    toolbar.className = 'maa-diagram-toolbar';
    const canvas = document.createElement('div');
    canvas.className = 'maa-diagram-canvas';
    const base = document.createElement('div');
    base.id = baseDiv;
    canvas.appendChild(base);
    const empty = document.createElement('div');
    empty.className = 'maa-diagram-empty';
    empty.textContent = 'No diagram yet: open a model file.';
    canvas.appendChild(empty);
    // The feature control of a variable component (configuration.ts), hidden for all others.
    const featureBar = document.createElement('div');
    featureBar.className = 'maa-diagram-features';
    featureBar.dataset['testid'] = 'diagram-features';
    featureBar.hidden = true;
    container.replaceChildren(toolbar, featureBar, canvas);

    // --- state -------------------------------------------------------------------------------
    let liveValues: ReadonlyMap<string, string> = new Map();
    let liveBySnake = new Map<string, string>();
    let activeStates: ReadonlyMap<string, string> = new Map();
    /** Instance types of every C&C diagram seen, by shown component (for live paths and states). */
    const typeMaps = new Map<string, Map<string, string>>();
    /** Port paths of every C&C diagram seen, by shown component. */
    const portPathMaps = new Map<string, string[]>();
    /** The instance path of the shown component in another known diagram (see `instancePrefix`). */
    let prefix: string | undefined;
    let schema: SchemaElement | undefined;
    let current: DiagramTarget | undefined;
    let lastCc: DiagramTarget | undefined;
    let fitPending = false;
    let restoreViewport: Viewport | undefined;
    const expandedByTarget = new Map<string, Set<string>>();
    const selectionByTarget = new Map<string, FeatureSelection>();
    const selectHandlers = new Set<(traces: string[]) => void>();
    const modelHandlers = new Set<() => void>();
    const programmatic = new WeakSet<Action>();
    let disposed = false;

    const expandedOf = (t: DiagramTarget): Set<string> => {
        const k = targetKey(t);
        let s = expandedByTarget.get(k);
        if (!s) expandedByTarget.set(k, (s = new Set()));
        return s;
    };

    const selectionOf = (t: DiagramTarget): FeatureSelection => selectionByTarget.get(targetKey(t)) ?? ALL_VARIATION_POINTS;
    const select = (selection: FeatureSelection): void => {
        if (!current) return;
        selectionByTarget.set(targetKey(current), selection);
        void rememberViewport().then(() => request(false));
    };

    const viewState: ViewState = {
        liveValue: (p) => {
            if (!p || liveValues.size === 0) return undefined;
            return lookupLiveValue(liveValues, liveBySnake, p) ?? (prefix ? lookupLiveValue(liveValues, liveBySnake, `${prefix}.${p}`) : undefined);
        },
        activeStateOf: (p) => {
            if (p === undefined || activeStates.size === 0) return undefined;
            return activeStates.get(p) ?? (prefix ? activeStates.get(p ? `${prefix}.${p}` : prefix) : undefined);
        },
        automatonActiveState: () => {
            if (!current || current.diagramType !== 'maa-automaton' || activeStates.size === 0) return undefined;
            const type = (schema?.['component'] as string | undefined) ?? current.component;
            return activeStateForType(typeMaps, activeStates, type);
        },
        toggleExpanded: (path) => {
            if (!current) return;
            const s = expandedOf(current);
            if (s.has(path)) s.delete(path);
            else s.add(path);
            void rememberViewport().then(() => request(false));
        },
        openAutomaton: (componentType) => {
            if (!current) return;
            view.show({ uri: current.uri, component: componentType, diagramType: 'maa-automaton' });
        },
    };

    const selectionHandler: IActionHandler = {
        handle: (action: Action): void => {
            if (programmatic.has(action) || action.kind !== SelectAction.KIND || !schema) return;
            const ids = new Set((action as SelectAction).selectedElementsIDs);
            if (ids.size === 0) return;
            const traces: string[] = [];
            for (const { el } of walkSchema(schema)) if (ids.has(el.id) && typeof el['trace'] === 'string') traces.push(el['trace'] as string);
            if (traces.length === 0) return;
            // the shell reveals the trace in its onSelect handler; without one, the diagram does
            if (selectHandlers.size > 0) for (const h of [...selectHandlers]) h(traces);
            else host.revealTrace(traces[0]!);
        },
    };

    // --- Sprotty container ---------------------------------------------------------------------
    const views = createViews(viewState);
    const diagramModule = new ContainerModule((bind, unbind, isBound, rebind) => {
        const context = { bind, unbind, isBound, rebind };
        bind(TYPES.ModelSource).to(MaaDiagramProxy).inSingletonScope();
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
        configureModelElement(context, 'label:text', SLabelImpl, views.LabelView, { disable: [moveFeature, popupFeature, edgeLayoutFeature] });
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
        configureCommand(context, RedrawCommand);
        configureCommand(context, ClearHiddenCommand);
        bind(SELECTION_HANDLER).toConstantValue(selectionHandler);
        configureActionHandler(context, SelectAction.KIND, SELECTION_HANDLER);
    });
    const di = new Container();
    loadDefaultModules(di);
    di.load(diagramModule);
    const proxy = di.get<MaaDiagramProxy>(TYPES.ModelSource);
    proxy.clientId = baseDiv;
    const dispatcher = di.get<IActionDispatcher>(TYPES.IActionDispatcher);
    proxy.connect(host);

    const dispatch = (action: Action, own = true): Promise<void> => {
        if (own) programmatic.add(action);
        return dispatcher.dispatch(action).catch((e: unknown) => console.warn('diagram:', e));
    };

    // --- redraw of live decorations, at most once per frame --------------------------------------
    let redrawScheduled = false;
    const scheduleRedraw = (): void => {
        if (redrawScheduled || disposed || !schema) return;
        redrawScheduled = true;
        const run = (): void => {
            redrawScheduled = false;
            if (!disposed && schema) void dispatch({ kind: RedrawCommand.KIND });
        };
        if (typeof requestAnimationFrame === 'function') requestAnimationFrame(run);
        else setTimeout(run, 16);
    };

    // --- model bookkeeping ---------------------------------------------------------------------
    proxy.modelListeners.add((root, kind) => {
        schema = root;
        empty.hidden = true;
        const type = (root['diagramType'] as string | undefined) ?? current?.diagramType;
        const shown = (root['component'] as string | undefined) ?? current?.component ?? '';
        if (type !== 'maa-automaton') {
            typeMaps.set(shown, instanceTypesOf(root));
            portPathMaps.set(shown, portPathsOf(root));
            prefix = instancePrefix(typeMaps, shown);
        }
        updateToolbar();
        if (kind === 'setModel') {
            if (fitPending) {
                fitPending = false;
                // A new diagram opens readable (a huge one from its top); the Fit button shows it all.
                void fit(1.5, false, 0.3);
            } else if (restoreViewport) {
                const vp = restoreViewport;
                void dispatch(SetViewportAction.create(root.id, vp, { animate: false }));
            }
            restoreViewport = undefined;
        }
        for (const h of [...modelHandlers]) h();
    });

    const rememberViewport = async (): Promise<void> => {
        try {
            const res = await dispatcher.request<ViewportResult>(GetViewportAction.create());
            restoreViewport = res.viewport;
        } catch {
            restoreViewport = undefined;
        }
    };

    const request = (fit: boolean): void => {
        if (!current || disposed) return;
        fitPending = fit;
        const options: Record<string, string | boolean | string[] | Record<string, boolean>> = {
            diagramType: current.diagramType,
            sourceUri: current.uri,
            needsClientLayout: false,
            needsServerLayout: true,
            expanded: [...expandedOf(current)].sort(),
        };
        if (current.component) options['component'] = current.component;
        if (current.diagramType === 'maa-cc') {
            const features = featuresOption(selectionOf(current), graphFeatureInfo(schema).features);
            if (features) options['features'] = features;
        }
        void dispatch(RequestModelAction.create(options));
    };

    /** Fits the diagram into the canvas (viewport.ts: also diagrams too large for the minimum zoom). */
    const fit = async (maxZoom: number, animate: boolean, readableZoom?: number): Promise<void> => {
        const root = schema;
        if (!root) return;
        const content = unionBounds((root.children ?? []).map((c) => absoluteBounds(root, c.id)).filter((b) => b !== undefined));
        if (!content) return;
        try {
            const { canvasBounds } = await dispatcher.request<ViewportResult>(GetViewportAction.create());
            const viewport = fitViewport(content, canvasBounds, { padding: 20, maxZoom, minZoom: ZOOM_LIMITS.min, readableZoom });
            await dispatch(SetViewportAction.create(root.id, viewport, { animate }));
        } catch (e) {
            console.warn('diagram fit:', e);
        }
    };

    // --- toolbar -------------------------------------------------------------------------------
    const zoomBy = async (factor: number): Promise<void> => {
        if (!schema) return;
        try {
            const res = await dispatcher.request<ViewportResult>(GetViewportAction.create());
            const { viewport, canvasBounds } = res;
            const zoom = Math.min(ZOOM_LIMITS.max, Math.max(ZOOM_LIMITS.min, viewport.zoom * factor));
            const cx = viewport.scroll.x + canvasBounds.width / 2 / viewport.zoom;
            const cy = viewport.scroll.y + canvasBounds.height / 2 / viewport.zoom;
            const scroll = { x: cx - canvasBounds.width / 2 / zoom, y: cy - canvasBounds.height / 2 / zoom };
            await dispatch(SetViewportAction.create(schema.id, { scroll, zoom }, { animate: true }));
        } catch (e) {
            console.warn('diagram zoom:', e);
        }
    };
    const title = document.createElement('span');
    title.className = 'maa-diagram-title';
    const switchButton = button('Automaton', 'Show the state machine of this component', 'diagram-switch', () => {
        if (!current) return;
        if (current.diagramType === 'maa-cc') {
            const comp = (schema?.['component'] as string | undefined) ?? current.component;
            view.show({ uri: current.uri, component: comp, diagramType: 'maa-automaton' });
        } else if (lastCc) {
            view.show(lastCc);
        } else {
            view.show({ uri: current.uri, diagramType: 'maa-cc' });
        }
    });
    toolbar.append(
        button('Fit', 'Fit the diagram into the view', 'diagram-fit', () => void fit(2, true)),
        button('−', 'Zoom out', 'diagram-zoom-out', () => void zoomBy(1 / 1.25)),
        button('+', 'Zoom in', 'diagram-zoom-in', () => void zoomBy(1.25)),
        button('Export SVG', 'Download the diagram as SVG', 'diagram-export', () => void downloadSvg()),
        switchButton,
        title,
    );

    function updateToolbar(): void {
        const comp = (schema?.['component'] as string | undefined) ?? current?.component ?? '';
        if (current?.diagramType === 'maa-automaton') {
            switchButton.hidden = false;
            switchButton.textContent = 'Architecture';
            switchButton.title = 'Back to the component diagram';
            title.textContent = `${comp.split('.').pop() ?? ''} — automaton`;
        } else {
            const node = schema ? shownComponentNode(schema) : undefined;
            const modes = (node?.['modeAutomaton'] ?? schema?.['modeAutomaton']) === true;
            switchButton.hidden = (node?.['behaviorKind'] ?? schema?.['behaviorKind']) !== 'automaton' && !modes;
            switchButton.textContent = 'Automaton';
            switchButton.title = modes ? 'Show the mode automaton of this component' : 'Show the state machine of this component';
            title.textContent = comp.split('.').pop() ?? '';
        }
        updateFeatureBar();
    }

    /** "All variation points" and a checkbox per feature, for the C&C diagram of a component with features. */
    function updateFeatureBar(): void {
        const info = graphFeatureInfo(current?.diagramType === 'maa-cc' ? schema : undefined);
        featureBar.hidden = info.features.length === 0;
        if (featureBar.hidden || !current) {
            featureBar.replaceChildren();
            return;
        }
        const selection = selectionOf(current);
        const checkbox = (text: string, testid: string, checked: boolean, title: string, onChange: (checked: boolean) => void): HTMLLabelElement => {
            const label = document.createElement('label');
            label.className = 'maa-diagram-feature';
            label.title = title;
            const input = document.createElement('input');
            input.type = 'checkbox';
            input.checked = checked;
            input.dataset['testid'] = testid;
            input.addEventListener('change', () => onChange(input.checked));
            label.append(input, text);
            return label;
        };
        const items: HTMLElement[] = [
            checkbox('All variation points', 'diagram-features-all', selection.all, 'Show every variation point (varif) with its condition', (all) => select(showAll(selection, all))),
        ];
        for (const f of info.features) {
            const box = checkbox(f, `diagram-feature-${f}`, featureChecked(info, selection, f), `Feature ${f}: checked shows a configuration with it, unchecked one without`,
                (value) => select(chooseFeature(selection, f, value)));
            if (selection.all) box.classList.add('maa-diagram-feature-inactive');
            items.push(box);
        }
        const status = document.createElement('span');
        status.className = 'maa-diagram-features-status';
        status.textContent = configurationStatus(info, selection);
        items.push(status);
        featureBar.replaceChildren(...items);
    }
    updateToolbar();

    async function exportSvg(): Promise<string> {
        if (!schema) throw new Error('no diagram to export');
        let text: string;
        try {
            text = (await dispatcher.request<ExportSvgAction>(RequestExportSvgAction.create())).svg;
        } finally {
            void dispatch({ kind: ClearHiddenCommand.KIND });
        }
        if (!/xmlns="http:\/\/www\.w3\.org\/2000\/svg"/.test(text)) text = text.replace(/<svg\b/, '<svg xmlns="http://www.w3.org/2000/svg"');
        if (!text.startsWith('<?xml')) text = `<?xml version="1.0" encoding="UTF-8" standalone="no"?>\n${text}`;
        return text;
    }

    async function downloadSvg(): Promise<void> {
        try {
            const text = await exportSvg();
            const blob = new Blob([text], { type: 'image/svg+xml' });
            const url = URL.createObjectURL(blob);
            const a = document.createElement('a');
            a.href = url;
            const comp = ((schema?.['component'] as string | undefined) ?? 'diagram').split('.').pop();
            a.download = `${comp}${current?.diagramType === 'maa-automaton' ? '-automaton' : ''}.svg`;
            document.body.appendChild(a);
            a.click();
            a.remove();
            setTimeout(() => URL.revokeObjectURL(url), 10_000);
        } catch (e) {
            console.warn('diagram export:', e);
        }
    }

    // --- the view --------------------------------------------------------------------------------
    const view: MaaDiagramView = {
        show(target: DiagramTarget): void {
            const changed = !current || targetKey(current) !== targetKey(target);
            current = { ...target };
            if (target.diagramType === 'maa-cc') lastCc = current;
            updateToolbar();
            request(changed);
        },
        revealPosition(uri: string, position: TextPosition): void {
            if (!schema) return;
            const els: TracedElement[] = [];
            for (const { el, depth } of walkSchema(schema)) {
                if (typeof el['trace'] === 'string' && el !== schema && SELECTABLE_TYPES.has(el.type)) els.push({ id: el.id, trace: el['trace'] as string, depth });
            }
            const hit = findInnermostElement(els, uri, position);
            if (!hit) return;
            void dispatch(SelectAllAction.create({ select: false }));
            void dispatch(SelectAction.create({ selectedElementsIDs: [hit.id] }));
            const root = schema;
            void (async () => {
                try {
                    const res = await dispatcher.request<ViewportResult>(GetViewportAction.create());
                    const b = absoluteBounds(root, hit.id);
                    if (b && boundsInside(b, visibleArea(res.viewport, res.canvasBounds))) return;
                } catch {
                    /* center anyway */
                }
                await dispatch(CenterAction.create([hit.id], { animate: true, retainZoom: true }));
            })();
        },
        exportSvg,
        setLiveValues(values: ReadonlyMap<string, string>): void {
            liveValues = new Map(values);
            liveBySnake = new Map([...values].map(([k, v]) => [snakePath(k), v]));
            scheduleRedraw();
        },
        setActiveStates(states: ReadonlyMap<string, string>): void {
            activeStates = new Map(states);
            scheduleRedraw();
        },
        onSelect(handler: (traces: string[]) => void): Disposable {
            selectHandlers.add(handler);
            return { dispose: () => selectHandlers.delete(handler) };
        },
        knownPortPaths: () => [...new Set([...portPathMaps.values()].flat())],
        knownInstancePaths: () => [...new Set([...typeMaps.values()].flatMap((m) => [...m.keys()]))],
        currentTarget: () => (current ? { ...current } : undefined),
        onModelChanged(handler: () => void): Disposable {
            modelHandlers.add(handler);
            return { dispose: () => modelHandlers.delete(handler) };
        },
        dispose(): void {
            if (disposed) return;
            disposed = true;
            proxy.disconnect();
            proxy.modelListeners.clear();
            selectHandlers.clear();
            modelHandlers.clear();
            for (const id of [`${baseDiv}-hidden`, `${baseDiv}-popup`]) document.getElementById(id)?.remove();
            container.replaceChildren();
            container.classList.remove('maa-diagram');
        },
    };
    return view;
}
