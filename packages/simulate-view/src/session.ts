/**
 * The simulation session of the simulate panel as a state machine: the states a session goes
 * through, the events that move it, and {@link transition}, the one function that decides. Pure,
 * no DOM: the controller (controller.ts) feeds it the user's clicks and the backend's answers and
 * renders what the state allows.
 *
 * ```
 *            start / adopt-preparing                    start-succeeded
 *   idle ─────────────────────────────► starting ─────────────────────────► running
 *    ▲  ◄──────────── start-failed ───────┘  │ stop                  start ┘ │ │ │
 *    │                                       ▼                (restart)      │ │ │
 *    │  ◄── start-failed (cancelled) ─── cancelling ── start-succeeded ──────┘ │ │
 *    │                                   (stop-finished: stop no longer open)  │ │
 *    │  ◄──────────── stop-finished ──── stopping ◄────────── stop ────────────┘ │
 *    │  ◄──────────────────────────── ended (the backend lost the session) ──────┘
 *    └─ adopt-running ─► running
 * ```
 */

/** Why the session is idle: the status line says so. */
export type IdleReason = 'initial' | 'stopped' | 'cancelled' | 'failed' | 'ended';

export type SessionState =
    /** No session, no request open. */
    | { readonly kind: 'idle'; readonly reason: IdleReason; readonly exitCode?: number | null }
    /** A start request is open (ours, or one adopted from another window or before a reload). */
    | { readonly kind: 'starting'; readonly adopted: boolean }
    /** Stop was pressed while a start was open: waits for the start's answer (409 when cancelled). */
    | { readonly kind: 'cancelling'; readonly adopted: boolean; readonly stopOpen: boolean }
    /** The session runs. */
    | { readonly kind: 'running' }
    /** A stop request is open. */
    | { readonly kind: 'stopping' };

export type SessionEvent =
    /** The user starts (from idle, or restarts a running session: the backend stops it first). */
    | { readonly type: 'start' }
    /** At mount: the backend still prepares a start (another window, or before a reload). */
    | { readonly type: 'adopt-preparing' }
    /** At mount: a session already runs. */
    | { readonly type: 'adopt-running' }
    /** The open start answered: the session runs. */
    | { readonly type: 'start-succeeded' }
    /** The open start failed (or was cancelled by a stop). */
    | { readonly type: 'start-failed' }
    /** The user stops (a running session, or an open start). */
    | { readonly type: 'stop' }
    /** The stop request answered (successfully or not: the panel forgets the session either way). */
    | { readonly type: 'stop-finished' }
    /** The backend reports that the running session is gone. */
    | { readonly type: 'ended'; readonly exitCode?: number | null };

export type SessionEventType = SessionEvent['type'];

export const INITIAL_SESSION: SessionState = { kind: 'idle', reason: 'initial' };

/** The next state, or `undefined` when the state refuses the event (nothing changes then). */
export function transition(state: SessionState, event: SessionEvent): SessionState | undefined {
    switch (state.kind) {
        case 'idle':
            if (event.type === 'start') return { kind: 'starting', adopted: false };
            if (event.type === 'adopt-preparing') return { kind: 'starting', adopted: true };
            if (event.type === 'adopt-running') return { kind: 'running' };
            return undefined;
        case 'starting':
            if (event.type === 'start-succeeded') return { kind: 'running' };
            if (event.type === 'start-failed') return { kind: 'idle', reason: 'failed' };
            if (event.type === 'stop') return { kind: 'cancelling', adopted: state.adopted, stopOpen: true };
            return undefined;
        case 'cancelling':
            // the backend serializes start and stop: a start that got through is stopped next
            if (event.type === 'start-succeeded') return state.stopOpen ? { kind: 'stopping' } : { kind: 'running' };
            if (event.type === 'start-failed') return state.stopOpen ? { kind: 'stopping' } : { kind: 'idle', reason: 'cancelled' };
            if (event.type === 'stop-finished' && state.stopOpen) return { ...state, stopOpen: false };
            if (event.type === 'stop' && !state.stopOpen) return { ...state, stopOpen: true };
            return undefined;
        case 'running':
            if (event.type === 'start') return { kind: 'starting', adopted: false };
            if (event.type === 'stop') return { kind: 'stopping' };
            if (event.type === 'ended') return { kind: 'idle', reason: 'ended', exitCode: event.exitCode };
            return undefined;
        case 'stopping':
            if (event.type === 'stop-finished') return { kind: 'idle', reason: 'stopped' };
            return undefined;
    }
}

/** Every event type, for callers that ask what a state accepts. */
export const SESSION_EVENT_TYPES: readonly SessionEventType[] = [
    'start',
    'adopt-preparing',
    'adopt-running',
    'start-succeeded',
    'start-failed',
    'stop',
    'stop-finished',
    'ended',
];

/** Whether the state accepts an event of this type (its payload does not matter for any transition). */
export function accepts(state: SessionState, type: SessionEventType): boolean {
    const event: SessionEvent = { type };
    return transition(state, event) !== undefined;
}

/** A request (start or stop) is open: the choice of app, platform and speed is locked. */
export function isBusy(state: SessionState): boolean {
    return state.kind === 'starting' || state.kind === 'cancelling' || state.kind === 'stopping';
}

/** The status line of an idle session. */
export function idleStatusText(state: SessionState & { kind: 'idle' }): string {
    switch (state.reason) {
        case 'initial':
        case 'failed':
            return 'Not running';
        case 'stopped':
            return 'Stopped';
        case 'cancelled':
            return 'Start cancelled';
        case 'ended':
            return `Simulation ended${state.exitCode !== undefined && state.exitCode !== null ? ` (exit code ${state.exitCode})` : ''}`;
    }
}

/** What the tool bar's buttons depend on besides the session. */
export interface ToolbarContext {
    /** A runnable platform is chosen (its mode is known). */
    readonly canRun: boolean;
    /** A rosbridge connection to the running simulator exists. */
    readonly connected: boolean;
    /** The simulator reports itself paused. */
    readonly paused: boolean;
    /** The 3D view is shown. */
    readonly viewShown: boolean;
}

/** Which tool bar controls are enabled (and whether Pause or Resume shows). */
export interface ToolbarState {
    readonly start: boolean;
    readonly stop: boolean;
    /** Pause/Resume, Step and Reset: a connected running session. */
    readonly run: boolean;
    readonly reloadView: boolean;
    /** The app, platform and speed choice. */
    readonly choice: boolean;
    readonly showResume: boolean;
}

/**
 * The tool bar for a session: Start only when no session is starting, running or stopping (a
 * second click cannot start a second run, or restart the one that runs: Stop first); Stop while a
 * start is open or a session runs.
 */
export function toolbarState(session: SessionState, ctx: ToolbarContext): ToolbarState {
    return {
        start: session.kind === 'idle' && ctx.canRun,
        stop: accepts(session, 'stop'),
        run: session.kind === 'running' && ctx.connected,
        reloadView: ctx.viewShown,
        choice: !isBusy(session),
        showResume: ctx.paused,
    };
}
