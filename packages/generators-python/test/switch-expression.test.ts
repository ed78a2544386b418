import { readFileSync } from 'node:fs';
import path from 'node:path';
import { describe, expect, it } from 'vitest';
import { bothPlatformsApp, generate, streamTests, tempModelRoot } from './maa-gen.js';
import { ensureVenv, filesUnder, run, venvPython } from './python-env.js';

/**
 * Switch expressions (expression arms, block arms with `yield`, a block arm with a loop and
 * `break`, a switch expression as the selector and as an arm, an enum switch without default)
 * generated for both Python platforms and RUN: python-timesync through its stream test
 * (`maa-gen test`), rospython by stepping the generated behavior class (plain Python, no ROS).
 * Expected values are what Java computes:
 * - a: i = 1, 2 -> 10; i = 3 -> 4 * 2 = 8; else 0.
 * - b: the selector (a switch expression whose block arm counts `evals`) is evaluated once:
 *   i = 1 -> total = 5, k = 3, yield 5 + 3 + 100 = 108; i = 2 -> (i + 1 == 3) -2; else 7 if i > 5, else 8.
 * - n: evals * 1000 + total: 1005 for i = 1, else 1000 (the selector ran exactly once).
 * - w: over the enum port c.
 */
const TYPES = `package p;

classdiagram Types {
  enum Color { RED, GREEN, BLUE, BLACK; }
}
`;

const CALC = `package p;

import p.Types.*;

component Calc {
  port <<sync>> in int i;
  port <<sync>> in Color c;
  port <<sync>> out int a, <<sync>> out int b, <<sync>> out int n, <<sync>> out String w;

  compute {
    a = switch (i) { case 1, 2 -> 10; case 3 -> { int y = 4; yield y * 2; } default -> 0; };
    int evals = 0;
    int total = 0;
    int yield = 100;
    b = switch (switch (i) { default -> { evals++; yield i; } }) {
      case 1 -> {
        total = total + 5;
        int k = 0;
        while (true) {
          k++;
          if (k == 3) break;
        }
        yield total + k + yield;
      }
      case 2 -> switch (i + 1) { case 3 -> { yield -2; } default -> -3; };
      default -> {
        if (i > 5) yield 7;
        else yield 8;
      }
    };
    n = evals * 1000 + total;
    w = switch (c) { case RED -> "r"; case GREEN, Color.BLUE -> "gb"; case BLACK -> "k"; };
  }
}
`;

const STREAM = `component p.Calc;

test "switch expressions: expression arms, block arms, nested, over an enum" {
  i = 1 Tk 2 Tk 3 Tk 9 Tk 0 Tk;
  c = RED Tk GREEN Tk BLUE Tk BLACK Tk RED Tk;
  a ~= 10 10 8 0 0;
  b ~= 108 -2 8 7 8;
  n ~= 1005 1000 1000 1000 1000;
  w ~= "r" "gb" "gb" "k" "r";
}
`;

/** Steps the generated ROS 2 behavior class once per input pair and prints what it emitted. */
const STEP_ROS2 = `import json, sys
sys.path.insert(0, sys.argv[1])
from calc.model.p.calc_behavior import CalcBehavior
from calc.model.p.types import Color
out = []
for i, color in ((1, Color.RED), (2, Color.GREEN), (3, Color.BLUE), (9, Color.BLACK), (0, Color.RED)):
    emitted = {}
    b = CalcBehavior(lambda port, value: emitted.__setitem__(port, value))
    b.step({"i": i, "c": color})
    out.append([emitted["a"], emitted["b"], emitted["n"], emitted["w"]])
print(json.dumps(out))
`;

const model = tempModelRoot('switch-expression', {
    'p/Types.cd': TYPES,
    'p/Calc.arc': CALC,
    'p/Calc.stream': STREAM,
    'A.arcapp': bothPlatformsApp('p.Calc'),
});

describe('switch expressions in generated Python', () => {
    it('python-timesync: the stream test passes', async () => {
        await ensureVenv();
        const { report, run: r } = await streamTests(path.join(model.dir, 'A.arcapp'), model.dir);
        expect(report?.results, r.stdout + r.stderr).toBeDefined();
        expect(report!.results.map((x) => [x.passed, x.problems])).toEqual([[true, []]]);
        expect(r.status).toBe(0);
    }, 240_000);

    it('rospython: the generated behavior computes the same outputs; block arms are local functions', async () => {
        await ensureVenv();
        const out = path.join(model.dir, 'gen-ros2');
        const g = await generate(path.join(model.dir, 'A.arcapp'), 'rospython', out, model.dir);
        expect(g.status, g.stdout + g.stderr).toBe(0);
        const behavior = filesUnder(out).find((f) => path.basename(f) === 'calc_behavior.py');
        expect(behavior, 'calc_behavior.py generated').toBeDefined();
        // Block arms are annotated local functions (ruff's ANN rules of the generated-code settings).
        expect(readFileSync(behavior!, 'utf8')).toMatch(/^ {8}def _maa_arm\d+\(\) -> object:$/m);
        const pkgRoot = path.resolve(path.dirname(behavior!), '..', '..', '..');
        const r = await run(venvPython, ['-c', STEP_ROS2, pkgRoot], model.dir);
        expect(r.status, r.stdout + r.stderr).toBe(0);
        expect(JSON.parse(r.stdout)).toEqual([
            [10, 108, 1005, 'r'],
            [10, -2, 1000, 'gb'],
            [8, 8, 1000, 'gb'],
            [0, 7, 1000, 'k'],
            [0, 8, 1000, 'r'],
        ]);
    }, 240_000);
});
