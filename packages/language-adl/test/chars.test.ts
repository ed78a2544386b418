import { describe, expect, test } from 'vitest';
import { errorsOf } from './helpers.js';

/** Errors of a compute block over `in char c, in Character k, in int i, in boolean b`. */
async function errors(body: string, outs = 'out int o'): Promise<string[]> {
    return errorsOf({
        'Foo.arc': `component Foo {\n  port in char c, in Character k, in int i, in boolean b, ${outs};\n  compute {\n${body}\n  }\n}`,
    });
}

describe('char and Character', () => {
    test('valid: char + int is int, casts to char, comparisons, Character unboxes, char literals', async () => {
        expect(await errors("    o = c + 1;\n    int d = k - 'a';\n    if (c >= 'a' && c <= 'z' && k == 'q') { o = d; }")).toEqual([]);
        expect(await errors('    n = (char) (c + 1);\n    m = (char) i;\n    n = (char) k;', 'out char n, out Character m')).toEqual([]);
        expect(
            await errors(
                '    o = (int) 2.9 + (int) c;\n    long l = (long) i;\n    double x = (double) c;\n    b2 = (boolean) b;',
                'out int o, out boolean b2',
            ),
        ).toEqual([]);
    });

    test('invalid: char + int is no char without a cast; boolean and numbers do not cast into each other', async () => {
        expect(await errors('    n = c + 1;', 'out char n')).toEqual(['expr/type-mismatch@c + 1']);
        expect(await errors('    o = (int) b;')).toEqual(['expr/type-mismatch@(int) b']);
        expect(await errors('    b2 = (boolean) i;', 'out boolean b2')).toEqual(['expr/type-mismatch@(boolean) i']);
    });

    test('a parenthesized expression is no cast', async () => {
        expect(await errors('    o = (i) - 1;\n    o = (i);')).toEqual([]);
    });
});
