/**
 * The seams of the diagram: what a front end (the browser IDE's workbench, the VS Code
 * extension's webview) gives the diagram ({@link DiagramHost}) and what it gets back
 * ({@link DiagramView}, its live layer {@link DiagramLiveLayer}). Only these types cross the seam.
 */
import type { Position, Range } from '@maa/protocol';
import type { ActionMessage } from 'sprotty-protocol';
import type { DiagramHighlight } from './highlight.js';

export type { DiagramHighlight } from './highlight.js';

/** Something that can be undone/removed. */
export interface Disposable {
    dispose(): void;
}

/** A position in a workspace file, 0-based like LSP (@maa/protocol's one convention). */
export type TextPosition = Position;

/** A range in a workspace file, 0-based like LSP, end exclusive. */
export type TextRange = Range;

/** What the front end gives the diagram: the language server's diagram channel and the editor. */
export interface DiagramHost {
    /** Sends a Sprotty action message to the diagram server (LSP notification `diagram/accept`). */
    sendDiagramMessage(message: ActionMessage): void;
    /** Receives the diagram server's action messages (notifications `diagram/accept`). */
    onDiagramMessage(handler: (message: ActionMessage) => void): Disposable;
    /** Opens the file of a langium-sprotty trace (`<uri>?<range>`) and selects the range. */
    revealTrace(trace: string): void;
    /**
     * Saves an exported SVG document (the tool bar's Export SVG); without it the diagram offers
     * the SVG as a browser download (the VS Code webview has none, so the extension saves it).
     */
    saveSvg?(svg: string, fileName: string): void;
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

/** Highlights a point of a run's trace: a state and the transition taken (`undefined` clears). */
export interface DiagramHighlighter {
    highlight(highlight: DiagramHighlight | undefined): void;
}

/** The mounted diagram, as the front end drives it (a simulation only through {@link DiagramLiveLayer}). */
export interface DiagramView extends Disposable, DiagramLiveLayer, DiagramHighlighter {
    /** Shows (or switches to) a diagram; later edits of the model update it. */
    show(target: DiagramTarget): void;
    /** Selects the innermost element whose trace contains the position (editor → diagram). */
    revealPosition(uri: string, position: TextPosition): void;
    /** The current diagram as a standalone SVG document. */
    exportSvg(): Promise<string>;
}
