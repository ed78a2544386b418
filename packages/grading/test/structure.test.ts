import { afterAll, beforeAll, describe, expect, test } from 'vitest';
import type { StructureCriterion } from '@maa/protocol/grading';
import { gradeDiagnostics, gradeStructure, loadSubmissionModel, type SubmissionModel } from '../src/index.js';
import { tempDir, writeFiles } from './exercise.js';

const MODEL = {
    'shop/Types.cd': 'package shop;\n\nclassdiagram Types {\n  enum Cmd { GO, STOP; }\n}\n',
    'shop/Gate.arc': `package shop;

import shop.Types.*;

component Gate {
  port in int distance,
       out Cmd cmd;

  <<sync>> automaton {
    initial { cmd = Cmd.STOP; } state Closed;
    state Open;
    Closed -> Open [distance < 10] / { cmd = Cmd.GO; };
    Open -> Closed [distance >= 10] / { cmd = Cmd.STOP; };
    Open -> Open [distance < 5];
  }
}
`,
    'shop/Double.arc': `package shop;

component Double {
  port in int i, out int o;
  compute { o = i * 2; }
}
`,
    'shop/Shop.arc': `package shop;

component Shop {
  port in int distance;
  Gate gate;
  Double twice;
  distance -> gate.distance;
  distance -> twice.i;
}
`,
};

const criterion = (require: StructureCriterion['require']): StructureCriterion => ({
    id: 'arch',
    title: 'Architecture',
    kind: 'structure',
    weight: 20,
    require,
});

describe('structure criterion (checked on the symbols)', () => {
    const work = tempDir('structure');
    let model: SubmissionModel;
    beforeAll(async () => {
        writeFiles(work.dir, MODEL);
        model = await loadSubmissionModel(work.dir, `${work.dir}/none.arcapp`);
    });
    afterAll(() => work.remove());

    test('a model that has everything required gets every point', () => {
        const grade = gradeStructure(
            criterion([
                {
                    component: 'shop.Gate',
                    ports: [
                        { name: 'distance', direction: 'in', type: 'int' },
                        { name: 'cmd', direction: 'out', type: 'Cmd' },
                    ],
                    behavior: { kind: 'automaton', minStates: 2, minTransitions: 3, states: ['Open', 'Closed'] },
                },
                {
                    component: 'shop.Shop',
                    subcomponents: [{ name: 'gate', type: 'shop.Gate' }, { type: 'shop.Double' }],
                    behavior: { kind: 'composed' },
                },
                { component: 'shop.Double', behavior: { kind: 'compute' }, ports: [{ name: 'o', type: 'int' }] },
            ]),
            model,
        );
        expect(grade.score).toBe(20);
        expect(grade.max).toBe(20);
        expect(grade.feedback).toEqual([{ severity: 'info', text: expect.stringContaining('All 15 structure checks met') }]);
    });

    test('each unmet check costs its share and says what is wrong, with the element', () => {
        const grade = gradeStructure(
            criterion([
                {
                    component: 'shop.Gate',
                    ports: [
                        { name: 'distance', direction: 'out' },
                        { name: 'cmd', type: 'int' },
                        { name: 'speed', direction: 'in' },
                    ],
                    behavior: { kind: 'automaton', minStates: 3, minTransitions: 4, states: ['Waiting'] },
                },
                { component: 'shop.Double', behavior: { kind: 'automaton' } },
                {
                    component: 'shop.Shop',
                    subcomponents: [
                        { name: 'door', type: 'shop.Gate' },
                        { name: 'twice', type: 'shop.Gate' },
                    ],
                },
            ]),
            model,
        );
        // checks: Gate 1 + 3 ports + 4 behavior = 8 (met: exists, kind); Double 2 (met: exists); Shop 3 (met: exists)
        expect(grade.score).toBeCloseTo((20 * 4) / 13, 2);
        const texts = grade.feedback.map((f) => f.text);
        expect(texts).toEqual(
            expect.arrayContaining([
                expect.stringMatching(/^Port distance of Gate is an in port; it must be an out port \(shop\/Gate\.arc:6\)/),
                expect.stringMatching(/^Port cmd of Gate has type Cmd; it must have type int/),
                expect.stringMatching(/^Gate has no port speed/),
                expect.stringMatching(/automaton of Gate has 2 states; it needs at least 3/),
                expect.stringMatching(/automaton of Gate has 3 transitions; it needs at least 4/),
                expect.stringMatching(/automaton of Gate has no state Waiting/),
                expect.stringMatching(/^Double must be an automaton; it is a compute block \(shop\/Double\.arc:3\)/),
                expect.stringMatching(/^Shop has no subcomponent shop.Gate door/),
                expect.stringMatching(/^Subcomponent twice of Shop is a shop.Double; it must be a shop.Gate \(shop\/Shop\.arc:6\)/),
            ]),
        );
        const port = grade.feedback.find((f) => f.text.startsWith('Port distance'));
        expect(port?.element).toEqual({ qualifiedName: 'shop.Gate.distance', file: 'shop/Gate.arc', line: 6 });
    });

    test('a missing component fails all its checks and points to a namesake in another package', () => {
        const grade = gradeStructure(
            criterion([{ component: 'toys.Gate', ports: [{ name: 'distance' }], behavior: { kind: 'automaton' } }]),
            model,
        );
        expect(grade.score).toBe(0);
        expect(grade.feedback).toEqual([
            { severity: 'error', text: 'There is no component toys.Gate (there is shop.Gate: check its package).' },
        ]);
    });

    test('diagnostics: all points without errors, none with, each error with file:line', async () => {
        const ok = gradeDiagnostics({ id: 'd', title: 'No errors', kind: 'diagnostics', weight: 10 }, model.root, model.diagnostics);
        expect(ok.score).toBe(10);
        const broken = tempDir('broken');
        try {
            writeFiles(broken.dir, {
                ...MODEL,
                'shop/Double.arc': 'package shop;\n\ncomponent Double {\n  port in int i, out int o;\n  compute { o = j * 2; }\n}\n',
            });
            const bad = await loadSubmissionModel(broken.dir, `${broken.dir}/none.arcapp`);
            const grade = gradeDiagnostics({ id: 'd', title: 'No errors', kind: 'diagnostics', weight: 10 }, bad.root, bad.diagnostics);
            expect(grade.score).toBe(0);
            expect(grade.feedback[0]!.text).toMatch(/^The model has 1 error/);
            expect(grade.feedback[1]).toMatchObject({
                severity: 'error',
                text: expect.stringMatching(/^shop\/Double\.arc:5: .*j/),
                element: { file: 'shop/Double.arc', line: 5 },
            });
        } finally {
            broken.remove();
        }
    });
});
