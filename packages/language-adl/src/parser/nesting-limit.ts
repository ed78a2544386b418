import type { LexerResult } from 'langium';

type Token = LexerResult['tokens'][number];

/**
 * The nesting budget of one document, in "levels". Langium's parser (Chevrotain) and its CST
 * builder recurse once per nesting level, so a deeply nested input overflows the stack and takes
 * the whole language server or `maa-gen check` with it. The scanner below measures, on the token
 * stream and before the parser runs, how deep the parse will recurse and cuts out what lies
 * beyond the budget.
 *
 * The weights are measured with Node's default stack (docs/diagnostics.md, `syntax/too-deep`):
 * with a syntax error at the innermost point (error recovery needs about as much stack again as
 * the parse), parsing overflowed at 27 nested parentheses, 125 nested blocks, 94 nested states,
 * about 200 nested `if` statements, 153 nested generic types, 452 prefix operators and 3,700
 * binary operators in one expression. A parenthesis or bracket recurses through the 15 rules of
 * the expression grammar (weight 16), a brace through the statement or state rules (4), a
 * generic `<` through the type rules (3), a statement keyword through the statement rules (2),
 * and every other keyword or operator adds 1 until the statement, argument or block it belongs to
 * ends. The budget is less than half of what the parser survived (12 nested parentheses, 50 nested
 * blocks, 40 nested states, 200 prefix operators), so the later phases (linking, typing,
 * validation, formatting, hover, the diagram) that walk the same tree from deeper call stacks
 * survive it too; the tests parse and serve every kind of nesting at the limit.
 */
export const NESTING_LIMIT = 200;

const OPENERS: ReadonlyMap<string, number> = new Map([
    ['(', 16],
    ['[', 16],
    ['{', 4],
]);
const CLOSERS: ReadonlySet<string> = new Set([')', ']', '}']);
/** Tokens that end a statement, an argument or a list element: the nesting they add ends too. */
const SEPARATORS: ReadonlySet<string> = new Set([';', ',']);
/** Keywords that recurse more than one rule deep (every other keyword and operator weighs 1). */
const STATEMENT_ENDS: ReadonlySet<string> = new Set([';', '}']);
const WEIGHTS: ReadonlyMap<string, number> = new Map([
    ['<', 3],
    ['if', 2],
    ['else', 2],
    ['while', 2],
    ['for', 2],
    ['do', 2],
]);

/** A region of the token stream that was cut out because it nests beyond the budget. */
export interface NestingCut {
    /** The first token past the limit. */
    readonly token: Token;
    /**
     * Where the cut's enclosing bracket opens (else the cut token): the parser may report the
     * gap as early as there (e.g. at `(` when it decides between a cast and parentheses).
     */
    readonly regionOffset: number;
    /**
     * The end of the statement the cut is in (its `;` or `}`; Infinity at the end): the parser
     * reports the gap anywhere from regionOffset up to there.
     */
    readonly resumeOffset: number;
}

export interface NestingScan {
    readonly tokens: Token[];
    readonly cuts: readonly NestingCut[];
}

interface Level {
    readonly weight: number;
    ops: number;
    readonly open?: Token;
}

/**
 * Returns the tokens without the regions that nest deeper than `limit`: the bracket, keyword or
 * operator that would exceed it is dropped with the rest of its statement, argument or list
 * element (up to the next `;` or `,`, or the bracket that closes the enclosing one). `keywords` are the token type names that count as operators.
 */
export function limitNesting(tokens: readonly Token[], keywords: ReadonlySet<string>, limit = NESTING_LIMIT): NestingScan {
    const kept: Token[] = [];
    const cuts: NestingCut[] = [];
    const stack: Level[] = [{ weight: 0, ops: 0 }];
    let depth = 0;
    const top = (): Level => stack[stack.length - 1]!;
    const resetOps = (): void => {
        depth -= top().ops;
        top().ops = 0;
    };
    let i = 0;
    while (i < tokens.length) {
        const token = tokens[i]!;
        const name = token.tokenType.name;
        const opener = OPENERS.get(name);
        if (opener !== undefined) {
            if (depth + opener > limit) {
                i = cut(tokens, i, skipRest(tokens, i), cuts, top().open);
                continue;
            }
            stack.push({ weight: opener, ops: 0, open: token });
            depth += opener;
        } else if (CLOSERS.has(name)) {
            if (stack.length > 1) {
                const level = stack.pop()!;
                depth -= level.weight + level.ops;
            }
            // An `if` block followed by `else` nests the `else` branch into the `if` statement.
            if (name === '}' && tokens[i + 1]?.tokenType.name !== 'else') resetOps();
        } else if (SEPARATORS.has(name)) {
            if (tokens[i + 1]?.tokenType.name !== 'else') resetOps();
        } else if (keywords.has(name)) {
            const weight = WEIGHTS.get(name) ?? 1;
            if (depth + weight > limit) {
                i = cut(tokens, i, skipRest(tokens, i), cuts, top().open);
                continue;
            }
            top().ops += weight;
            depth += weight;
        }
        kept.push(token);
        i++;
    }
    return { tokens: kept, cuts };
}

function cut(tokens: readonly Token[], from: number, to: number, cuts: NestingCut[], open: Token | undefined): number {
    const token = tokens[from]!;
    let end = to;
    while (end < tokens.length && !STATEMENT_ENDS.has(tokens[end]!.tokenType.name)) end++;
    cuts.push({ token, regionOffset: open?.startOffset ?? token.startOffset, resumeOffset: tokens[end]?.startOffset ?? Infinity });
    return to;
}

/** The index of the separator or closing bracket that ends the statement or argument at `start`. */
function skipRest(tokens: readonly Token[], start: number): number {
    let open = 0;
    for (let i = start; i < tokens.length; i++) {
        const name = tokens[i]!.tokenType.name;
        if (OPENERS.has(name)) open++;
        else if (CLOSERS.has(name) && --open < 0) return i;
        else if (open === 0 && SEPARATORS.has(name) && tokens[i + 1]?.tokenType.name !== 'else') return i;
    }
    return tokens.length;
}
