/**
 * One mounted diagram: the Sprotty container over the shell's diagram channel, the tool and
 * feature bars, the requests for models and what arrives, and the view the shell and the
 * simulate panel drive (contracts.ts `DiagramView`, its live layer `DiagramLiveLayer`).
 */
import {
    RequestExportSvgAction,
    type Viewport,
    RequestModelAction,
    SelectAction,
    SelectAllAction,
    type Action,
    type ExportSvgAction,
} from 'sprotty-protocol';
import type { IActionDispatcher } from 'sprotty';
import type { DiagramHost, DiagramTarget, DiagramView, Disposable, TextPosition } from './contracts.js';
import { Camera } from './camera.js';
import { ClearHiddenCommand, RedrawCommand } from './commands.js';
import { featuresOption, graphFeatureInfo, type FeatureSelection } from './configuration.js';
import { createDiagramContainer } from './container.js';
import { FeatureBar } from './feature-bar.js';
import type { DiagramHighlight } from './highlight.js';
import { LiveLayer } from './live-layer.js';
import type { MaaDiagramProxy } from './proxy.js';
import type { SchemaElement } from './schema.js';
import { elementAt, selectionHandler } from './selection.js';
import { downloadText, standaloneSvg, svgFileName } from './svg-export.js';
import { TargetMemory, targetKey } from './target-memory.js';
import { READABLE_ZOOM } from './viewport.js';
import { Toolbar, shownComponent } from './toolbar.js';
import { createViews, type ViewState } from './views.js';

/** The mounted diagram with what only the diagram's own tests and tools use. */
export interface MaaDiagramView extends DiagramView {
    /** The target currently shown. */
    currentTarget(): DiagramTarget | undefined;
    /** Called whenever a new model arrived (set or update). */
    onModelChanged(handler: () => void): Disposable;
    /** The file name Export SVG suggests: the shown component's simple name, `-automaton` for an automaton view. */
    exportFileName(): string;
}

let mountCounter = 0;

export class MountedDiagram implements MaaDiagramView {
    private readonly baseDiv = `maa-diagram-${++mountCounter}`;
    private readonly live = new LiveLayer();
    private readonly memory = new TargetMemory();
    private readonly selectHandlers = new Set<(traces: string[]) => void>();
    private readonly modelHandlers = new Set<() => void>();
    /** Actions the diagram dispatched itself (a selection among them is no user's). */
    private readonly programmatic = new WeakSet<Action>();
    private readonly proxy: MaaDiagramProxy;
    private readonly dispatcher: IActionDispatcher;
    private readonly camera: Camera;
    private readonly toolbar: Toolbar;
    private readonly featureBar: FeatureBar;
    private readonly empty = document.createElement('div');
    private schema: SchemaElement | undefined;
    private current: DiagramTarget | undefined;
    private lastCc: DiagramTarget | undefined;
    private fitPending = false;
    /** Models asked for (RequestModel) and not come yet. */
    private modelsAwaited = 0;
    /** Waits for the container to get a size, to fit a new diagram then. */
    private sizeWatch: ResizeObserver | undefined;
    private redrawScheduled = false;
    private disposed = false;

    constructor(
        private readonly container: HTMLElement,
        private readonly host: DiagramHost,
    ) {
        container.dataset['testid'] = 'diagram';
        container.classList.add('maa-diagram');
        const handler = selectionHandler(
            () => this.schema,
            (a) => this.programmatic.has(a),
            (traces) => this.userSelected(traces),
        );
        ({ proxy: this.proxy, dispatcher: this.dispatcher } = createDiagramContainer(this.baseDiv, createViews(this.viewState()), handler));
        this.camera = new Camera(this.dispatcher, (action) => this.dispatch(action));
        this.toolbar = new Toolbar({
            fit: () => {
                if (this.schema) void this.camera.fit(this.schema, 2, true);
            },
            zoomBy: (factor) => {
                if (this.schema) void this.camera.zoomBy(this.schema, factor);
            },
            exportSvg: () => void this.downloadSvg(),
            switchView: () => this.switchView(),
        });
        this.featureBar = new FeatureBar((selection) => this.select(selection));
        container.replaceChildren(this.toolbar.element, this.featureBar.element, this.canvas());
        this.updateBars();
        this.proxy.modelListeners.add((root, kind) => this.modelArrived(root, kind));
        this.proxy.connect(host);
    }

    // --- DiagramView -------------------------------------------------------------------------------
    show(target: DiagramTarget): void {
        const changed = !this.current || targetKey(this.current) !== targetKey(target);
        this.current = { ...target };
        if (target.diagramType === 'maa-cc') this.lastCc = this.current;
        this.updateBars();
        // The shown diagram again (Open Diagram on its file): the server keeps it up to date, and a
        // new model would drop the selection; ask again only while no model has come.
        if (changed || !this.schema) this.request(changed);
    }

