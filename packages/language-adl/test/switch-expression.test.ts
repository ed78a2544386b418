import { describe, expect, test } from 'vitest';
import { errorsOf, validate } from './helpers.js';

const types = `package t;
classdiagram Types {
  enum Color { RED, GREEN, BLUE; }
}`;

/** A component with ports `in int i`, `in String s`, `in Color color`, `out int o`, `out String t` whose compute block is `body`. */
async function errors(body: string, extra = ''): Promise<string[]> {
    return errorsOf({
        'Foo.arc': `import t.Types.*;
component Foo {
  port in int i;
  port in String s;
  port in Color color;
  port out int o;
  port out String t;
  ${extra}
  compute {
${body}
  }
}`,
        't/Types.cd': types,
    });
}

describe('switch expressions (valid)', () => {
    test('expression arms, block arms with yield, default; as an initializer, an argument of an operator and an assignment', async () => {
        expect(
            await errors(`
    int x = switch (i) { case 1, 2 -> 10; case 3 -> { int y = 4; yield y * 2; } default -> 0; };
    o = x + switch (s) { case "a" -> 1; default -> { if (i > 0) yield 2; else yield 3; } };
    t = switch (i) { case 1 -> "one"; default -> null; };`),
        ).toEqual([]);
    });

    test('an enum switch without default covering every constant (bare and qualified labels); the arms widen to double', async () => {
        expect(
            await errors(`
    double d = switch (color) { case RED -> 1; case GREEN, Color.BLUE -> 2.5; };
    o = (int) d;`),
        ).toEqual([]);
    });

    test('yield stays a name: a variable called yield, assigned and read; break and continue inside loops inside an arm', async () => {
        expect(
            await errors(`
    int yield = 1;
    yield = yield + 1;
    o = switch (i) {
      case 1 -> {
        int n = 0;
        for (int k = 0; k < 5; k++) { if (k == 1) continue; if (k == 3) break; n += k; }
        switch (n) { case 2: n = 7; break; default: n = 0; }
        yield n + yield;
      }
      default -> yield;
    };`),
        ).toEqual([]);
    });

    test('nested switch expressions; a yield belongs to the innermost one', async () => {
        expect(
            await errors(`
    o = switch (i) { case 1 -> { int a = switch (i + 1) { case 2 -> { yield 20; } default -> 0; }; yield a + 1; } default -> -1; };`),
        ).toEqual([]);
    });
});

describe('switch expressions (invalid)', () => {
    test('statement/switch-not-exhaustive: no default over an int; an enum constant missing', async () => {
        expect(await errors('    o = switch (i) { case 1 -> 10; };')).toEqual(['statement/switch-not-exhaustive@i']);
        const found = await validate({
            'Foo.arc':
                'import t.Types.*;\ncomponent Foo {\n  port in Color color;\n  port out int o;\n  compute {\n    o = switch (color) { case RED -> 1; case GREEN -> 2; };\n  }\n}',
            't/Types.cd': types,
        });
        const e = found.filter((f) => f.severity === 'error');
        expect(e.map((f) => `${f.code}@${f.text}`)).toEqual(['statement/switch-not-exhaustive@color']);
        expect(e[0]!.message).toContain('BLUE');
    });

    test('statement/missing-yield: a block arm that does not yield on every path', async () => {
        expect(await errors('    o = switch (i) { case 1 -> { o = 2; } default -> 0; };')).toEqual(['statement/missing-yield@{ o = 2; }']);
        expect(await errors('    o = switch (i) { case 1 -> { if (i > 0) yield 1; } default -> 0; };')).toEqual([
            'statement/missing-yield@{ if (i > 0) yield 1; }',
        ]);
    });

    test('statement/yield-outside-switch-expression: yield in a compute block and in a switch statement', async () => {
        expect(await errors('    yield 1;')).toEqual(['statement/yield-outside-switch-expression@yield 1;']);
        expect(await errors('    switch (i) { case 1 -> { yield 2; } default -> o = 1; }')).toEqual([
            'statement/yield-outside-switch-expression@yield 2;',
        ]);
    });

    test('statement/jump-out-of-switch-expression: break and continue cannot leave a switch expression', async () => {
        expect(await errors('    while (true) { o = switch (i) { case 1 -> { break; } default -> 0; }; }')).toEqual([
            'statement/jump-out-of-switch-expression@break;',
        ]);
        expect(await errors('    for (int k = 0; k < 2; k++) { o = switch (i) { case 1 -> { continue; } default -> 0; }; }')).toEqual([
            'statement/jump-out-of-switch-expression@continue;',
        ]);
    });

    test('expr/type-mismatch: arms of incompatible types; a label of the wrong type; a yield value with a problem', async () => {
        expect(await errors('    o = switch (i) { case 1 -> 1; default -> "x"; };')).toEqual(['expr/type-mismatch@"x"']);
        expect(await errors('    o = switch (i) { case "a" -> 1; default -> 2; };')).toEqual(['expr/type-mismatch@"a"']);
        expect(await errors('    o = switch (i) { case 1 -> { yield true + 1; } default -> 2; };')).toEqual([
            'expr/type-mismatch@true + 1',
        ]);
        expect(await errors('    String r = switch (i) { case 1 -> 1; default -> 2; };')).toEqual([
            'expr/type-mismatch@switch (i) { case 1 -> 1; default -> 2; }',
        ]);
    });

    test('expr/mixed-switch-labels: a colon label in a switch expression', async () => {
        expect(await errors('    o = switch (i) { case 1: 2; default -> 0; };')).toEqual(['expr/mixed-switch-labels@case 1:']);
    });

    test('expr/unresolved-name and expr/duplicate-case-label in a switch expression over an enum', async () => {
        expect(await errors('    o = switch (color) { case PURPLE -> 1; default -> 0; };')).toEqual(['expr/unresolved-name@PURPLE']);
        expect(await errors('    o = switch (color) { case RED -> 1; case Color.RED -> 2; default -> 0; };')).toEqual([
            'expr/duplicate-case-label@Color.RED',
        ]);
    });
});
