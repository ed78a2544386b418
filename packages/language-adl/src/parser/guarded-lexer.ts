import { DefaultLexer, GrammarAST, AstUtils, type LangiumCoreServices, type LexerResult, type TokenizeOptions } from 'langium';
import { Codes } from '../validation/codes.js';
import { limitNesting, NESTING_LIMIT, type NestingCut } from './nesting-limit.js';

type LexingError = LexerResult['errors'][number];

/**
 * The code of a file above SIZE_LIMIT. Not in `Codes` (whose every code has a catalog entry with
 * examples, rendered into docs/diagnostics.md): an example would have to be 2 MB long; the ADL
 * catalog's introduction documents it instead.
 */
export const TOO_LARGE_CODE = 'syntax/too-large';

/**
 * The largest model file that is parsed, in characters. Larger files get one `syntax/too-large`
 * error and an empty model (docs/diagnostics.md gives the time and memory measured at the limit).
 */
export const SIZE_LIMIT = 1_000_000;

/** A lexing error of the guard: its diagnostic code and where parsing resumes after it. */
export interface GuardError extends LexingError {
    readonly code: typeof Codes.SyntaxTooDeep | typeof TOO_LARGE_CODE;
    /**
     * The regions cut out: parser errors from `offset` up to and including the token at
     * `resumeOffset` (Infinity: up to the end) are follow-ups of the cut.
     */
    readonly regions: ReadonlyArray<{ readonly offset: number; readonly resumeOffset: number }>;
}

export function isGuardError(error: LexingError): error is GuardError {
    return typeof (error as Partial<GuardError>).code === 'string' && Array.isArray((error as Partial<GuardError>).regions);
}

/**
 * The lexer of every language of the family: Langium's lexer, then a guard that keeps the parser
 * from recursing deeper than the stack allows (see nesting-limit.ts) and from parsing files that
 * would take minutes. What the guard removes is reported as a lexing error with a code, so the
 * document still gets an AST (of the text before and after the cut) and every later phase runs.
 */
export class GuardedLexer extends DefaultLexer {
    private readonly keywords: ReadonlySet<string>;

    constructor(services: LangiumCoreServices) {
        super(services);
        const keywords = new Set<string>();
        for (const node of AstUtils.streamAllContents(services.Grammar)) {
            if (GrammarAST.isKeyword(node)) keywords.add(node.value);
        }
        this.keywords = keywords;
    }

    override tokenize(text: string, options?: TokenizeOptions): LexerResult {
        if (text.length > SIZE_LIMIT) return tooLarge(text);
        const result = super.tokenize(text, options);
        const scan = limitNesting(result.tokens, this.keywords);
        if (scan.cuts.length === 0) return result;
        return { ...result, tokens: scan.tokens, errors: [...result.errors, tooDeep(scan.cuts)] };
    }
}

/** One error for all cuts of a document, at the first: one cause, one diagnostic. */
function tooDeep(cuts: readonly NestingCut[]): GuardError {
    const t = cuts[0]!.token;
    const more = cuts.length > 1 ? ` (and ${cuts.length - 1} more place${cuts.length > 2 ? 's' : ''} in this file)` : '';
    return {
        code: Codes.SyntaxTooDeep,
        offset: t.startOffset,
        line: t.startLine,
        column: t.startColumn,
        length: t.image.length,
        regions: cuts.map((c) => ({ offset: c.regionOffset, resumeOffset: c.resumeOffset })),
        message:
            `Nested too deeply${more}: '${t.image}' exceeds the nesting limit of ${NESTING_LIMIT} levels ` +
            '(a parenthesis or bracket counts 16, a brace 4, a statement keyword 2, any other keyword or operator 1 until its statement ends); ' +
            'the text up to its closing bracket or the end of its statement is not parsed.',
    };
}

function tooLarge(text: string): LexerResult {
    const error: GuardError = {
        code: TOO_LARGE_CODE,
        offset: 0,
        line: 1,
        column: 1,
        length: 1,
        regions: [{ offset: 0, resumeOffset: Infinity }],
        message: `The file has ${text.length.toLocaleString('en')} characters, more than the limit of ${SIZE_LIMIT.toLocaleString('en')}; it is not parsed (split the model into several files).`,
    };
    return { tokens: [], hidden: [], errors: [error] };
}
