import { mkdirSync, mkdtempSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import path from 'node:path';
import { afterAll, describe, expect, it } from 'vitest';
import { maaGen } from './maa-gen.js';
import { ensureVenv, lintPython, packageDir, repoDir, run, venvPython } from './python-env.js';

// Methods declared in class diagrams (classes, enums; static and instance) become methods of the
// generated data types whose bodies are protected regions: generated, they raise
// NotImplementedError naming the method; filled in by the user, they survive regeneration and the
// compute blocks that call them run with the user's code.
const TYPES = `package probe;
classdiagram Shapes {
  class Rect {
    double w;
    double h;
    double area();
    static Rect square(double side);
  }
  enum Color {
    RED, GREEN;
    int code();
  }
}
`;

const CALC = `package probe;

import probe.Shapes.*;

component Calc {
  port <<sync>> in double side,
       <<sync>> out double area,
       <<sync>> out int code;

  compute {
    Rect r = Rect.square(side);
    area = r.area();
    code = Color.GREEN.code();
  }
}
`;

const APP =
    'application CalcApp for probe.Calc {\n  platform timesync {\n    timesync.Components;\n    timesync.DataTypes;\n  }\n  platform rospython {\n    ros2.Components;\n    ros2.DataTypes;\n  }\n}\n';

/** Per platform: the folder to put on sys.path, the behavior module, the data type module. */
const PLATFORMS = {
    timesync: { dir: ['timesync'], behavior: 'probe.calc', types: ['timesync', 'probe', 'shapes.py'] },
    rospython: {
        dir: ['rospython', 'calc'],
        behavior: 'calc.model.probe.calc_behavior',
        types: ['rospython', 'calc', 'calc', 'model', 'probe', 'shapes.py'],
    },
} as const;

const HARNESS = `
import importlib, json, sys
sys.path.insert(0, sys.argv[1])
CalcBehavior = getattr(importlib.import_module(sys.argv[2]), "CalcBehavior")
out = {}
b = CalcBehavior(lambda port, value: out.__setitem__(port, value))
b.init()
try:
    b.step({"side": 3.0})
    print(json.dumps({"ok": out}))
except NotImplementedError as e:
    print(json.dumps({"not_implemented": str(e)}))
`;

/** The user's implementations, written between the markers of the generated module. */
const IMPLEMENTATIONS: Record<string, string> = {
    'probe.Shapes.Rect.area()': '        return self.w * self.h',
    'probe.Shapes.Rect.square(double)': '        return Rect(side, side)',
    'probe.Shapes.Color.code()': '        return 10 + self.value',
};

describe('class-diagram methods in the Python data types', () => {
    const work = mkdtempSync(path.join(tmpdir(), 'maa-cd-methods-'));
    afterAll(() => rmSync(work, { recursive: true, force: true }));
    const root = path.join(work, 'models');
    const out = path.join(work, 'out');

    async function generateAndRun(platform: keyof typeof PLATFORMS): Promise<{ ok?: Record<string, unknown>; not_implemented?: string }> {
        const gen = await run(
            process.execPath,
            [maaGen, 'generate', path.join(root, 'CalcApp.arcapp'), '--platform', platform, '--out', out],
            repoDir,
        );
        expect(gen.status, `${gen.stdout}\n${gen.stderr}`).toBe(0);
        const py = await run(
            venvPython,
            ['-c', HARNESS, path.join(out, ...PLATFORMS[platform].dir), PLATFORMS[platform].behavior],
            packageDir,
        );
        expect(py.status, py.stderr).toBe(0);
        return JSON.parse(py.stdout) as { ok?: Record<string, unknown>; not_implemented?: string };
    }

    it.each(['timesync', 'rospython'] as const)(
        '%s: generated stubs raise NotImplementedError naming the method; implementations between the markers run and survive regeneration',
        async (platform) => {
            await ensureVenv();
            mkdirSync(path.join(root, 'probe'), { recursive: true });
            writeFileSync(path.join(root, 'probe', 'Shapes.cd'), TYPES);
            writeFileSync(path.join(root, 'probe', 'Calc.arc'), CALC);
            writeFileSync(path.join(root, 'CalcApp.arcapp'), APP);
            const module = path.join(out, ...PLATFORMS[platform].types);

            const first = await generateAndRun(platform);
            expect(first.not_implemented).toContain('probe.Shapes.Rect.square(double) is declared in the class diagram');
            const text = readFileSync(module, 'utf8');
            expect(text).toContain('    @staticmethod\n    def square(side: float) -> Rect:');
            expect(text).toContain('    def area(self) -> float:');
            expect(text).toContain('    def code(self) -> int:');
            if (platform === 'timesync') expect(await lintPython(path.join(out, 'timesync'))).toEqual([]);

            // The user fills in the regions; regeneration keeps them.
            let edited = text;
            for (const [id, body] of Object.entries(IMPLEMENTATIONS)) {
                const re = new RegExp(`(# PROTECTED REGION BEGIN ${id.replace(/[.()]/g, '\\$&')}\\n)[^\\n]*\\n`);
                expect(re.test(edited), id).toBe(true);
                edited = edited.replace(re, `$1${body}\n`);
            }
            writeFileSync(module, edited);
            const second = await generateAndRun(platform);
            expect(second.ok).toEqual({ area: 9.0, code: 11 });
            expect(readFileSync(module, 'utf8')).toBe(edited);
        },
        240_000,
    );

    it('overloaded methods are refused with a message (Python has no overloading)', async () => {
        const dir = path.join(work, 'overload');
        mkdirSync(path.join(dir, 'probe'), { recursive: true });
        writeFileSync(
            path.join(dir, 'probe', 'Shapes.cd'),
            TYPES.replace('double area();', 'double area();\n    double area(double scale);'),
        );
        writeFileSync(path.join(dir, 'probe', 'Calc.arc'), CALC);
        writeFileSync(path.join(dir, 'CalcApp.arcapp'), APP);
        const gen = await run(
            process.execPath,
            [maaGen, 'generate', path.join(dir, 'CalcApp.arcapp'), '--platform', 'timesync', '--out', path.join(dir, 'out')],
            repoDir,
        );
        expect(gen.status).not.toBe(0);
        expect(`${gen.stdout}${gen.stderr}`).toContain("probe.Shapes.Rect declares the method 'area' twice");
    }, 120_000);
});
