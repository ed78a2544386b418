import { describe, expect, test } from 'vitest';
import { errorsOf, validate } from './helpers.js';

const types = `package t;
classdiagram Types {
  enum Color { RED, GREEN, BLUE; }
  enum Shade { RED, DARK; }
}`;

/** A component switching over an in port of enum type `Color` (its compute block is `body`). */
async function errors(body: string, extra = ''): Promise<string[]> {
    return errorsOf({
        'Foo.arc': `import t.Types.*;
component Foo {
  port in Color color;
  port in int i;
  port out int o;
  ${extra}
  compute {
${body}
  }
}`,
        't/Types.cd': types,
    });
}

describe('switch over an enum: bare constants as case labels (valid)', () => {
    test('bare labels in groups and arrow rules, several constants in one label, the qualified form', async () => {
        expect(
            await errors(`
    int r = 0;
    switch (color) {
      case RED:
        r = 1;
        break;
      case GREEN, BLUE:
        r = 2;
    }
    switch (color) {
      case RED -> r = r + 10;
      case Color.GREEN -> r = r + 20;
      default -> r = r + 30;
    }
    o = r;`),
        ).toEqual([]);
    });

    test('a label names the constant even where the name means something else (a field RED of type int)', async () => {
        expect(
            await errors(
                `
    switch (color) {
      case RED: o = RED; break;
      default: o = 0;
    }`,
                'int RED = 7;',
            ),
        ).toEqual([]);
    });

    test('labels of a switch over an int still resolve as names of the component', async () => {
        expect(
            await errors(
                `
    switch (i) {
      case LIMIT: o = 1; break;
      default: o = 0;
    }`,
                'int LIMIT = 7;',
            ),
        ).toEqual([]);
    });
});

describe('switch over an enum: bare constants as case labels (invalid)', () => {
    test('expr/unresolved-name: a label that is no constant of the selector enum', async () => {
        expect(
            await errors(`
    switch (color) {
      case RED: o = 1; break;
      case PURPLE: o = 2;
    }`),
        ).toEqual(['expr/unresolved-name@PURPLE']);
    });

    test('expr/unresolved-name: a constant of another enum is no label of this one, and the message lists the constants', async () => {
        const found = await validate({
            'Foo.arc':
                'import t.Types.*;\ncomponent Foo {\n  port in Color color;\n  port out int o;\n  compute {\n    switch (color) { case DARK -> o = 1; default -> o = 0; }\n  }\n}',
            't/Types.cd': types,
        });
        const e = found.filter((f) => f.severity === 'error');
        expect(e.map((f) => `${f.code}@${f.text}`)).toEqual(['expr/unresolved-name@DARK']);
        expect(e[0]!.message).toContain('RED, GREEN, BLUE');
    });

    test('expr/duplicate-case-label: the same constant twice, bare and qualified', async () => {
        expect(
            await errors(`
    switch (color) {
      case RED: o = 1; break;
      case GREEN, Color.RED: o = 2;
    }`),
        ).toEqual(['expr/duplicate-case-label@Color.RED']);
        expect(await errors('    switch (color) { case BLUE -> o = 1; case BLUE -> o = 2; }')).toEqual(['expr/duplicate-case-label@BLUE']);
    });

    test('expr/type-mismatch: a qualified constant of another enum', async () => {
        expect(await errors('    switch (color) { case Shade.DARK -> o = 1; default -> o = 0; }')).toEqual([
            'expr/type-mismatch@Shade.DARK',
        ]);
    });
});
