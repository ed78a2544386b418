import { readFileSync } from 'node:fs';
import path from 'node:path';
import { describe, expect, it } from 'vitest';
import { bothPlatformsApp, generate, streamTests, tempModelRoot } from './maa-gen.js';
import { ensureVenv, filesUnder, pythonFiles, run, venvPython } from './python-env.js';

/**
 * Java's switch (fall-through, default in the middle, arrow rules), do-while, break and continue
 * (in a for loop, in a do-while, inside a switch inside a loop) and an `autoconnect`ed
 * architecture, generated for python-timesync and RUN through stream tests (`maa-gen test`);
 * the rospython build of the same model is generated and byte-compiled. The expected values are
 * what Java computes for the compute block (worked out in the comments).
 */
const MODEL = `package p;

component Calc {
  port <<sync>> in int i;
  port <<sync>> out int grade, <<sync>> out int odds, <<sync>> out int sum, <<sync>> out int kind;

  compute {
    int g = 0;
    switch (i) {
      case 1:
        g = g + 100;
      case 2:
      case 3:
        g = g + 10;
        break;
      default:
        g = -1;
      case 9:
        g = g + 9;
    }
    grade = g;
    int n = 0;
    int k = 0;
    do {
      k++;
      if (k % 2 == 0) continue;
      n = n + k;
    } while (k < i);
    odds = n;
    int e = 0;
    for (int j = 0; j < 10; j++) {
      switch (j % 3) {
        case 0:
          continue;
        case 1:
          e = e + j;
          break;
        default:
          if (j > i) {
            break;
          }
          e = e + 100;
      }
      if (j == 8) break;
    }
    sum = e;
    switch (i) {
      case 0, 1 -> kind = 0;
      case 2 -> {
        kind = 2;
      }
      default -> kind = 7;
    }
  }
}
`;

const ROOT = `package p;

// The subcomponent's ports are connected by name: i -> calc.i, calc.grade -> grade, ...
component Root {
  port <<sync>> in int i;
  port <<sync>> out int grade, <<sync>> out int odds, <<sync>> out int sum, <<sync>> out int kind;
  Calc calc;
  autoconnect port;
}
`;

// i = 1: 100 + 10 (falls into case 2/3) = 110; i = 5 and i = 0: default -1 falls into case 9: 8.
// odds: the odd k in 1..max(i, 1) (continue jumps to the do-while's condition).
// sum: j = 1, 4, 7 add themselves; j = 2, 5, 8 add 100 unless j > i (break leaves the switch
// only); j = 0, 3, 6 continue (the for update still runs); j == 8 ends the loop.
const STREAMS = (component: string): string => `component ${component};

test "switch, do-while, break and continue" {
  i      = 1 Tk 2 Tk 5 Tk 9 Tk 0 Tk;
  grade ~= 110 10 8 9 8;
  odds  ~= 1 1 9 25 1;
  sum   ~= 12 112 212 312 12;
  kind  ~= 0 2 7 7 0;
}
`;

const model = tempModelRoot('control-flow', {
    'p/Calc.arc': MODEL,
    'p/Root.arc': ROOT,
    'p/Calc.stream': STREAMS('p.Calc'),
    'p/Root.stream': STREAMS('p.Root'),
    'A.arcapp': bothPlatformsApp('p.Root'),
});

describe('switch, do-while, break, continue and autoconnect in generated Python', () => {
    it('python-timesync: the stream tests of the component and of the autoconnected root pass', async () => {
        await ensureVenv();
        const { report, run: r } = await streamTests(path.join(model.dir, 'A.arcapp'), model.dir);
        expect(report?.results, r.stdout + r.stderr).toBeDefined();
        expect(
            report!.results.filter((x) => !x.passed),
            r.stdout + r.stderr,
        ).toEqual([]);
        expect(report!.results.map((x) => path.basename(x.file)).sort()).toEqual(['Calc.stream', 'Root.stream']);
        expect(r.status).toBe(0);
    }, 240_000);

    it('rospython: the same model generates and compiles; the switch is translated, the implied connectors are wired', async () => {
        await ensureVenv();
        const out = path.join(model.dir, 'gen-ros2');
        const g = await generate(path.join(model.dir, 'A.arcapp'), 'rospython', out, model.dir);
        expect(g.status, g.stdout + g.stderr).toBe(0);
        const c = await run(venvPython, ['-m', 'compileall', '-q', out], model.dir);
        expect(c.status, c.stdout + c.stderr).toBe(0);
        const text = pythonFiles(out)
            .map((f) => readFileSync(f, 'utf8'))
            .join('\n');
        expect(text).toContain('_maa_sw');
        expect(text).toContain('_maa_first');
        // The subcomponent reads the root's in port only through the implied connector i -> calc.i.
        const deployment = filesUnder(out, 'deployment.json').map((f) => JSON.parse(readFileSync(f, 'utf8')) as Deployment)[0];
        const calc = deployment?.nodes.find((n) => n.instance === 'root.calc');
        expect(calc?.subscribes, JSON.stringify(deployment)).toEqual([expect.objectContaining({ port: 'i', topic: '/root/i' })]);
    }, 240_000);
});

interface Deployment {
    nodes: Array<{ instance: string; subscribes: Array<{ port: string; topic: string }> }>;
}
