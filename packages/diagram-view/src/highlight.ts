/**
 * A point of a run's trace shown on the diagram (issue 19's trace-to-model debugging): the state
 * an instance was in and the transition it took, highlighted until cleared. The extension's
 * command `maa.diagram.highlightTrace` passes it on; its argument comes from another part of the
 * extension or a webview, so it is checked here. Pure: no Sprotty, no DOM.
 */

/** What to highlight: the automaton view of `component` and the state chip of `instancePath` in C&C views. */
export interface DiagramHighlight {
    /** Qualified name of the component type whose automaton (or mode automaton) took the step. */
    readonly component: string;
    /** The instance (`"ctrl"`, `""` for the application's own component). */
    readonly instancePath: string;
    /** The state (path, `Outer.Inner`) or mode the instance is in. */
    readonly state?: string;
    /** The transition taken: `index` in allTransitions order (the automaton diagram's `index` of its edges). */
    readonly transition?: { readonly from: string; readonly to: string; readonly index: number };
}

const isRecord = (v: unknown): v is Record<string, unknown> => typeof v === 'object' && v !== null && !Array.isArray(v);

/**
 * The highlight a value describes, or undefined for `undefined` (clear). Throws on anything else
 * that is not a highlight, with what is wrong.
 */
export function parseHighlight(value: unknown): DiagramHighlight | undefined {
    if (value === undefined || value === null) return undefined;
    if (!isRecord(value)) throw new Error('highlight: expected an object { component, instancePath, state?, transition? } or nothing');
    const { component, instancePath, state, transition } = value;
    if (typeof component !== 'string' || component === '') throw new Error('highlight: component must be a qualified component name');
    if (typeof instancePath !== 'string') throw new Error('highlight: instancePath must be a string ("" for the application)');
    if (state !== undefined && typeof state !== 'string') throw new Error('highlight: state must be a state path');
    const out: { -readonly [K in keyof DiagramHighlight]: DiagramHighlight[K] } = { component, instancePath };
    if (state !== undefined) out.state = state;
    if (transition !== undefined) {
        if (!isRecord(transition)) throw new Error('highlight: transition must be { from, to, index }');
        const { from, to, index } = transition;
        if (typeof from !== 'string' || typeof to !== 'string') throw new Error('highlight: transition.from and .to must be state paths');
        if (typeof index !== 'number' || !Number.isInteger(index) || index < 0)
            throw new Error('highlight: transition.index must be a non-negative integer');
        out.transition = { from, to, index };
    }
    return out;
}
