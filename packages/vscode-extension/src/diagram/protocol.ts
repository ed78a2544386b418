/**
 * The messages between the diagram webview (webview/main.ts) and the extension (panel.ts), in
 * both directions through `postMessage`. The Sprotty action messages travel unchanged but for
 * the models the server sends (`setModel`, `updateModel`): their root travels as JSON text beside
 * the action ({@link packServerAction}). The extension relays the messages between the webview and
 * the language server's `diagram/accept` notifications (relay.ts).
 */
import type { DiagramHighlight, DiagramTarget, TextPosition } from '@maa/diagram-view/contracts';
import { parseHighlight } from '@maa/diagram-view/highlight';
import type { Action, ActionMessage } from 'sprotty-protocol';

/** Webview → extension. */
export type FromWebview =
    /** The webview's script runs and listens (sent once after mounting the diagram). */
    | { readonly type: 'ready' }
    /** An action message for the diagram server (becomes a `diagram/accept` notification). */
    | { readonly type: 'action'; readonly message: ActionMessage }
    /** The user selected diagram elements: their langium-sprotty traces (`<uri>?<range>`). */
    | { readonly type: 'select'; readonly traces: readonly string[] }
    /** The tool bar's Export SVG: the standalone SVG document and a suggested file name. */
    | { readonly type: 'saveSvg'; readonly svg: string; readonly fileName: string };

/** Extension → webview. */
export type ToWebview =
    /** Show (or switch to) a diagram. */
    | { readonly type: 'show'; readonly target: DiagramTarget }
    /**
     * An action message from the diagram server (a `diagram/accept` notification for this
     * webview's client); a model's root as JSON text in `model`, not in the action.
     */
    | { readonly type: 'action'; readonly message: ActionMessage; readonly model?: string }
    /** The editor's cursor moved: select the innermost element there. */
    | { readonly type: 'revealPosition'; readonly uri: string; readonly position: TextPosition }
    /** Live port values by port path (`"ctrl.arm"`); an empty list clears them. */
    | { readonly type: 'liveValues'; readonly values: ReadonlyArray<readonly [string, string]> }
    /** Active automaton state or mode by instance path (`"ctrl"` → `"Toasting"`); an empty list clears them. */
    | { readonly type: 'activeStates'; readonly states: ReadonlyArray<readonly [string, string]> }
    /** Export the shown diagram (the webview answers with `saveSvg`). */
    | { readonly type: 'exportSvg' }
    /** Highlight a run's trace point (a state, the transition taken) until the next one; without `highlight`: clear. */
    | { readonly type: 'highlight'; readonly highlight?: DiagramHighlight };

/**
 * The webview message of the command `maa.diagram.highlightTrace`'s argument (checked: it comes
 * from another part of the extension, maybe from a webview); throws with what is wrong.
 */
export function highlightMessage(argument: unknown): Extract<ToWebview, { type: 'highlight' }> {
    const highlight = parseHighlight(argument);
    return highlight ? { type: 'highlight', highlight } : { type: 'highlight' };
}

type ServerAction = Extract<ToWebview, { type: 'action' }>;

/**
 * A server's action message for the webview, a model's root (`newRoot` of `setModel` and
 * `updateModel`) taken out as JSON text: the way into the webview serializes and copies the
 * message three times (the extension host's call to the workbench, the workbench's post to the
 * webview's frame, that frame's to the inner one), and a text of the System diagram of 200
 * components is far cheaper to serialize and copy than its object tree (issue 18: keystroke →
 * diagram).
 */
export function packServerAction(message: ActionMessage): ServerAction {
    const action = message.action as Action & { newRoot?: unknown };
    if ((action.kind !== 'setModel' && action.kind !== 'updateModel') || action.newRoot === undefined) return { type: 'action', message };
    const { newRoot, ...rest } = action;
    return { type: 'action', message: { ...message, action: rest }, model: JSON.stringify(newRoot) };
}

/** The action message {@link packServerAction} packed, with its model's root again. */
export function unpackServerAction(packed: ServerAction): ActionMessage {
    if (packed.model === undefined) return packed.message;
    return { ...packed.message, action: { ...packed.message.action, newRoot: JSON.parse(packed.model) } as Action };
}

function isRecord(value: unknown): value is Record<string, unknown> {
    return typeof value === 'object' && value !== null;
}

function isActionMessage(value: unknown): value is ActionMessage {
    return (
        isRecord(value) && typeof value['clientId'] === 'string' && isRecord(value['action']) && typeof value['action']['kind'] === 'string'
    );
}

/** A webview's message checked for its shape (a webview is untrusted input); undefined when it is none of {@link FromWebview}. */
export function parseFromWebview(data: unknown): FromWebview | undefined {
    if (!isRecord(data)) return undefined;
    switch (data['type']) {
        case 'ready':
            return { type: 'ready' };
        case 'action':
            return isActionMessage(data['message']) ? { type: 'action', message: data['message'] } : undefined;
        case 'select': {
            const traces = data['traces'];
            return Array.isArray(traces) && traces.every((t) => typeof t === 'string') ? { type: 'select', traces } : undefined;
        }
        case 'saveSvg': {
            const { svg, fileName } = data;
            return typeof svg === 'string' && typeof fileName === 'string' ? { type: 'saveSvg', svg, fileName } : undefined;
        }
        default:
            return undefined;
    }
}
