import type { LexerResult } from 'langium';

type Token = LexerResult['tokens'][number];

/** What Chevrotain's error message provider gets for a "no viable alternative" error. */
interface NoViableAltOptions {
    expectedPathsPerAlt: unknown;
    actual: Token[];
    previous: Token;
    customUserDescription: string | undefined;
    ruleName: string;
}

/** The members of Chevrotain's parser (Langium's `wrapper`) that the cache uses; private in its typings. */
export interface ChevrotainErrorHandler {
    raiseNoAltException(occurrence: number, errMsgTypes: string | undefined): never;
    getCurrRuleFullName(): string;
    LA(i: number): Token;
    maxLookahead: number;
    errorMessageProvider: { buildNoViableAltMessage(options: NoViableAltOptions): string };
    SAVE_ERROR(error: Error): Error;
}

type RecognitionExceptionClass = new (message: string, token: Token, previous: Token) => Error;

/**
 * Keeps the lookahead paths of the "no viable alternative" error messages per rule and alternation.
 * For each such syntax error Chevrotain computes, from the grammar, every token sequence that
 * could have started each alternative (`getLookaheadPathsForOr`, marked "consider caching" in its
 * source): a function of the rule and the alternation's occurrence only, and in the family's
 * composed grammar expensive (tens of milliseconds for a statement or an expression). A file with
 * many syntax errors, as while typing, recomputed them for every error: the fuzz corpus spent
 * three quarters of its parse time there (issue 18, `node --cpu-prof`). The first error of an
 * alternation runs Chevrotain's own code and keeps the paths its message provider was given; later
 * ones build the message with the same provider from the same inputs and throw the same exception,
 * so errors and messages are unchanged (test/adl-parser.test.ts compares them with Langium's parser).
 */
export function cacheNoViableAltPaths(parser: ChevrotainErrorHandler): void {
    const raise: ChevrotainErrorHandler['raiseNoAltException'] = parser.raiseNoAltException.bind(parser);
    const provider = parser.errorMessageProvider;
    const paths = new Map<string, unknown>();
    let exceptionClass: RecognitionExceptionClass | undefined;
    let lastPaths: unknown;
    const recording = Object.create(provider) as typeof provider;
    recording.buildNoViableAltMessage = (options) => {
        lastPaths = options.expectedPathsPerAlt;
        return provider.buildNoViableAltMessage(options);
    };
    parser.errorMessageProvider = recording;
    parser.raiseNoAltException = (occurrence, errMsgTypes) => {
        const ruleName = parser.getCurrRuleFullName();
        const key = `${ruleName}#${occurrence}`;
        const known = paths.get(key);
        if (known === undefined || exceptionClass === undefined) {
            lastPaths = undefined;
            try {
                raise(occurrence, errMsgTypes);
            } catch (error) {
                if (lastPaths !== undefined && error instanceof Error) {
                    paths.set(key, lastPaths);
                    exceptionClass ??= error.constructor as RecognitionExceptionClass;
                }
                throw error;
            }
        }
        // As Chevrotain's raiseNoAltException, with the paths computed before.
        const actual: Token[] = [];
        for (let i = 1; i <= parser.maxLookahead; i++) actual.push(parser.LA(i));
        const previous = parser.LA(0);
        const message = parser.errorMessageProvider.buildNoViableAltMessage({
            expectedPathsPerAlt: known,
            actual,
            previous,
            customUserDescription: errMsgTypes,
            ruleName,
        });
        throw parser.SAVE_ERROR(new exceptionClass(message, parser.LA(1), previous));
    };
}
