import { describe, expect, test } from 'vitest';
import { NESTING_LIMIT } from '../src/parser/nesting-limit.js';
import { SIZE_LIMIT } from '../src/parser/guarded-lexer.js';
import { dump } from '../src/testing/index.js';
import { validate, type Finding } from './helpers.js';

const component = (body: string): Record<string, string> => ({
    'A.arc': `component A {\n  port in int i;\n  port out int o;\n  port out boolean b;\n${body}\n}\n`,
});

/** A model with `k` levels of one kind of nesting, and the text of the k-th nesting token. */
interface Construct {
    model(k: number): Record<string, string>;
    /**
     * Where the first token past the limit is, for k levels: the offset of the k-th level's first
     * token, or (where a level has tokens of different weights) the tokens it may be.
     */
    tokenAt: ((text: string, k: number) => number) | readonly string[];
    /** Fewer levels than this are always accepted (docs/diagnostics.md names these figures). */
    readonly atLeast: number;
}

const nth =
    (needle: string) =>
    (text: string, k: number): number => {
        let at = -1;
        for (let n = 0; n < k; n++) at = text.indexOf(needle, at + 1);
        return at;
    };

const CONSTRUCTS: Record<string, Construct> = {
    'nested parentheses': {
        model: (k) => component(`  compute { o = ${'('.repeat(k)}i${')'.repeat(k)}; }`),
        tokenAt: nth('('),
        atLeast: 11,
    },
    'unary minus signs': { model: (k) => component(`  compute { o = ${'- '.repeat(k)}i; }`), tokenAt: nth('-'), atLeast: 180 },
    'nested blocks': {
        model: (k) => component(`  compute { ${'{ '.repeat(k)}${'} '.repeat(k)}}`),
        tokenAt: (t, k) => nth('{')(t, k + 2),
        atLeast: 45,
    },
    'nested if statements': {
        model: (k) => component(`  compute { ${'if (i > 0) '.repeat(k)}o = 1; }`),
        tokenAt: ['if', '(', '>'],
        atLeast: 60,
    },
    'else-if chain': {
        model: (k) => component(`  compute { o = 0; ${'if (i > 0) o = 1; else '.repeat(k)}o = 2; }`),
        tokenAt: ['if', '(', '>', '=', 'else'],
        atLeast: 35,
    },
    'binary operators': { model: (k) => component(`  compute { o = i${' + i'.repeat(k)}; }`), tokenAt: nth('+'), atLeast: 180 },
    'conditional operators': { model: (k) => component(`  compute { o = ${'b ? 1 : '.repeat(k)}0; }`), tokenAt: ['?', ':'], atLeast: 90 },
    'generic type arguments': {
        model: (k) => ({ 'A.arc': `component A {\n  port in ${'java.util.List<'.repeat(k)}Integer${'>'.repeat(k)} l;\n}\n` }),
        tokenAt: ['<', '.', '>'],
        atLeast: 25,
    },
};

/** The largest k whose model has no `syntax/too-deep` (binary search: nesting is monotonic). */
async function largestAccepted(c: Construct): Promise<number> {
    let lo = 1;
    let hi = 2;
    while (!(await tooDeep(c.model(hi)))) {
        lo = hi;
        hi *= 2;
        if (hi > 100_000) throw new Error('no limit found');
    }
    while (hi - lo > 1) {
        const mid = Math.floor((lo + hi) / 2);
        if (await tooDeep(c.model(mid))) hi = mid;
        else lo = mid;
    }
    return lo;
}

async function tooDeep(files: Record<string, string>): Promise<Finding[] | undefined> {
    const found = (await validate(files)).filter((f) => f.code === 'syntax/too-deep');
    return found.length > 0 ? found : undefined;
}

