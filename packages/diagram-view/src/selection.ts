/**
 * Selection between the diagram and the editor: a user's selection in the diagram becomes the
 * traces of the selected elements (diagram → editor); a text position becomes the innermost
 * selectable element whose trace contains it (editor → diagram).
 */
import type { IActionHandler } from 'sprotty';
import { SelectAction, type Action } from 'sprotty-protocol';
import type { TextPosition } from './contracts.js';
import { walkSchema, type SchemaElement } from './schema.js';
import { findInnermostElement, type TracedElement } from './trace.js';

/** Element types that can be selected (labels and compartments select their parent). */
const SELECTABLE_TYPES = new Set([
    'node:component',
    'port',
    'edge:connector',
    'node:state',
    'edge:transition',
    'node:generic',
    'edge:generic',
]);

/** The traces of the elements with these ids, in model order. */
export function tracesOf(schema: SchemaElement, ids: ReadonlySet<string>): string[] {
    const traces: string[] = [];
    for (const { el } of walkSchema(schema)) if (ids.has(el.id) && typeof el['trace'] === 'string') traces.push(el['trace'] as string);
    return traces;
}

/** The id of the innermost selectable element (not the root) whose trace contains the position. */
export function elementAt(schema: SchemaElement, uri: string, position: TextPosition): string | undefined {
    const els: TracedElement[] = [];
    for (const { el, depth } of walkSchema(schema)) {
        if (typeof el['trace'] === 'string' && el !== schema && SELECTABLE_TYPES.has(el.type))
            els.push({ id: el.id, trace: el['trace'] as string, depth });
    }
    return findInnermostElement(els, uri, position)?.id;
}

/**
 * The handler of the user's `SelectAction`s: the traces of what was selected go to `onTraces`.
 * Selections the diagram made itself (`isOwn`) and empty ones are ignored.
 */
export function selectionHandler(
    schema: () => SchemaElement | undefined,
    isOwn: (action: Action) => boolean,
    onTraces: (traces: string[]) => void,
): IActionHandler {
    return {
        handle: (action: Action): void => {
            const root = schema();
            if (isOwn(action) || action.kind !== SelectAction.KIND || !root) return;
            const ids = new Set((action as SelectAction).selectedElementsIDs);
            if (ids.size === 0) return;
            const traces = tracesOf(root, ids);
            if (traces.length > 0) onTraces(traces);
        },
    };
}
