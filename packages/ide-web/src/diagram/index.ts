/**
 * The Sprotty diagram of the browser IDE: `mountDiagram(container, host)` (contracts.ts).
 *
 * The model comes from the diagram server in the language server worker (langium-sprotty,
 * server-side ELK layout, docs/ide.md "Diagram protocol"); the client only renders it. Action
 * messages travel through the shell's {@link DiagramHost} channel (LSP notifications
 * `diagram/accept`) via {@link MaaDiagramProxy}, a `DiagramServerProxy` over that channel.
 *
 * The parts: the Sprotty container (container.ts: proxy.ts, commands.ts, views.ts), the tool bar
 * and the feature bar (toolbar.ts, feature-bar.ts), the viewport (camera.ts), selection both ways
 * (selection.ts), what is remembered per target (target-memory.ts), the SVG export
 * (svg-export.ts), and the live layer of a simulation run (live-layer.ts), which the view offers
 * as contracts.ts `DiagramLiveLayer`.
 */
import 'reflect-metadata';
import 'sprotty/css/sprotty.css';
import './diagram.css';
import { RequestExportSvgAction, RequestModelAction, SelectAction, SelectAllAction, type Action, type ExportSvgAction } from 'sprotty-protocol';
import type { DiagramHost, DiagramTarget, DiagramView, Disposable, TextPosition } from '../contracts.js';
import { Camera } from './camera.js';
import { ClearHiddenCommand, RedrawCommand } from './commands.js';
import { featuresOption, graphFeatureInfo, type FeatureSelection } from './configuration.js';
import { createDiagramContainer } from './container.js';
import { FeatureBar } from './feature-bar.js';
import { LiveLayer } from './live-layer.js';
import type { SchemaElement } from './schema.js';
import { elementAt, selectionHandler } from './selection.js';
import { downloadText, standaloneSvg, svgFileName } from './svg-export.js';
import { TargetMemory, targetKey } from './target-memory.js';
import { Toolbar, shownComponent } from './toolbar.js';
import { createViews, type ViewState } from './views.js';

export { parseTrace, findInnermostElement, normalizeUri, rangeContains } from './trace.js';
export { MaaDiagramProxy } from './proxy.js';
export { ClearHiddenCommand, RedrawCommand } from './commands.js';

/** The mounted diagram with what only the diagram's own tests and tools use. */
export interface MaaDiagramView extends DiagramView {
    /** The target currently shown. */
    currentTarget(): DiagramTarget | undefined;
    /** Called whenever a new model arrived (set or update). */
    onModelChanged(handler: () => void): Disposable;
}

let mountCounter = 0;