    revealPosition(uri: string, position: TextPosition): void {
        const root = this.schema;
        const id = root ? elementAt(root, uri, position) : undefined;
        if (!root || !id) return;
        void this.dispatch(SelectAllAction.create({ select: false }));
        void this.dispatch(SelectAction.create({ selectedElementsIDs: [id] }));
        void this.camera.reveal(root, id);
    }

    async exportSvg(): Promise<string> {
        if (!this.schema) throw new Error('no diagram to export');
        try {
            return standaloneSvg((await this.dispatcher.request<ExportSvgAction>(RequestExportSvgAction.create())).svg);
        } finally {
            void this.dispatch({ kind: ClearHiddenCommand.KIND });
        }
    }

    // --- DiagramLiveLayer --------------------------------------------------------------------------
    setLiveValues(values: ReadonlyMap<string, string>): void {
        this.live.setLiveValues(values);
        this.scheduleRedraw();
    }

    setActiveStates(states: ReadonlyMap<string, string>): void {
        this.live.setActiveStates(states);
        this.scheduleRedraw();
    }

    highlight(highlight: DiagramHighlight | undefined): void {
        this.live.setHighlight(highlight);
        this.scheduleRedraw();
    }

    onSelect(handler: (traces: string[]) => void): Disposable {
        this.selectHandlers.add(handler);
        return { dispose: () => this.selectHandlers.delete(handler) };
    }

    // --- MaaDiagramView ----------------------------------------------------------------------------
    currentTarget(): DiagramTarget | undefined {
        return this.current ? { ...this.current } : undefined;
    }

    onModelChanged(handler: () => void): Disposable {
        this.modelHandlers.add(handler);
        return { dispose: () => this.modelHandlers.delete(handler) };
    }

    exportFileName(): string {
        return svgFileName(this.schema?.['component'] as string | undefined, this.current);
    }

    dispose(): void {
        if (this.disposed) return;
        this.disposed = true;
        this.sizeWatch?.disconnect();
        this.proxy.disconnect();
        this.proxy.modelListeners.clear();
        this.selectHandlers.clear();
        this.modelHandlers.clear();
        for (const id of [`${this.baseDiv}-hidden`, `${this.baseDiv}-popup`]) document.getElementById(id)?.remove();
        this.container.replaceChildren();
        this.container.classList.remove('maa-diagram');
    }

    // --- internals ---------------------------------------------------------------------------------
    /** What the views read: live decorations, expansion, opening an automaton. */
    private viewState(): ViewState {
        return {
            liveValue: (p) => this.live.liveValue(p),
            activeStateOf: (p) => this.live.activeStateOf(p),
            automatonActiveState: () =>
                this.current?.diagramType === 'maa-automaton'
                    ? this.live.activeStateForType((this.schema?.['component'] as string | undefined) ?? this.current.component)
                    : undefined,
            highlightOf: (p) => this.live.highlightOf(p),
            automatonHighlight: () =>
                this.current?.diagramType === 'maa-automaton'
                    ? this.live.highlightForType((this.schema?.['component'] as string | undefined) ?? this.current.component)
                    : undefined,
            toggleExpanded: (path) => {
                if (!this.current) return;
                this.memory.toggleExpanded(this.current, path);
                void this.camera.remember().then(() => this.request(false));
            },
            openAutomaton: (componentType) => {
                if (this.current) this.show({ uri: this.current.uri, component: componentType, diagramType: 'maa-automaton' });
            },
        };
    }

    private canvas(): HTMLElement {
        const canvas = document.createElement('div');
        canvas.className = 'maa-diagram-canvas';
        const base = document.createElement('div');
        base.id = this.baseDiv;
        this.empty.className = 'maa-diagram-empty';
        this.empty.textContent = 'No diagram yet: open a model file.';
        canvas.append(base, this.empty);
        return canvas;
    }

    private dispatch(action: Action): Promise<void> {
        this.programmatic.add(action);
        return this.dispatcher.dispatch(action).catch((e: unknown) => console.warn('diagram:', e));
    }

    /** The shell reveals the trace in its onSelect handler; without one, the diagram does. */
    private userSelected(traces: string[]): void {
        const first = traces[0];
        if (this.selectHandlers.size > 0) for (const h of [...this.selectHandlers]) h(traces);
        else if (first !== undefined) this.host.revealTrace(first);
    }

    private updateBars(): void {
        this.toolbar.update(this.schema, this.current);
        const isCc = this.current?.diagramType === 'maa-cc';
        this.featureBar.update(
            graphFeatureInfo(isCc ? this.schema : undefined),
            this.current ? this.memory.selectionOf(this.current) : undefined,
        );
    }

    private switchView(): void {
        const current = this.current;
        if (!current) return;
        if (current.diagramType === 'maa-cc') {
            const comp = (this.schema?.['component'] as string | undefined) ?? current.component;
            this.show({ uri: current.uri, component: comp, diagramType: 'maa-automaton' });
        } else {
            this.show(this.lastCc ?? { uri: current.uri, diagramType: 'maa-cc' });
        }
    }

