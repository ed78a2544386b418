/**
 * The messages between the VS Code extension and the simulate panel in its webview
 * (vscode-webview.ts), both directions, with their checks: a webview message is data from
 * another process, so each side accepts only what parses. Pure (no DOM, no `vscode`).
 */

export type Severity = 'info' | 'warning' | 'error';

/** What the extension sends the webview. */
export type ToWebview =
    /** Mount the panel against the backend below `backendBase` (the extension's relay). */
    | { type: 'init'; backendBase: string }
    /** **Start Simulation**: the application (`.arcapp` path relative to the workspace folder) and platform. */
    | { type: 'start'; app: string; platform: string }
    | { type: 'stop' }
    | { type: 'reset' };

export type PanelCommand = 'start' | 'stop' | 'reset';

/** What the webview sends the extension. */
export type FromWebview =
    /** The script runs and listens (the extension then sends `init`). */
    | { type: 'ready' }
    | { type: 'notify'; severity: Severity; message: string }
    /** The outcome of a command (`ok: false`: the panel did not know the application, or no run to reset). */
    | { type: 'done'; command: PanelCommand; ok: boolean }
    /** Live port values by port path (empty: cleared). */
    | { type: 'live-values'; values: Array<[string, string]> }
    /** Active automaton states or modes by instance path (empty: cleared). */
    | { type: 'active-states'; states: Array<[string, string]> }
    /**
     * A transition (or program step) was selected in a panel: open `file` (workspace-relative)
     * at `line` (1-based) and, with `highlight`, highlight it in the diagrams (maa.diagram.highlightTrace).
     */
    | RevealMessage;

/** The argument of `maa.diagram.highlightTrace`: a component's state and the transition taken into it. */
export interface TraceHighlight {
    /** The component's qualified name. */
    component: string;
    instancePath: string;
    state?: string;
    transition?: { from: string; to: string; index: number };
}

export interface RevealMessage {
    type: 'reveal';
    /** Workspace-relative path, `/`-separated, without `..`. */
    file: string;
    line: number;
    column?: number;
    highlight?: TraceHighlight;
}

type Fields = Record<string, unknown>;

function isRecord(x: unknown): x is Fields {
    return typeof x === 'object' && x !== null && !Array.isArray(x);
}

function isString(x: unknown): x is string {
    return typeof x === 'string';
}

const SEVERITIES: readonly string[] = ['info', 'warning', 'error'];
const COMMANDS: readonly string[] = ['start', 'stop', 'reset'];

/** A list of string pairs (a map's entries), or undefined. */
function pairs(x: unknown): Array<[string, string]> | undefined {
    if (!Array.isArray(x)) return undefined;
    const out: Array<[string, string]> = [];
    for (const e of x) {
        if (!Array.isArray(e) || e.length !== 2 || !isString(e[0]) || !isString(e[1])) return undefined;
        out.push([e[0], e[1]]);
    }
    return out;
}

const isLine = (x: unknown): x is number => typeof x === 'number' && Number.isInteger(x) && x >= 1;

/**
 * A workspace-relative file path as a reveal may name it: relative, `/`-separated, no empty,
 * `.` or `..` segment (the extension opens it inside a workspace folder, nowhere else).
 */
export function isRelativeFile(file: unknown): file is string {
    if (!isString(file) || file.length === 0 || file.length > 1024) return false;
    if (file.startsWith('/') || file.includes('\\') || /^[a-zA-Z]:/.test(file) || file.includes('\0')) return false;
    return file.split('/').every((seg) => seg.length > 0 && seg !== '.' && seg !== '..');
}

function parseHighlight(x: unknown): TraceHighlight | undefined {
    if (!isRecord(x) || !isString(x['component']) || !isString(x['instancePath'])) return undefined;
    const out: TraceHighlight = { component: x['component'], instancePath: x['instancePath'] };
    if (x['state'] !== undefined) {
        if (!isString(x['state'])) return undefined;
        out.state = x['state'];
    }
    const t = x['transition'];
    if (t !== undefined) {
        if (!isRecord(t) || !isString(t['from']) || !isString(t['to']) || !Number.isInteger(t['index'])) return undefined;
        out.transition = { from: t['from'], to: t['to'], index: t['index'] as number };
    }
    return out;
}

function parseReveal(x: Fields): RevealMessage | undefined {
    const { file, line, column, highlight } = x;
    if (!isRelativeFile(file) || !isLine(line)) return undefined;
    const out: RevealMessage = { type: 'reveal', file, line };
    if (column !== undefined) {
        if (!isLine(column)) return undefined;
        out.column = column;
    }
    if (highlight !== undefined) {
        const h = parseHighlight(highlight);
        if (!h) return undefined;
        out.highlight = h;
    }
    return out;
}

/** A message for the webview, or undefined when it is none. */
export function parseToWebview(x: unknown): ToWebview | undefined {
    if (!isRecord(x)) return undefined;
    switch (x['type']) {
        case 'init':
            return isString(x['backendBase']) ? { type: 'init', backendBase: x['backendBase'] } : undefined;
        case 'start':
            return isString(x['app']) && isString(x['platform']) ? { type: 'start', app: x['app'], platform: x['platform'] } : undefined;
        case 'stop':
        case 'reset':
            return { type: x['type'] };
        default:
            return undefined;
    }
}

/** A message from the webview, or undefined when it is none. */
export function parseFromWebview(x: unknown): FromWebview | undefined {
    if (!isRecord(x)) return undefined;
    switch (x['type']) {
        case 'ready':
            return { type: 'ready' };
        case 'notify': {
            const { severity, message } = x;
            return isString(severity) && SEVERITIES.includes(severity) && isString(message)
                ? { type: 'notify', severity: severity as Severity, message }
                : undefined;
        }
        case 'done': {
            const { command, ok } = x;
            return isString(command) && COMMANDS.includes(command) && typeof ok === 'boolean'
                ? { type: 'done', command: command as PanelCommand, ok }
                : undefined;
        }
        case 'live-values': {
            const values = pairs(x['values']);
            return values ? { type: 'live-values', values } : undefined;
        }
        case 'active-states': {
            const states = pairs(x['states']);
            return states ? { type: 'active-states', states } : undefined;
        }
        case 'reveal':
            return parseReveal(x);
        default:
            return undefined;
    }
}
