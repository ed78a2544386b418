import { describe, expect, test } from 'vitest';
import { validate } from './helpers.js';

const model = `package toast;
import toast.types.*;

component Controller(int threshold = 30) {
  port in int distance,
       <<delayed>> out boolean start;
  int cycles = 0;
  compute {
    if (distance < threshold) { start = true; cycles++; } else { start = false; }
  }
}
`;

describe('broken models yield syntax diagnostics, never a crash', () => {
    test('every truncation of a model', async () => {
        for (let n = 0; n < model.length; n += 7) {
            const found = await validate({ 'toast/Controller.arc': model.substring(0, n) });
            for (const f of found) expect(f.code).toMatch(/^(syntax|arc|expr|link)\//);
            if (n > 20 && n < model.length - 2)
                expect(
                    found.some((f) => f.code.startsWith('syntax/')),
                    `cut at ${n}`,
                ).toBe(true);
        }
    });

    test('random bytes', async () => {
        let seed = 42;
        const rnd = (): number => (seed = (seed * 1103515245 + 12345) % 2 ** 31) / 2 ** 31;
        for (let i = 0; i < 20; i++) {
            const text = Array.from({ length: 200 }, () => String.fromCharCode(Math.floor(rnd() * 256))).join('');
            const found = await validate({ 'Noise.arc': text, 'Ok.arc': 'component Ok { }' });
            expect(found.some((f) => f.file === 'Noise.arc' && f.code.startsWith('syntax/'))).toBe(true);
            expect(found.filter((f) => f.file === 'Ok.arc')).toEqual([]);
        }
    });

    test('unbalanced braces report the position and a concise message', async () => {
        const found = await validate({ 'A.arc': 'component A {\n  port in int i;\n  compute { if (i > 0) { }\n}\n' });
        const syntax = found.filter((f) => f.code.startsWith('syntax/'));
        expect(syntax.length).toBeGreaterThan(0);
        expect(syntax[0]!.message.length).toBeLessThan(300);
        expect(syntax.map((s) => s.code)).toContain('syntax/unexpected-end');
    });
});
