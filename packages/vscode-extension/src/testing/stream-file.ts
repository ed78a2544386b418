/**
 * Where the tests of a `.stream` file stand: its component and, per `test "…" { … }` case, the
 * range of the case and of each statement that can fail (an expected stream `port == …` /
 * `port ~= …`, a `state == …`, an `empty …`). The tests themselves are parsed and run by the
 * time-synchronous runtime's runner (`maa_timesync.streamtest`, Python, behind `maa-gen test`),
 * the only parser of the format; the editor only needs positions, which this scanner finds with
 * the same tokens (comments, strings, characters) so that a `test` inside a string or comment is
 * no case. Pure (no `vscode`), lines and characters 0-based.
 */

export interface Span {
    readonly line: number;
    readonly character: number;
    readonly endLine: number;
    readonly endCharacter: number;
}

export interface StreamCase {
    readonly name: string;
    /** From `test` to the closing `}` (to the end of the file when it is missing). */
    readonly range: Span;
    /** The statement of each port's expected stream (`port == …;`, `port ~= …;`). */
    readonly expected: Readonly<Record<string, Span>>;
    /** The `state == …;` statements, in file order. */
    readonly states: readonly Span[];
    /** The `empty …;` statements, in file order. */
    readonly empties: readonly Span[];
}

export interface StreamFileOutline {
    /** The component type under test (`component a.B…;`), if the file names one. */
    readonly component?: string;
    readonly cases: readonly StreamCase[];
}

interface Token {
    readonly kind: 'string' | 'word' | 'punct' | 'other';
    readonly text: string;
    readonly start: number;
    readonly end: number;
}

const TOKEN = /\/\/[^\n]*|"(?:\\.|[^"\\\n])*"?|'(?:\\.|[^'\\\n])*'?|==|~=|[A-Za-z_][\w.]*|[=;{}]|\S/gy;

function tokens(text: string): Token[] {
    const out: Token[] = [];
    const blank = /\s+/y;
    let pos = 0;
    while (pos < text.length) {
        blank.lastIndex = pos;
        if (blank.test(text)) pos = blank.lastIndex;
        if (pos >= text.length) break;
        TOKEN.lastIndex = pos;
        const m = TOKEN.exec(text);
        if (!m) break;
        const t = m[0];
        pos = TOKEN.lastIndex;
        if (t.startsWith('//')) continue;
        const kind = t.startsWith('"') ? 'string' : /^[A-Za-z_]/.test(t) ? 'word' : /^(==|~=|[=;{}])$/.test(t) ? 'punct' : 'other';
        out.push({ kind, text: t, start: m.index, end: pos });
    }
    return out;
}

/** Offsets to 0-based line/character. */
function positions(text: string): (offset: number) => { line: number; character: number } {
    const starts = [0];
    for (let i = 0; i < text.length; i++) if (text[i] === '\n') starts.push(i + 1);
    return (offset) => {
        let lo = 0;
        let hi = starts.length - 1;
        while (lo < hi) {
            const mid = (lo + hi + 1) >> 1;
            if (starts[mid]! <= offset) lo = mid;
            else hi = mid - 1;
        }
        return { line: lo, character: offset - starts[lo]! };
    };
}

function stringValue(literal: string): string {
    try {
        return JSON.parse(literal.endsWith('"') && literal.length > 1 ? literal : `${literal}"`) as string;
    } catch {
        return literal.slice(1, literal.endsWith('"') ? -1 : undefined);
    }
}

/** The outline of a `.stream` file's text; malformed text gives what can be found (never throws). */
export function outlineStreamFile(text: string): StreamFileOutline {
    const toks = tokens(text);
    const at = positions(text);
    const span = (start: number, end: number): Span => {
        const a = at(start);
        const b = at(end);
        return { line: a.line, character: a.character, endLine: b.line, endCharacter: b.character };
    };
    const componentAt = toks.findIndex((t) => t.kind === 'word' && t.text === 'component');
    const component = componentAt >= 0 && toks[componentAt + 1]?.kind === 'word' ? toks[componentAt + 1]!.text : undefined;
    const cases: StreamCase[] = [];
    for (let i = 0; i < toks.length; i++) {
        const t = toks[i]!;
        if (!(t.kind === 'word' && t.text === 'test' && toks[i + 1]?.kind === 'string' && toks[i + 2]?.text === '{')) continue;
        const body = caseBody(toks, i + 3);
        const statements = statementsOf(toks.slice(i + 3, body.close), span);
        const end = body.close < toks.length ? toks[body.close]!.end : text.length;
        cases.push({ name: stringValue(toks[i + 1]!.text), range: span(t.start, end), ...statements });
        i = body.close;
    }
    return component === undefined ? { cases } : { component, cases };
}

/** The index of the `}` closing a case body that starts at `from` (the token count when it is missing). */
function caseBody(toks: readonly Token[], from: number): { close: number } {
    let depth = 0;
    for (let j = from; j < toks.length; j++) {
        const text = toks[j]!.text;
        if (text === '{') depth++;
        else if (text === '}') {
            if (depth === 0) return { close: j };
            depth--;
        }
        // A `test "…" {` inside means the closing brace is missing: the case ends before it.
        else if (text === 'test' && toks[j + 1]?.kind === 'string' && toks[j + 2]?.text === '{') return { close: j - 1 };
    }
    return { close: toks.length };
}

function statementsOf(body: readonly Token[], span: (start: number, end: number) => Span): Omit<StreamCase, 'name' | 'range'> {
    const expected: Record<string, Span> = {};
    const states: Span[] = [];
    const empties: Span[] = [];
    let first = 0;
    for (let j = 0; j <= body.length; j++) {
        if (j < body.length && body[j]!.text !== ';') continue;
        const stmt = body.slice(first, j);
        first = j + 1;
        const head = stmt[0];
        if (head?.kind !== 'word') continue;
        const end = j < body.length ? body[j]!.end : stmt[stmt.length - 1]!.end;
        const where = span(head.start, end);
        const op = stmt[1]?.text;
        if (head.text === 'state' && op === '==') states.push(where);
        else if (head.text === 'empty' && op !== '=' && op !== '==' && op !== '~=') empties.push(where);
        else if (op === '==' || op === '~=') expected[head.text] ??= where;
    }
    return { expected, states, empties };
}