/** Mounts the diagram into `container`; the shell calls `show` with what to display. */
export function mountDiagram(container: HTMLElement, host: DiagramHost): MaaDiagramView {
    const baseDiv = `maa-diagram-${++mountCounter}`;
    container.dataset['testid'] = 'diagram';
    container.classList.add('maa-diagram');

    // --- state -------------------------------------------------------------------------------
    const live = new LiveLayer();
    const memory = new TargetMemory();
    let schema: SchemaElement | undefined;
    let current: DiagramTarget | undefined;
    let lastCc: DiagramTarget | undefined;
    let fitPending = false;
    const selectHandlers = new Set<(traces: string[]) => void>();
    const modelHandlers = new Set<() => void>();
    /** Actions the diagram dispatched itself (a selection among them is no user's). */
    const programmatic = new WeakSet<Action>();
    let disposed = false;

    // --- Sprotty container ---------------------------------------------------------------------
    const viewState: ViewState = {
        liveValue: (p) => live.liveValue(p),
        activeStateOf: (p) => live.activeStateOf(p),
        automatonActiveState: () => (current?.diagramType === 'maa-automaton' ? live.activeStateForType((schema?.['component'] as string | undefined) ?? current.component) : undefined),
        toggleExpanded: (path) => {
            if (!current) return;
            memory.toggleExpanded(current, path);
            void camera.remember().then(() => request(false));
        },
        openAutomaton: (componentType) => {
            if (current) view.show({ uri: current.uri, component: componentType, diagramType: 'maa-automaton' });
        },
    };
    const onUserSelection = (traces: string[]): void => {
        // the shell reveals the trace in its onSelect handler; without one, the diagram does
        if (selectHandlers.size > 0) for (const h of [...selectHandlers]) h(traces);
        else host.revealTrace(traces[0]!);
    };
    const { proxy, dispatcher } = createDiagramContainer(baseDiv, createViews(viewState), selectionHandler(() => schema, (a) => programmatic.has(a), onUserSelection));
    const dispatch = (action: Action): Promise<void> => {
        programmatic.add(action);
        return dispatcher.dispatch(action).catch((e: unknown) => console.warn('diagram:', e));
    };
    const camera = new Camera(dispatcher, dispatch);
    proxy.connect(host);

    // --- DOM -----------------------------------------------------------------------------------
    const toolbar = new Toolbar({
        fit: () => {
            if (schema) void camera.fit(schema, 2, true);
        },
        zoomBy: (factor) => {
            if (schema) void camera.zoomBy(schema, factor);
        },
        exportSvg: () => void downloadSvg(),
        switchView,
    });
    const featureBar = new FeatureBar((selection) => select(selection));
    const canvas = document.createElement('div');
    canvas.className = 'maa-diagram-canvas';
    const base = document.createElement('div');
    base.id = baseDiv;
    const empty = document.createElement('div');
    empty.className = 'maa-diagram-empty';
    empty.textContent = 'No diagram yet: open a model file.';
    canvas.append(base, empty);
    container.replaceChildren(toolbar.element, featureBar.element, canvas);

    function updateBars(): void {
        toolbar.update(schema, current);
        const isCc = current?.diagramType === 'maa-cc';
        featureBar.update(graphFeatureInfo(isCc ? schema : undefined), current ? memory.selectionOf(current) : undefined);
    }
    updateBars();

    function switchView(): void {
        if (!current) return;
        if (current.diagramType === 'maa-cc') {
            const comp = (schema?.['component'] as string | undefined) ?? current.component;
            view.show({ uri: current.uri, component: comp, diagramType: 'maa-automaton' });
        } else {
            view.show(lastCc ?? { uri: current.uri, diagramType: 'maa-cc' });
        }
    }

    function select(selection: FeatureSelection): void {
        if (!current) return;
        memory.setSelection(current, selection);
        void camera.remember().then(() => request(false));
    }

    // --- requests and models -------------------------------------------------------------------
    function request(fit: boolean): void {
        if (!current || disposed) return;
        fitPending = fit;
        const options: Record<string, string | boolean | string[] | Record<string, boolean>> = {
            diagramType: current.diagramType,
            sourceUri: current.uri,
            needsClientLayout: false,
            needsServerLayout: true,
            expanded: [...memory.expandedOf(current)].sort(),
        };
        if (current.component) options['component'] = current.component;
        if (current.diagramType === 'maa-cc') {
            const features = featuresOption(memory.selectionOf(current), graphFeatureInfo(schema).features);
            if (features) options['features'] = features;
        }
        void dispatch(RequestModelAction.create(options));
    }

    proxy.modelListeners.add((root, kind) => {
        schema = root;
        empty.hidden = true;
        live.recordModel(root, (root['diagramType'] as string | undefined) ?? current?.diagramType, shownComponent(root, current));
        updateBars();
        if (kind === 'setModel') {
            if (fitPending) {
                fitPending = false;
                camera.forget();
                // A new diagram opens readable (a huge one from its top); the Fit button shows it all.
                void camera.fit(root, 1.5, false, 0.3);
            } else {
                camera.restore(root);
            }
        }
        for (const h of [...modelHandlers]) h();
    });

    // --- live decorations: redrawn at most once per frame ---------------------------------------
    let redrawScheduled = false;
    function scheduleRedraw(): void {
        if (redrawScheduled || disposed || !schema) return;
        redrawScheduled = true;
        const run = (): void => {
            redrawScheduled = false;
            if (!disposed && schema) void dispatch({ kind: RedrawCommand.KIND });
        };
        if (typeof requestAnimationFrame === 'function') requestAnimationFrame(run);
        else setTimeout(run, 16);
    }

    // --- export ----------------------------------------------------------------------------------
    async function exportSvg(): Promise<string> {
        if (!schema) throw new Error('no diagram to export');
        try {
            return standaloneSvg((await dispatcher.request<ExportSvgAction>(RequestExportSvgAction.create())).svg);
        } finally {
            void dispatch({ kind: ClearHiddenCommand.KIND });
        }
    }

    async function downloadSvg(): Promise<void> {
        try {
            downloadText(await exportSvg(), svgFileName(schema?.['component'] as string | undefined, current));
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
            updateBars();
            request(changed);
        },
        revealPosition(uri: string, position: TextPosition): void {
            const root = schema;
            const id = root ? elementAt(root, uri, position) : undefined;
            if (!root || !id) return;
            void dispatch(SelectAllAction.create({ select: false }));
            void dispatch(SelectAction.create({ selectedElementsIDs: [id] }));
            void camera.reveal(root, id);
        },
        exportSvg,
        setLiveValues(values: ReadonlyMap<string, string>): void {
            live.setLiveValues(values);
            scheduleRedraw();
        },
        setActiveStates(states: ReadonlyMap<string, string>): void {
            live.setActiveStates(states);
            scheduleRedraw();
        },
        knownPortPaths: () => live.knownPortPaths(),
        knownInstancePaths: () => live.knownInstancePaths(),
        onSelect(handler: (traces: string[]) => void): Disposable {
            selectHandlers.add(handler);
            return { dispose: () => selectHandlers.delete(handler) };
        },
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
