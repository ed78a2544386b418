/**
 * Selection both ways between the editor and the diagram, without VS Code's API: the source
 * range of a selected diagram element (its langium-sprotty trace), and the component or
 * automaton at the cursor from the document's symbols (the outline the language server gives).
 */
import { parseTrace } from '@maa/diagram-view/trace';
import type { DiagramTarget, TextPosition, TextRange } from '@maa/diagram-view/contracts';

/** Where the first selected element comes from: the document URI (as the trace writes it) and the range. */
export function selectionSource(traces: readonly string[]): { uri: string; range: TextRange } | undefined {
    for (const trace of traces) {
        const parsed = parseTrace(trace);
        if (parsed) return { uri: parsed.uri, range: parsed.range };
    }
    return undefined;
}

/** A document symbol as far as the lookups read it (VS Code's `DocumentSymbol` has this shape). */
export interface SymbolNode {
    readonly name: string;
    readonly kind: number;
    readonly range: TextRange;
    /** Absent for a leaf in LSP's DocumentSymbol. */
    readonly children?: readonly SymbolNode[];
}

/** The outline names of the two automata a component may have (language-automata's symbols). */
const AUTOMATON_SYMBOLS = new Set(['automaton', 'mode automaton']);

function before(a: TextPosition, b: TextPosition): boolean {
    return a.line < b.line || (a.line === b.line && a.character < b.character);
}

function contains(range: TextRange, p: TextPosition): boolean {
    return !before(p, range.start) && !before(range.end, p);
}

/** The symbols containing the position, outermost first. */
export function symbolPath(symbols: readonly SymbolNode[], position: TextPosition): SymbolNode[] {
    const path: SymbolNode[] = [];
    let level = symbols;
    for (;;) {
        const hit = level.find((s) => contains(s.range, position));
        if (!hit) return path;
        path.push(hit);
        level = hit.children ?? [];
    }
}

/** The package a model file declares (`package a.b;`), empty when none. */
export function packageOf(text: string): string {
    const stripped = text.replace(/\/\*[\s\S]*?\*\//g, '').replace(/\/\/[^\n]*/g, '');
    return /^\s*package\s+([\w.]+)\s*;/.exec(stripped)?.[1] ?? '';
}

/** The qualified name of the innermost component around the position (`componentKind`: the symbol kind of components). */
export function componentAt(
    symbols: readonly SymbolNode[],
    position: TextPosition,
    pkg: string,
    componentKind: number,
): string | undefined {
    const names = symbolPath(symbols, position)
        .filter((s) => s.kind === componentKind)
        .map((s) => s.name);
    if (names.length === 0) return undefined;
    return [pkg, ...names].filter((n) => n !== '').join('.');
}

/** Whether the position is inside an automaton (or a mode automaton) of a component. */
export function inAutomaton(symbols: readonly SymbolNode[], position: TextPosition): boolean {
    return symbolPath(symbols, position).some((s) => AUTOMATON_SYMBOLS.has(s.name));
}

/**
 * What **Open Diagram** (`automaton`: false) or **Open Automaton View** shows for a cursor: the
 * component around it (the file's first component when the cursor is outside every component),
 * as architecture or automaton. The automaton view needs the cursor inside an automaton.
 */
export function targetAt(
    uri: string,
    symbols: readonly SymbolNode[],
    position: TextPosition,
    text: string,
    componentKind: number,
    automaton: boolean,
): DiagramTarget | undefined {
    const component = componentAt(symbols, position, packageOf(text), componentKind);
    if (automaton) return component && inAutomaton(symbols, position) ? { uri, component, diagramType: 'maa-automaton' } : undefined;
    return component ? { uri, component, diagramType: 'maa-cc' } : { uri, diagramType: 'maa-cc' };
}