describe('nesting deeper than the parser can take is cut out with one syntax/too-deep error', () => {
    describe.each(Object.entries(CONSTRUCTS))('%s', (_name, c) => {
        test('at the limit: parsed and checked without syntax errors; one level more: one syntax/too-deep at the first token past the limit', async () => {
            const k = await largestAccepted(c);
            expect(k).toBeGreaterThanOrEqual(c.atLeast);
            const atLimit = await validate(c.model(k));
            expect(
                atLimit.filter((f) => f.code.startsWith('syntax/') || f.code.startsWith('internal/')),
                dump(atLimit),
            ).toEqual([]);

            const files = c.model(k + 1);
            const over = await validate(files);
            const deep = over.filter((f) => f.code === 'syntax/too-deep');
            expect(deep, dump(over)).toHaveLength(1);
            expect(deep[0]!.severity).toBe('error');
            expect(deep[0]!.message).toContain(`nesting limit of ${NESTING_LIMIT} levels`);
            const text = files['A.arc']!;
            if (typeof c.tokenAt === 'function') {
                const at = c.tokenAt(text, k + 1);
                expect(deep[0]!.line).toBe(text.substring(0, at).split('\n').length);
                expect(text.substring(at).startsWith(deep[0]!.text), `reported at '${deep[0]!.text}'`).toBe(true);
            } else {
                expect(c.tokenAt).toContain(deep[0]!.text);
            }
            // The cut leaves no follow-up syntax errors and nothing crashes in the checks.
            expect(
                over.filter((f) => f.code !== 'syntax/too-deep' && (f.code.startsWith('syntax/') || f.code.startsWith('internal/'))),
                dump(over),
            ).toEqual([]);
        });
    });

    test('10,000 levels of each kind: one syntax/too-deep, and the rest of the file is still checked', async () => {
        for (const [name, c] of Object.entries(CONSTRUCTS)) {
            const files = c.model(10_000);
            const found = await validate({
                ...files,
                'A.arc': `${files['A.arc']!.replace('component A {', 'component A {\n  port in Missing m;')}`,
            });
            expect(
                found.filter((f) => f.code === 'syntax/too-deep'),
                name,
            ).toHaveLength(1);
            expect(
                found.filter((f) => f.code.startsWith('internal/')),
                `${name}: ${dump(found)}`,
            ).toEqual([]);
            expect(
                found.map((f) => f.code),
                name,
            ).toContain('arc/unresolved-type');
        }
    });

    test('deep regions in several places: one diagnostic that counts the others', async () => {
        const deep = `o = ${'('.repeat(50)}i${')'.repeat(50)};`;
        const found = await validate(component(`  compute { ${deep} ${deep} ${deep} }`));
        const d = found.filter((f) => f.code === 'syntax/too-deep');
        expect(d).toHaveLength(1);
        expect(d[0]!.message).toContain('and 2 more places');
    });

    test('unbalanced openers (a file of 20,000 braces or parentheses) do not crash', async () => {
        for (const text of ['{'.repeat(20_000), '('.repeat(20_000), 'component A { '.repeat(5_000), ') ] }'.repeat(5_000)]) {
            const found = await validate({ 'A.arc': text });
            expect(found.some((f) => f.code.startsWith('syntax/'))).toBe(true);
            expect(
                found.filter((f) => f.code.startsWith('internal/')),
                dump(found),
            ).toEqual([]);
        }
    });
});

describe('files above the size limit are not parsed', () => {
    test(`a file of more than ${SIZE_LIMIT} characters gets one syntax/too-large error; one at the limit is parsed`, async () => {
        const pad = (n: number): string => `component A {\n  port in int i;\n}\n${' '.repeat(n)}`;
        const base = pad(0).length;
        const over = await validate({ 'A.arc': pad(SIZE_LIMIT - base + 1), 'B.arc': 'component B { port in Missing m; }' });
        const big = over.filter((f) => f.file === 'A.arc');
        expect(
            big.map((f) => f.code),
            dump(over),
        ).toEqual(['syntax/too-large']);
        expect(big[0]!.message).toContain('not parsed');
        expect(over.filter((f) => f.file === 'B.arc').map((f) => f.code)).toEqual(['arc/unresolved-type']);

        const at = await validate({ 'A.arc': pad(SIZE_LIMIT - base) });
        expect(at, dump(at)).toEqual([]);
    });
});
