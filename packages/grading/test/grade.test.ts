/** gradeSubmissions without the Python side: criteria that need no task, a bad specification, a driver that cannot start, a model that does not generate. */
import path from 'node:path';
import { afterAll, beforeAll, describe, expect, test } from 'vitest';
import type { GradingSpec } from '@maa/protocol/grading';
import { GradingSpecError, gradeSubmissions } from '../src/index.js';
import { fixtures, tempDir, toastController } from './exercise.js';

const gradingDir = path.join(fixtures, 'toast-controller');
const NO_PYTHON = '/nonexistent/python3';

describe('gradeSubmissions (no driver needed or the driver missing)', () => {
    const work = tempDir('grade');
    let reference: string;
    let broken: string;
    beforeAll(() => {
        reference = toastController(path.join(work.dir, 'reference'), { solution: true });
        broken = toastController(path.join(work.dir, 'broken'), {
            solution: true,
            overlay: { 'toast/Controller.arc': 'package toast;\n\ncomponent Controller {\n  port in int distance;\n}\n' },
        });
    });
    afterAll(() => work.remove());

    test('structure and diagnostics alone run no task', async () => {
        const spec: GradingSpec = {
            format: 'maa-grading/1',
            criteria: [
                {
                    id: 'arch',
                    title: 'Architecture',
                    kind: 'structure',
                    weight: 5,
                    require: [{ component: 'toast.Controller', behavior: { kind: 'automaton' } }],
                },
                { id: 'clean', title: 'No errors', kind: 'diagnostics', weight: 5 },
            ],
        };
        const events: string[] = [];
        const grades = await gradeSubmissions({
            spec,
            gradingDir,
            submissions: [
                { id: 'reference', root: reference, appFile: 'TR.arcapp' },
                { id: 'broken', root: broken, appFile: 'TR.arcapp' },
            ],
            workDir: path.join(work.dir, 'w1'),
            python: NO_PYTHON,
            onProgress: (e) => events.push(`${e.kind}:${'step' in e ? e.step : ''}`),
        });
        expect(grades.map((g) => [g.submission, g.score, g.maxScore, g.tasks.length])).toEqual([
            ['reference', 10, 10, 0],
            ['broken', 2.5, 10, 0], // Controller exists (1 of 2 structure checks), it has errors
        ]);
        expect(grades[1]!.criteria[0]!.feedback[0]!.text).toMatch(
            /^Controller must be an automaton; it is without behavior \(toast\/Controller\.arc:3\)\.$/,
        );
        expect(grades[1]!.criteria[1]!.feedback[0]!.text).toMatch(/^The model has \d+ errors?; fix them for these points\.$/);
        expect(events).not.toContain('submission:generate');
    });

    test('a specification object that breaks the format is refused before any work', async () => {
        const spec = {
            format: 'maa-grading/1',
            criteria: [{ id: 'x', title: 'X', kind: 'coverage', weight: 1, component: 'toast.Controller', states: 3, transitions: 1 }],
        };
        const error = await gradeSubmissions({
            spec: spec as GradingSpec,
            gradingDir,
            submissions: [],
            workDir: path.join(work.dir, 'w2'),
        }).catch((e: unknown) => e);
        expect(error).toBeInstanceOf(GradingSpecError);
        expect((error as Error).message).toContain('/criteria/0/states: states must be a share from 0 to 1');
    });

    test('a driver that cannot start: the task criteria score 0 and say why, the others are graded', async () => {
        const grades = await gradeSubmissions({
            gradingDir,
            submissions: [{ id: 'reference', root: reference, appFile: 'TR.arcapp' }],
            workDir: path.join(work.dir, 'w3'),
            python: NO_PYTHON,
        });
        const [g] = grades;
        const byId = new Map(g!.criteria.map((c) => [c.id, c]));
        expect(byId.get('architecture')!.score).toBe(byId.get('architecture')!.max);
        expect(byId.get('no-errors')!.score).toBe(byId.get('no-errors')!.max);
        expect(byId.get('hidden-tests')!.score).toBe(0);
        expect(byId.get('hidden-tests')!.feedback[0]!.text).toMatch(
            /^The hidden tests did not run: could not start the grading driver \/nonexistent\/python3/,
        );
        expect(byId.get('scenarios')!.feedback[1]!.text).toMatch(
            /^Scenario 'Standard toaster' did not run to its end: could not start the grading driver/,
        );
        expect(g!.tasks.map((t) => [t.id, t.status])).toEqual([
            ['reference.tests', 'error'],
            ['reference.scenario.standard', 'error'],
        ]);
    });

    test('a model that does not generate: its task criteria say so with the errors, no task runs', async () => {
        const grades = await gradeSubmissions({
            gradingDir,
            submissions: [{ id: 'broken', root: broken, appFile: 'TR.arcapp' }],
            workDir: path.join(work.dir, 'w4'),
            python: NO_PYTHON,
        });
        const tests = grades[0]!.criteria.find((c) => c.kind === 'tests')!;
        expect(tests.score).toBe(0);
        expect(tests.feedback[0]!.text).toMatch(
            /^The hidden tests did not run: the model does not generate: toast\/ToastServiceRobot\.arc:\d+: /,
        );
        expect(grades[0]!.tasks.every((t) => t.status === 'error' && t.message?.startsWith('the model does not generate'))).toBe(true);
        const coverage = grades[0]!.criteria.find((c) => c.kind === 'coverage')!;
        expect(coverage.feedback[0]!.text).toBe('Controller has no automaton: there is nothing to cover.');
    });
});
