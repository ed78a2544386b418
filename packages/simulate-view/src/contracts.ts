/**
 * What the simulate panel needs from the front end that mounts it (the browser IDE's shell or
 * the VS Code extension's webview). Only these types cross the seam; they are structural, so the
 * IDE's diagram view (a DiagramLiveLayer with more) fits as it is.
 */
import type { AppInfo } from '@maa/protocol';
import type { RevealMessage } from './host-messages.js';

/** Something that can be undone/removed. */
export interface Disposable {
    dispose(): void;
}

/**
 * The diagram's extension point for a simulation run: live values on ports and connectors, the
 * active automaton state or mode of each instance, and the user's selection.
 */
export interface DiagramLiveLayer {
    /** Live values by port path (`"ctrl.arm"`); shown on connectors and ports. Empty map clears. */
    setLiveValues(values: ReadonlyMap<string, string>): void;
    /** Active automaton state or mode by instance path (`"ctrl"` → `"Toasting"`). Empty map clears. */
    setActiveStates(states: ReadonlyMap<string, string>): void;
    /** Called when the user selects diagram elements (their traces). */
    onSelect(handler: (traces: string[]) => void): Disposable;
}

/** One application configuration of the workspace (`GET /api/apps`, @maa/protocol). */
export type { AppInfo };

/**
 * State the host keeps for the panel across a reload of the page or webview (VS Code: the
 * webview's getState/setState). Values are JSON; each part of the panel uses a key of its own.
 */
export interface ViewState {
    get(key: string): unknown;
    set(key: string, value: unknown): void;
}

/** What the front end gives the simulate panel. */
export interface SimulateHost {
    /** The diagram's live layer, for live values and active states during a run. */
    diagram: DiagramLiveLayer;
    /** The application configurations of the workspace (fresh from the backend). */
    apps(): Promise<AppInfo[]>;
    /** Reports a message in the front end's status line / notifications. */
    notify(severity: 'info' | 'warning' | 'error', message: string): void;
    /**
     * Where the backend's simulation API, rosbridge and viser are (endpoints.ts): absent in the
     * browser IDE (the page's own origin), an absolute URL in the VS Code webview (the extension's
     * relay, whose path carries the capability).
     */
    backendBase?: string;
    /** Where the panel keeps its layout (the 3D view's size); absent: not kept. */
    viewState?: ViewState;
    /**
     * Shows a transition or program step selected in the panels in the model: its source line
     * and the diagram highlight (VS Code: the extension, host-messages.ts); absent: not shown.
     */
    reveal?(message: RevealMessage): void;
}
