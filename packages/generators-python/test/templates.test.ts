import { readdirSync, readFileSync } from 'node:fs';
import path from 'node:path';
import { describe, expect, it } from 'vitest';
import { renderLines, renderPython } from '../src/python/templates.js';
import { packageDir } from './python-env.js';

// The Python templates of the behavior emitters and the timesync generator (templates/behavior,
// templates/timesync): exact output of small views (the golden tests check whole builds), and
// that every template file is used and ships with the package.
describe('Python templates', () => {
    it('render a mode transition body: unused arguments deleted, transitions in order with their indexes, None last', () => {
        expect(
            renderLines('timesync/mode-transition.njk', {
                unused: ['trigger', 'params'],
                transitions: [
                    { index: 0, conditions: ['mode == "A"', '(inputs.get("go") == 1)'], target: 'B' },
                    { index: 1, conditions: ['mode == "B"'], target: 'A' },
                ],
            }),
        ).toEqual([
            'del trigger, params',
            'if mode == "A" and (inputs.get("go") == 1):',
            '    return 0, "B"',
            'if mode == "B":',
            '    return 1, "A"',
            'return None',
        ]);
        expect(renderLines('timesync/mode-transition.njk', { unused: [], transitions: [] })).toEqual(['return None']);
    });

    it('write Python tuples, sets and dicts with the right commas', () => {
        const view = (ins: string[], delayed: string[]) => ({
            className: 'ArmBehavior',
            qualifiedName: 'p.Arm',
            inPorts: ins,
            outPorts: ['status', 'x'],
            delayed,
            statusType: 'None',
            file: 'p/Arm.arc',
            programs: [
                {
                    name: 'home',
                    steps: ['Move(Fixed(0.0), Keep())', 'Gripper(close=True)'],
                    sources: ['(4, "move(0, keep)")', '(5, "close")'],
                },
                { name: 'idle', steps: [], sources: [] },
            ],
            commands: [{ constant: 'HOME', program: 'home' }],
        });
        const one = renderPython('behavior/robotarm.njk', view(['cmd'], []));
        expect(one).toContain('    IN_PORTS = ("cmd",)\n    OUT_PORTS = ("status", "x")\n    DELAYED = frozenset()\n');
        expect(one).toContain(
            '        "home": (\n            Move(Fixed(0.0), Keep()),\n            Gripper(close=True),\n        ),\n        "idle": (\n        ),\n',
        );
        expect(one).toContain('    COMMANDS: ClassVar[Mapping[str, str]] = {\n        "HOME": "home",\n    }\n');
        expect(one).toContain('    FILE = "p/Arm.arc"\n');
        expect(one).toContain(
            '        "home": (\n            (4, "move(0, keep)"),\n            (5, "close"),\n        ),\n        "idle": (\n        ),\n',
        );
        expect(one.endsWith('    }\n')).toBe(true);
        const none = renderPython('behavior/robotarm.njk', view([], ['status', 'x']));
        expect(none).toContain('    IN_PORTS = ()\n');
        expect(none).toContain('    DELAYED = frozenset({"status", "x"})\n');
    });

    it('render a module: docstring, import groups, two blank lines, the classes, one final newline', () => {
        expect(
            renderPython('behavior/module.py.njk', {
                doc: 'D.',
                imports: ['from typing import ClassVar', '', 'from maa_behavior import Behavior'],
                body: 'class A:\n    pass',
            }),
        ).toBe(
            '"""D."""\n\nfrom __future__ import annotations\n\nfrom typing import ClassVar\n\nfrom maa_behavior import Behavior\n\n\nclass A:\n    pass\n',
        );
    });

    it('are each rendered by an emitter or included by another template, and ship with the package', () => {
        const registry = readFileSync(path.join(packageDir, 'src', 'python', 'templates.ts'), 'utf8');
        const root = path.join(packageDir, 'templates');
        const files = ['python.njk', ...['behavior', 'timesync'].flatMap((d) => readdirSync(path.join(root, d)).map((f) => `${d}/${f}`))];
        const texts = files.map((f) => readFileSync(path.join(root, f), 'utf8')).join('\n');
        for (const f of files) {
            expect(registry.includes(`'${f}'`) || texts.includes(`"${f}"`), `${f} is neither rendered nor included`).toBe(true);
        }
        const pkg = JSON.parse(readFileSync(path.join(packageDir, 'package.json'), 'utf8')) as { files: string[] };
        expect(pkg.files).toContain('templates');
    });
});