    private select(selection: FeatureSelection): void {
        if (!this.current) return;
        this.memory.setSelection(this.current, selection);
        void this.camera.remember().then(() => this.request(false));
    }

    private request(fit: boolean): void {
        const current = this.current;
        if (!current || this.disposed) return;
        // A fit asked for stays asked for until a new model comes (a second show of the same target
        // before the first model, e.g. the diagram opened at start and from the title button, keeps it).
        if (fit) {
            this.fitPending = true;
            this.modelsAwaited = 0;
        }
        this.modelsAwaited++;
        const options: Record<string, string | boolean | string[] | Record<string, boolean>> = {
            diagramType: current.diagramType,
            sourceUri: current.uri,
            needsClientLayout: false,
            needsServerLayout: true,
            expanded: [...this.memory.expandedOf(current)].sort(),
        };
        if (current.component) options['component'] = current.component;
        if (current.diagramType === 'maa-cc') {
            const features = featuresOption(this.memory.selectionOf(current), graphFeatureInfo(this.schema).features);
            if (features) options['features'] = features;
        }
        void this.dispatch(RequestModelAction.create(options));
    }

    private modelArrived(root: SchemaElement, kind: string): void {
        this.schema = root;
        this.empty.hidden = true;
        this.live.recordModel(
            root,
            (root['diagramType'] as string | undefined) ?? this.current?.diagramType,
            shownComponent(root, this.current),
        );
        this.updateBars();
        if (kind === 'setModel') {
            this.modelsAwaited = Math.max(0, this.modelsAwaited - 1);
            if (this.fitPending) {
                // every model asked for since the fit was wanted is fitted: the answer to a second
                // request (the diagram shown at start and again from the title button) replaces
                // the first model and its viewport
                if (this.modelsAwaited === 0) this.fitPending = false;
                this.camera.forget();
                // A new diagram opens readable (a huge one from its top); the Fit button shows it all.
                this.openingFit(root);
            } else {
                this.camera.restore(root);
            }
        }
        for (const h of [...this.modelHandlers]) h();
    }

    /**
     * The fit of a new diagram, after Sprotty has drawn it and measured its canvas; when the canvas
     * has no size yet (the webview not laid out), again when the container gets one.
     */
    private openingFit(root: SchemaElement): void {
        this.sizeWatch?.disconnect();
        this.sizeWatch = undefined;
        let tries = 0;
        // The model's own viewport may still replace the fit (the new root is rendered after it): watched for some frames, fitted again then.
        const recheck = (expected: Viewport, frames: number): void => {
            requestAnimationFrame(() => {
                void this.camera.shows(expected).then((ok) => {
                    if (this.disposed || this.schema !== root) return;
                    if (!ok) {
                        if (++tries < 10) attempt();
                    } else if (frames < 15) recheck(expected, frames + 1);
                });
            });
        };
        const attempt = (): void => {
            void this.camera.fit(root, 1.5, false, READABLE_ZOOM).then((done) => {
                if (this.disposed || this.schema !== root) return;
                if (typeof done === 'object') {
                    if (typeof requestAnimationFrame === 'function') recheck(done, 0);
                    return;
                }
                if (done || typeof ResizeObserver !== 'function') return;
                const watch = new ResizeObserver(() => {
                    if (this.container.clientWidth <= 0 || this.container.clientHeight <= 0) return;
                    watch.disconnect();
                    if (this.sizeWatch === watch) this.sizeWatch = undefined;
                    // Sprotty measures the canvas on the window's resize; a pane that got its size without one is measured here.
                    window.dispatchEvent(new Event('resize'));
                    if (this.schema === root) requestAnimationFrame(attempt);
                });
                this.sizeWatch = watch;
                watch.observe(this.container);
            });
        };
        if (typeof requestAnimationFrame === 'function') requestAnimationFrame(attempt);
        else attempt();
    }

    /** Live decorations are redrawn at most once per frame. */
    private scheduleRedraw(): void {
        if (this.redrawScheduled || this.disposed || !this.schema) return;
        this.redrawScheduled = true;
        const run = (): void => {
            this.redrawScheduled = false;
            if (!this.disposed && this.schema) void this.dispatch({ kind: RedrawCommand.KIND });
        };
        if (typeof requestAnimationFrame === 'function') requestAnimationFrame(run);
        else setTimeout(run, 16);
    }

    private async downloadSvg(): Promise<void> {
        try {
            const svg = await this.exportSvg();
            const fileName = this.exportFileName();
            if (this.host.saveSvg) this.host.saveSvg(svg, fileName);
            else downloadText(svg, fileName);
        } catch (e) {
            console.warn('diagram export:', e);
        }
    }
}
