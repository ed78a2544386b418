/**
 * langium-sprotty trace strings: `<uri>?<startLine>:<startCol>-<endLine>:<endCol>#<ast path>`.
 * The trace provider writes them with `URI.toString()`, which percent-encodes the query
 * (`?3%3A2-10%3A4`) and the fragment; both spellings are accepted. Lines and columns are
 * 0-based (LSP positions). Pure functions, no DOM.
 */
import type { TextPosition, TextRange } from './contracts.js';

export interface ParsedTrace {
    /** The document URI, normalized (see {@link normalizeUri}). */
    uri: string;
    range: TextRange;
    /** The AST node path after `#`, decoded; empty when absent. */
    fragment: string;
}

const RANGE = /^(\d+):(\d+)-(\d+):(\d+)$/;

function safeDecode(text: string): string {
    try {
        return decodeURIComponent(text);
    } catch {
        return text;
    }
}

/**
 * A comparable form of a document URI: percent-escapes decoded, scheme and drive letter in
 * lower case, no query or fragment. `file:///workspace/a%20b.arc` and `file:///workspace/a b.arc`
 * compare equal.
 */
export function normalizeUri(uri: string): string {
    let u = uri;
    const hash = u.indexOf('#');
    if (hash >= 0) u = u.slice(0, hash);
    const q = u.indexOf('?');
    if (q >= 0) u = u.slice(0, q);
    u = safeDecode(u);
    const scheme = /^([A-Za-z][A-Za-z0-9+.-]*):/.exec(u);
    if (scheme) u = scheme[1]!.toLowerCase() + u.slice(scheme[1]!.length);
    // file:///C:/x and file:///c%3A/x
    u = u.replace(/^file:\/\/\/([A-Za-z]):/, (_m, d: string) => `file:///${d.toLowerCase()}:`);
    return u;
}

/** Parses a trace string; `undefined` when it has no valid range. */
export function parseTrace(trace: string | undefined | null): ParsedTrace | undefined {
    if (!trace) return undefined;
    const q = trace.indexOf('?');
    if (q < 0) return undefined;
    const uriPart = trace.slice(0, q);
    let rest = trace.slice(q + 1);
    let fragment = '';
    const hash = rest.indexOf('#');
    if (hash >= 0) {
        fragment = safeDecode(rest.slice(hash + 1));
        rest = rest.slice(0, hash);
    }
    const m = RANGE.exec(safeDecode(rest).trim());
    if (!m) return undefined;
    const [sl, sc, el, ec] = [m[1], m[2], m[3], m[4]].map((s) => Number(s)) as [number, number, number, number];
    const range: TextRange = { start: { line: sl, character: sc }, end: { line: el, character: ec } };
    if (comparePositions(range.start, range.end) > 0) return undefined;
    return { uri: normalizeUri(uriPart), range, fragment };
}

/** Negative when a is before b, 0 when equal, positive after. */
export function comparePositions(a: TextPosition, b: TextPosition): number {
    return a.line !== b.line ? a.line - b.line : a.character - b.character;
}

/** Whether the range contains the position (start and end inclusive, like a cursor at the end of a name). */
export function rangeContains(range: TextRange, pos: TextPosition): boolean {
    return comparePositions(range.start, pos) <= 0 && comparePositions(pos, range.end) <= 0;
}

/** Whether `inner` lies within `outer`. */
export function rangeWithin(inner: TextRange, outer: TextRange): boolean {
    return comparePositions(outer.start, inner.start) <= 0 && comparePositions(inner.end, outer.end) <= 0;
}

/** A size measure for choosing the innermost of several containing ranges. */
function rangeSpan(r: TextRange): [number, number] {
    return [
        r.end.line - r.start.line,
        r.end.line === r.start.line ? r.end.character - r.start.character : r.end.character + 1_000_000 - r.start.character,
    ];
}

export interface TracedElement {
    id: string;
    trace?: string;
    /** Nesting depth in the diagram (deeper wins a tie). */
    depth?: number;
}

/**
 * The innermost element whose trace lies in `uri` and contains the position: the smallest
 * containing range; on equal ranges the deeper element of the diagram (a port before its node),
 * then the earlier one.
 */
export function findInnermostElement<T extends TracedElement>(elements: Iterable<T>, uri: string, pos: TextPosition): T | undefined {
    const target = normalizeUri(uri);
    let best: { el: T; range: TextRange } | undefined;
    for (const el of elements) {
        const t = parseTrace(el.trace);
        if (!t || t.uri !== target || !rangeContains(t.range, pos)) continue;
        if (!best) {
            best = { el, range: t.range };
            continue;
        }
        const inside = rangeWithin(t.range, best.range);
        const outside = rangeWithin(best.range, t.range);
        if (inside && outside) {
            // equal ranges
            if ((el.depth ?? 0) > (best.el.depth ?? 0)) best = { el, range: t.range };
        } else if (inside) {
            best = { el, range: t.range };
        } else if (!outside) {
            // overlapping, neither contains the other: the smaller one
            const [al, ac] = rangeSpan(t.range);
            const [bl, bc] = rangeSpan(best.range);
            if (al < bl || (al === bl && ac < bc)) best = { el, range: t.range };
        }
    }
    return best?.el;
}
