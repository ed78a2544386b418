import { EmptyFileSystem, createCompletionParser, createLangiumParser, type LangiumParser } from 'langium';
import { describe, expect, test } from 'vitest';
import { createAdlServices } from '../src/index.js';

// AdlParser keeps the lookahead paths of "no viable alternative" errors per rule and alternation
// (src/parser/no-viable-alt-paths.ts): the second and later errors of an alternation build their
// message from the kept paths. These texts repeat the same errors, in one file and across parses,
// and must give the errors and messages of Langium's own parser, which computes them every time.

const errors = (parser: LangiumParser, text: string): string[] =>
    parser.parse(text).parserErrors.map((e) => `${e.name} ${e.token.startOffset}: ${e.message}`);

describe('the kept lookahead paths of syntax errors', () => {
    const services = createAdlServices(EmptyFileSystem).Arc;
    const langium = createLangiumParser(services);
    const texts = [
        // the same broken statement and expression many times in one file
        `component A { port in int x; compute { ${'x = * ; '.repeat(20)} } }`,
        `component B { ${'port in ; '.repeat(10)} automaton { state S; S -> S [ x > ] ; } }`,
        `component C { port in int x; compute { if ( ) { x = 1 } else + } }`,
        `component D { ${'component ; '.repeat(5)} }`,
    ];

    test.each(texts)('%s', (text) => {
        const expected = errors(langium, text);
        expect(expected.filter((e) => e.startsWith('NoViableAltException')).length).toBeGreaterThan(0);
        // twice: the first parse may fill the cache, the second uses it
        expect(errors(services.parser.LangiumParser, text)).toEqual(expected);
        expect(errors(services.parser.LangiumParser, text)).toEqual(expected);
    });

    test('the completion parser keeps them too and gives the same contexts as Langium’s', () => {
        const plain = createCompletionParser(services);
        const contexts = (parser: typeof plain, text: string) => {
            const { elementStack, tokenIndex } = parser.parse(text);
            return { stack: elementStack.map((e) => e.$type), tokenIndex };
        };
        expect(services.parser.CompletionParser).not.toBe(plain);
        for (const text of [...texts, ...texts]) {
            for (let cut = 10; cut <= text.length; cut += 7)
                expect(contexts(services.parser.CompletionParser, text.slice(0, cut))).toEqual(contexts(plain, text.slice(0, cut)));
        }
    });
});
