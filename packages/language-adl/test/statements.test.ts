import { describe, expect, test } from 'vitest';
import { hits } from '../src/testing/index.js';
import { errorsOf, validate } from './helpers.js';

/** A component whose compute block is `body` (ports: in int i, in String s, out int o). */
function model(body: string, extra = ''): Record<string, string> {
    return {
        'Foo.arc': `component Foo {
  port in int i;
  port in String s;
  port in char c;
  port out int o;
  ${extra}
  compute {
${body}
  }
}`,
    };
}

async function errors(body: string): Promise<string[]> {
    return errorsOf(model(body));
}

describe('switch, do-while, break and continue: valid', () => {
    test('switch groups with fall-through, several labels, default anywhere; arrow rules; switch over String and char', async () => {
        expect(
            await errors(`
    int r = 0;
    switch (i) {
      case 1:
      case 2:
        r = 10;
      case 3, 4:
        r = r + 1;
        break;
      default:
        r = -1;
      case 5:
        r = 5;
    }
    switch (s) {
      case "a" -> r = 1;
      case "b" -> { r = 2; }
      default -> r = 3;
    }
    switch (c) {
      case 'x':
        int k = 1;
        r = k;
        break;
    }
    o = r;`),
        ).toEqual([]);
    });

    test('do-while, break and continue inside loops and a switch inside a loop', async () => {
        expect(
            await errors(`
    int n = 0;
    do {
      n++;
      if (n == 2) continue;
      if (n > 5) break;
    } while (n < i);
    for (int k = 0; k < 3; k++) {
      switch (k) {
        case 1:
          continue;
        default:
          break;
      }
      while (true) { break; }
    }
    o = n;`),
        ).toEqual([]);
    });
});

describe('switch, do-while, break and continue: invalid', () => {
    test('expr/type-mismatch: a do-while condition is boolean', async () => {
        expect(await errors('    do { o = 1; } while (i);')).toEqual(['expr/type-mismatch@i']);
    });

    test('expr/type-mismatch: a switch selector of a type Java cannot switch over, a label of another type', async () => {
        expect(await errors('    switch (true) { default: o = 1; }')).toEqual(['expr/type-mismatch@true']);
        expect(await errors('    switch (i) { case "a": o = 1; }')).toEqual(['expr/type-mismatch@"a"']);
    });

    test('expr/duplicate-case-label: the same value twice, two defaults', async () => {
        expect(await errors('    switch (i) { case 1: o = 1; case 2, 1: o = 2; }')).toEqual(['expr/duplicate-case-label@1']);
        expect(await errors('    switch (i) { default: o = 1; break; default: o = 2; }')).toEqual(['expr/duplicate-case-label@default:']);
    });

    test('expr/mixed-switch-labels: colon groups and arrow rules together; an arrow rule with two statements', async () => {
        expect((await errors('    switch (i) { case 1: o = 1; case 2 -> o = 2; }')).map((e) => e.split('@')[0])).toEqual([
            'expr/mixed-switch-labels',
        ]);
        expect((await errors('    switch (i) { case 1 -> o = 1; o = 2; }')).map((e) => e.split('@')[0])).toEqual([
            'expr/mixed-switch-labels',
        ]);
    });

    test('expr/break-outside-loop and expr/continue-outside-loop', async () => {
        expect(await errors('    o = 1;\n    break;')).toEqual(['expr/break-outside-loop@break;']);
        expect(await errors('    o = 1;\n    continue;')).toEqual(['expr/continue-outside-loop@continue;']);
        // continue leaves loops only, not a switch
        expect(await errors('    switch (i) { case 1: continue; }')).toEqual(['expr/continue-outside-loop@continue;']);
    });

    test('the new keywords do not break names: a local declared in a switch group is not visible in the next statement after the switch', async () => {
        const found = await validate(model('    switch (i) { case 1: int k = 2; o = k; }\n    o = k;'));
        expect(hits(found, 'expr/unresolved-name', 'link/unresolved-reference').length).toBeGreaterThan(0);
    });
});
