/**
 * The simulate panel: `mountSimulatePanel(container, host)` (contracts.ts). Starts and stops a
 * simulation session through the backend, drives it through the simulator's rosbridge services
 * (docs/simulation.md) over the proxied rosbridge, embeds the viser view, and offers a port
 * inspector with live values, plots and input injection. During a run the diagram shows the
 * port values and the active automaton states and modes (through `host.diagram`, the diagram's
 * live layer).
 *
 * The parts: the tool bar (controls.ts), the status line (status-view.ts), the 3D view
 * (viewer.ts) with a drag handle between it and the port table (layout.ts), the port inspector
 * (inspector.ts, its rows, plots and injection), and the controller (controller.ts) with the
 * session's state machine (session.ts) and the live connection of a run (live-run.ts).
 */
import './simulate.css';
import type { Disposable, SimulateHost } from './contracts.js';
import { Controls } from './controls.js';
import { SimulationController } from './controller.js';
import { simEndpoints } from './endpoints.js';
import { createSimApi } from './backend.js';
import { Inspector } from './inspector.js';
import { SplitLayout } from './layout.js';
import { StatusView } from './status-view.js';
import { Viewer } from './viewer.js';
import { createReplayApi } from './replay/api.js';
import { ReplayBar } from './replay/bar.js';
import { ReplayController } from './replay/session.js';
import { TimelineStore } from './timeline/store.js';
import { Panels } from './panels/index.js';
import { parseAutomata } from './timeline/automata.js';
import { BreakpointsView } from './breakpoints/index.js';

/** The mounted panel: its tool bar's actions for hosts that offer them as commands too. */
export interface SimulatePanel extends Disposable {
    /** Starts an application (`.arcapp` path as the backend lists it) on a platform; false when unknown. */
    start(app: string, platform: string): Promise<boolean>;
    /** Stops the session (as the Stop button). */
    stop(): Promise<void>;
    /** Resets the running simulation; false when none is connected. */
    reset(): Promise<boolean>;
}

export function mountSimulatePanel(container: HTMLElement, host: SimulateHost): SimulatePanel {
    container.dataset['testid'] = 'simulate-panel';
    container.classList.add('maa-simulate');
    const controls = new Controls();
    const status = new StatusView();
    const endpoints = simEndpoints(host.backendBase, window.location);
    const viewer = new Viewer(endpoints.viser);
    // the session's timeline store (C5): a live run's messages, or a replay's recording
    const timeline = new TimelineStore();
    // the panels over it (plots, state timeline, messages, log; docs/ide.md "Panels")
    const panels = new Panels(timeline, host);
    // breakpoints on the run's states and transitions (lock-step runs; docs/simulation.md "Breakpoints")
    const breakpoints = new BreakpointsView({ notify: (severity, message) => host.notify(severity, message) });
    const replayBar = new ReplayBar();
    controls.element.append(...replayBar.toolbarItems);
    let controller: SimulationController | undefined;
    const inspector = new Inspector({
        sampleTime: () => controller?.clockSeconds() ?? performance.now() / 1000,
        valuesChanged: () => controller?.pushValues(),
        notify: (severity, message) => host.notify(severity, message),
    });
    const layout = new SplitLayout(viewer.element, inspector.element, host.viewState);
    container.replaceChildren(
        controls.element,
        status.bar,
        replayBar.element,
        status.errorBox,
        status.progressBox,
        layout.element,
        panels.element,
        breakpoints.element,
    );
    const simApi = createSimApi(endpoints.api);
    controller = new SimulationController({
        host,
        controls,
        status,
        inspector,
        viewer,
        // the Record toggle decides whether a start records
        api: { ...simApi, start: (app, platform, mode, speed) => simApi.start(app, platform, mode, speed, replayBar.recordToggle.checked) },
        rosbridge: endpoints.rosbridge,
        timeline: {
            store: timeline,
            runStarted: () => {
                timeline.clear();
                panels.reset();
            },
            runInfo: (topicMap, instanceOf) => {
                panels.setRunInfo(parseAutomata(topicMap), instanceOf);
                breakpoints.attach(parseAutomata(topicMap), endpoints.rosbridge);
            },
        },
    });
    const replay = new ReplayController({
        bar: replayBar,
        api: createReplayApi(endpoints.api),
        simApi,
        rosbridge: endpoints.rosbridge,
        store: timeline,
        viewer,
        inspector,
        diagram: host.diagram,
        status,
        notify: (severity, message) => host.notify(severity, message),
        runActive: () => controller !== undefined && controller.state.kind !== 'idle',
        timeline: {
            runStarted: () => panels.reset(),
            runInfo: (topicMap, instanceOf) => panels.setRunInfo(parseAutomata(topicMap), instanceOf),
        },
    });
    // a start ends a replay session (one session at a time); a run's end lists its recording
    controls.startBtn.addEventListener('click', () => replay.leaveForRun());
    controls.stopBtn.addEventListener('click', () => void replay.refresh());
    // the controller renders its session state; the replay buttons follow it (enabled only without a run)
    const renderReplay = setInterval(() => replay.render(), 500);
    void controller.mount().then(() => replay.mount());
    return {
        start: async (app, platform) => (controller ? controller.startWith(app, platform) : false),
        stop: async () => controller?.stop(),
        reset: async () => (controller ? controller.reset() : false),
        dispose(): void {
            if (!controller) return;
            clearInterval(renderReplay);
            replay.dispose();
            controller.dispose();
            controller = undefined;
            panels.dispose();
            breakpoints.dispose();
            viewer.dispose();
            layout.dispose();
            container.replaceChildren();
            container.classList.remove('maa-simulate');
        },
    };
}

export type { AppInfo, DiagramLiveLayer, Disposable, SimulateHost } from './contracts.js';
export { simEndpoints, type SimEndpoints } from './endpoints.js';
