import { readFileSync } from 'node:fs';
import path from 'node:path';
import { describe, expect, it } from 'vitest';
import { bothPlatformsApp, generate, streamTests, tempModelRoot } from './maa-gen.js';
import { ensureVenv, filesUnder, run, venvPython } from './python-env.js';

/**
 * `char` and `Character` kept apart from numbers end to end on python-timesync: Character ports
 * receive and send characters (`'a'` in the stream file, `{"char": "a"}` in the runtime's JSON),
 * `c + 1` is an int, `(char) (c + 1)` a character again, a char in a string is the character
 * (not its code), also with `+=`, comparisons and switch over chars. The component is generated and RUN
 * (`maa-gen test`); the expected values are Java's.
 */
const MODEL = `package p;

component Chars {
  port <<sync>> in Character c;
  port <<sync>> out Character next, <<sync>> out char upper, <<sync>> out int code,
       <<sync>> out String text, <<sync>> out String text2, <<sync>> out int kind;

  compute {
    next = (char) (c + 1);
    if (c >= 'a' && c <= 'z') {
      upper = (char) (c - 'a' + 'A');
    } else {
      upper = c;
    }
    code = c + 1;
    text = "<" + c + ">" + (char) 33;
    String t = "<" + c;
    t += '>';
    t += (char) 33;
    t += 1;
    text2 = t;
    switch (c) {
      case 'a', 'e', 'i', 'o', 'u':
        kind = 1;
        break;
      case 'Z':
        kind = 2;
        break;
      default:
        kind = 0;
    }
  }
}
`;

const STREAM = `component p.Chars;

test "characters in, characters and numbers out" {
  c     = 'a' Tk 'y' Tk 'Z' Tk '0' Tk;
  next  ~= 'b' 'z' '[' '1';
  upper ~= 'A' 'Y' 'Z' '0';
  code  ~= 98 122 91 49;
  text  ~= "<a>!" "<y>!" "<Z>!" "<0>!";
  text2 ~= "<a>!1" "<y>!1" "<Z>!1" "<0>!1";
  kind  ~= 1 0 2 0;
}
`;

const model = tempModelRoot('chars', { 'p/Chars.arc': MODEL, 'p/Chars.stream': STREAM, 'A.arcapp': bothPlatformsApp('p.Chars') });

describe('char and Character in generated Python', () => {
    it('python-timesync: the stream test passes', async () => {
        await ensureVenv();
        const { report, run: r } = await streamTests(path.join(model.dir, 'A.arcapp'), model.dir);
        expect(report?.results, r.stdout + r.stderr).toHaveLength(1);
        expect(
            report!.results.filter((x) => !x.passed),
            r.stdout + r.stderr,
        ).toEqual([]);
        expect(r.status).toBe(0);
    }, 240_000);

    it('rospython: char and Character ports use the character codec (one-character std_msgs/String), the build compiles', async () => {
        await ensureVenv();
        const out = path.join(model.dir, 'gen-ros2');
        const g = await generate(path.join(model.dir, 'A.arcapp'), 'rospython', out, model.dir);
        expect(g.status, g.stdout + g.stderr).toBe(0);
        const c = await run(venvPython, ['-m', 'compileall', '-q', out], model.dir);
        expect(c.status, c.stdout + c.stderr).toBe(0);
        const node = filesUnder(out).find((f) => f.endsWith(path.join('nodes', 'chars.py')));
        const text = node ? readFileSync(node, 'utf8') : '';
        // in port c (Character), out ports next (Character) and upper (char); text and text2 are Strings
        expect(text.match(/char_port\(String\)/g), text).toHaveLength(3);
        expect(text.match(/std_port\(String, str\)/g), text).toHaveLength(2);
    }, 240_000);
});
