/**
 * The seams between the parts of the browser app: the workbench shell (editor, explorer,
 * problems, generate panel) owns the language client and the layout; the diagram and the
 * simulate panel are mounted into containers it hands out. Only these types cross the seams.
 */
import type { AppInfo, Position, Range } from '@maa/protocol';
import type { ActionMessage } from 'sprotty-protocol';

/** Something that can be undone/removed. */
export interface Disposable {
    dispose(): void;
}

/** A position in a workspace file, 0-based like LSP (@maa/protocol's one convention). */
export type TextPosition = Position;

/** A range in a workspace file, 0-based like LSP, end exclusive. */
export type TextRange = Range;

/** What the shell gives the diagram: the language server's diagram channel and the editor. */
export interface DiagramHost {
    /** Sends a Sprotty action message to the diagram server (LSP notification `diagram/accept`). */
    sendDiagramMessage(message: ActionMessage): void;
    /** Receives the diagram server's action messages (notifications `diagram/accept`). */
    onDiagramMessage(handler: (message: ActionMessage) => void): Disposable;
    /** Opens the file of a langium-sprotty trace (`<uri>?<range>`) and selects the range. */
    revealTrace(trace: string): void;
}

/** Which diagram to show. */
export interface DiagramTarget {
    /** `file:///workspace/...` of a model file of the root to show. */
    uri: string;
    /** Qualified component name; default: the first component of the file. */
    component?: string;
    /** `maa-cc` (architecture) or `maa-automaton` (the component's state machine). */
    diagramType: 'maa-cc' | 'maa-automaton';
}

/**
 * The diagram's extension point for a simulation run (what the simulate panel uses): live values
 * on ports and connectors, the active automaton state or mode of each instance, and the user's
 * selection.
 */
export interface DiagramLiveLayer {
    /** Live values by port path (`"ctrl.arm"`); shown on connectors and ports. Empty map clears. */
    setLiveValues(values: ReadonlyMap<string, string>): void;
    /** Active automaton state or mode by instance path (`"ctrl"` → `"Toasting"`). Empty map clears. */
    setActiveStates(states: ReadonlyMap<string, string>): void;
    /** Called when the user selects diagram elements (their traces). */
    onSelect(handler: (traces: string[]) => void): Disposable;
}

/** The mounted diagram, as the shell drives it (the simulate panel only through {@link DiagramLiveLayer}). */
export interface DiagramView extends Disposable, DiagramLiveLayer {
    /** Shows (or switches to) a diagram; later edits of the model update it. */
    show(target: DiagramTarget): void;
    /** Selects the innermost element whose trace contains the position (editor → diagram). */
    revealPosition(uri: string, position: TextPosition): void;
    /** The current diagram as a standalone SVG document. */
    exportSvg(): Promise<string>;
}

/** One application configuration of the workspace (`GET /api/apps`, @maa/protocol). */
export type { AppInfo };

/** What the shell gives the simulate panel. */
export interface SimulateHost {
    /** The diagram's live layer, for live values and active states during a run. */
    diagram: DiagramLiveLayer;
    /** The application configurations of the workspace (fresh from the backend). */
    apps(): Promise<AppInfo[]>;
    /** Reports a message in the shell's status line / notifications. */
    notify(severity: 'info' | 'warning' | 'error', message: string): void;
}
