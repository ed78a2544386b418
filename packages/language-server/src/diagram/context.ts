import { AstUtils, type AstNode } from 'langium';
import type { IdCache, TraceProvider } from 'langium-sprotty';
import type { SModelElement } from 'sprotty-protocol';
import type { Range } from 'vscode-languageserver';
import type { MarkerSeverity } from './model.js';

/** What the diagram builders need from the server: ids, traces and diagnostics. */
export interface BuildContext {
    /** A unique id; the proposal is used as is unless an element already has it. */
    id(proposal: string, source?: AstNode): string;
    /** Sets the element's `trace` to the source's range. */
    trace(element: SModelElement & { trace?: string }, source: AstNode): void;
    /** `error` or `warning` when such a diagnostic lies inside one of the sources' ranges. */
    severity(...sources: ReadonlyArray<AstNode | undefined>): MarkerSeverity | undefined;
}

export function buildContext(idCache: IdCache<AstNode>, traces: TraceProvider): BuildContext {
    return {
        id: (proposal, source) => idCache.uniqueId(proposal, source),
        trace: (element, source) => traces.trace(element, source),
        severity: (...sources) => {
            let found: MarkerSeverity | undefined;
            for (const source of sources) {
                const range = source?.$cstNode?.range;
                if (!source || !range) continue;
                for (const d of AstUtils.getDocument(source).diagnostics ?? []) {
                    if (!contains(range, d.range)) continue;
                    if (d.severity === 1 || d.severity === undefined) return 'error';
                    if (d.severity === 2) found = 'warning';
                }
            }
            return found;
        },
    };
}

function contains(outer: Range, inner: Range): boolean {
    const startsAfter =
        outer.start.line < inner.start.line || (outer.start.line === inner.start.line && outer.start.character <= inner.start.character);
    const endsBefore = outer.end.line > inner.end.line || (outer.end.line === inner.end.line && outer.end.character >= inner.end.character);
    return startsAfter && endsBefore;
}
