/**
 * The simulate panel: `mountSimulatePanel(container, host)` (contracts.ts). Starts and stops a
 * simulation session through the backend, drives it through the simulator's rosbridge services
 * (docs/simulation.md) over the proxied rosbridge, embeds the viser view, and offers a port
 * inspector with live values, plots and input injection. During a run the diagram shows the
 * port values and the active automaton states and modes (through `host.diagram`, the diagram's
 * live layer).
 *
 * The parts: the tool bar (controls.ts), the status line (status-view.ts), the 3D view
 * (viewer.ts), the port inspector (inspector.ts, its rows, plots and injection), and the
 * controller (controller.ts) with the session's state machine (session.ts) and the live
 * connection of a run (live-run.ts).
 */
import './simulate.css';
import type { Disposable, SimulateHost } from '../contracts.js';
import { Controls } from './controls.js';
import { SimulationController } from './controller.js';
import { el } from './dom.js';
import { Inspector } from './inspector.js';
import { StatusView } from './status-view.js';
import { Viewer } from './viewer.js';

export function mountSimulatePanel(container: HTMLElement, host: SimulateHost): Disposable {
    container.dataset['testid'] = 'simulate-panel';
    container.classList.add('maa-simulate');
    const controls = new Controls();
    const status = new StatusView();
    const viewer = new Viewer();
    let controller: SimulationController | undefined;
    const inspector = new Inspector({
        sampleTime: () => controller?.clockSeconds() ?? performance.now() / 1000,
        valuesChanged: () => controller?.pushValues(),
        notify: (severity, message) => host.notify(severity, message),
    });
    container.replaceChildren(
        controls.element,
        status.bar,
        status.errorBox,
        status.progressBox,
        el('div', { class: 'maa-sim-body' }, viewer.element, inspector.element),
    );
    controller = new SimulationController({ host, controls, status, inspector, viewer });
    void controller.mount();
    return {
        dispose(): void {
            if (!controller) return;
            controller.dispose();
            controller = undefined;
            container.replaceChildren();
            container.classList.remove('maa-simulate');
        },
    };
}
