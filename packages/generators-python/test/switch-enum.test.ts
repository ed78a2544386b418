import path from 'node:path';
import { describe, expect, it } from 'vitest';
import { bothPlatformsApp, generate, streamTests, tempModelRoot } from './maa-gen.js';
import { ensureVenv, filesUnder, run, venvPython } from './python-env.js';

/**
 * A switch over an enum in port whose case labels are bare constants (`case RED:`, `case GREEN,
 * BLUE ->`) next to the qualified form (`case Color.GREEN ->`), generated for both Python
 * platforms and RUN: python-timesync through its stream test (`maa-gen test`), rospython by
 * stepping the generated behavior class (plain Python, no ROS needed) for every constant.
 * Expected values are what Java computes (RED falls through into GREEN/BLUE: 1 + 10).
 */
const TYPES = `package p;

classdiagram Types {
  enum Color { RED, GREEN, BLUE, BLACK; }
}
`;

const PAINT = `package p;

import p.Types.*;

component Paint {
  port <<sync>> in Color c;
  port <<sync>> out int code;
  port <<sync>> out Color next;

  compute {
    int k = 0;
    switch (c) {
      case RED:
        k = 1;
      case GREEN, BLUE:
        k = k + 10;
        break;
      default:
        k = -1;
    }
    code = k;
    switch (c) {
      case RED -> next = Color.GREEN;
      case Color.GREEN -> next = Color.BLUE;
      case BLUE -> {
        next = Color.RED;
      }
      default -> next = c;
    }
  }
}
`;

const STREAM = `component p.Paint;

test "a switch over an enum in port with bare constant labels" {
  c    = RED Tk GREEN Tk BLUE Tk BLACK Tk;
  code ~= 11 10 10 -1;
  next ~= GREEN BLUE RED BLACK;
}
`;

/** Steps the generated ROS 2 behavior class once per constant and prints what it emitted. */
const STEP_ROS2 = `import json, sys
sys.path.insert(0, sys.argv[1])
from paint.model.p.paint_behavior import PaintBehavior
from paint.model.p.types import Color
out = []
for color in (Color.RED, Color.GREEN, Color.BLUE, Color.BLACK):
    emitted = {}
    b = PaintBehavior(lambda port, value: emitted.__setitem__(port, value))
    b.step({"c": color})
    out.append([emitted["code"], emitted["next"].name])
print(json.dumps(out))
`;

const model = tempModelRoot('switch-enum', {
    'p/Types.cd': TYPES,
    'p/Paint.arc': PAINT,
    'p/Paint.stream': STREAM,
    'A.arcapp': bothPlatformsApp('p.Paint'),
});

describe('a switch over an enum with bare constant labels in generated Python', () => {
    it('python-timesync: the stream test passes', async () => {
        await ensureVenv();
        const { report, run: r } = await streamTests(path.join(model.dir, 'A.arcapp'), model.dir);
        expect(report?.results, r.stdout + r.stderr).toBeDefined();
        expect(report!.results.map((x) => [x.test, x.passed, x.problems])).toEqual([
            ['a switch over an enum in port with bare constant labels', true, []],
        ]);
        expect(r.status).toBe(0);
    }, 240_000);

    it('rospython: the generated behavior computes the same outputs', async () => {
        await ensureVenv();
        const out = path.join(model.dir, 'gen-ros2');
        const g = await generate(path.join(model.dir, 'A.arcapp'), 'rospython', out, model.dir);
        expect(g.status, g.stdout + g.stderr).toBe(0);
        const behavior = filesUnder(out).find((f) => path.basename(f) === 'paint_behavior.py');
        expect(behavior, 'paint_behavior.py generated').toBeDefined();
        // .../<pkg root>/paint/model/p/paint_behavior.py: the package root holds paint/ and maa_behavior/.
        const pkgRoot = path.resolve(path.dirname(behavior!), '..', '..', '..');
        const r = await run(venvPython, ['-c', STEP_ROS2, pkgRoot], model.dir);
        expect(r.status, r.stdout + r.stderr).toBe(0);
        expect(JSON.parse(r.stdout)).toEqual([
            [11, 'GREEN'],
            [10, 'BLUE'],
            [10, 'RED'],
            [-1, 'BLACK'],
        ]);
    }, 240_000);
});
