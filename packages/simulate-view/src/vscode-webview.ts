/**
 * The simulate panel in a VS Code webview (the extension bundles this file for its simulate view,
 * packages/vscode-extension/src/simulate): the same panel as the browser IDE's, against the
 * backend below the base URL the extension sends (its relay), driven by the extension's commands
 * (host-messages.ts). The diagram's live layer posts the values and states to the extension,
 * which hands them to the diagram view.
 */
import './vscode-webview.css';
import { createSimApi } from './backend.js';
import type { DiagramLiveLayer, Disposable, ViewState } from './contracts.js';
import { simEndpoints } from './endpoints.js';
import { type FromWebview, parseToWebview, type ToWebview } from './host-messages.js';
import { mountSimulatePanel, type SimulatePanel } from './index.js';

interface VsCodeApi {
    postMessage(message: FromWebview): void;
    /** VS Code's webview state (optional here: a stand-in of the API may lack it; nothing is kept then). */
    getState?(): unknown;
    setState?(state: unknown): void;
}

declare function acquireVsCodeApi(): VsCodeApi;

const vscode = acquireVsCodeApi();

/** The diagram's live layer as messages to the extension (selection does not come back this way). */
const postingLayer: DiagramLiveLayer = {
    setLiveValues: (values) => vscode.postMessage({ type: 'live-values', values: [...values] }),
    setActiveStates: (states) => vscode.postMessage({ type: 'active-states', states: [...states] }),
    onSelect: (): Disposable => ({ dispose: () => undefined }),
};

/** The webview's state (kept by VS Code while the view is hidden or reloaded): one object, a key per part. */
const viewState: ViewState = {
    get: (key) => {
        const state = vscode.getState?.();
        return state && typeof state === 'object' ? (state as Record<string, unknown>)[key] : undefined;
    },
    set: (key, value) => {
        const state = vscode.getState?.();
        vscode.setState?.({ ...(state && typeof state === 'object' ? state : {}), [key]: value });
    },
};

let panel: SimulatePanel | undefined;

function mount(backendBase: string): void {
    panel?.dispose();
    const container = document.getElementById('simulate-root');
    if (!container) throw new Error('the webview has no #simulate-root');
    const api = createSimApi(simEndpoints(backendBase, window.location).api);
    panel = mountSimulatePanel(container, {
        backendBase,
        viewState,
        diagram: postingLayer,
        apps: () => api.apps(),
        notify: (severity, message) => vscode.postMessage({ type: 'notify', severity, message }),
        reveal: (message) => vscode.postMessage(message),
    });
}

async function handle(message: ToWebview): Promise<void> {
    if (message.type === 'init') {
        mount(message.backendBase);
        return;
    }
    if (!panel) {
        vscode.postMessage({ type: 'done', command: message.type, ok: false });
        return;
    }
    let ok = true;
    if (message.type === 'start') ok = await panel.start(message.app, message.platform);
    else if (message.type === 'stop') await panel.stop();
    else ok = await panel.reset();
    vscode.postMessage({ type: 'done', command: message.type, ok });
}

window.addEventListener('message', (event: MessageEvent<unknown>) => {
    const message = parseToWebview(event.data);
    if (message) void handle(message);
});
vscode.postMessage({ type: 'ready' });
