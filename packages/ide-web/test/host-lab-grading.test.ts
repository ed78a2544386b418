// Lab mode's Exercise view, its grading rows (src/host/exercise-grading.ts): the lab's answer
// checked, Submit for grading for the owner only, the run while it goes on or when it failed, the
// grade with each criterion and its feedback (an item about a model element opens its file at the line).
import { describe, expect, it } from 'vitest';
import { type GradingState, gradingItems, parseGradingState, runGoesOn, SUBMIT_COMMAND } from '../src/host/exercise-grading.js';

const GRADED: GradingState = {
    graded: true,
    run: { id: 3, status: 'done', done: 4, total: 4, error: null, url: '/api/courses/c/exercises/e/grading/runs/3' },
    latest: {
        score: 62.5,
        maxScore: 100,
        gradedAt: '2026-11-24T10:00:00Z',
        criteria: [
            { id: 'no-errors', title: 'The model has no errors', score: 10, max: 10, feedback: [] },
            {
                id: 'scenarios',
                title: 'The robot serves toast',
                score: 15,
                max: 30,
                feedback: [
                    {
                        severity: 'error',
                        text: "Scenario 'Slow toaster' failed: no toast on the plate after 60.0 s",
                        scenario: 'slow',
                        simTime: 60,
                        state: 'Toasting',
                        element: { qualifiedName: 'toast.Controller', file: 'toast/Controller.arc', line: 22 },
                    },
                ],
            },
        ],
        recordings: [{ scenario: 'slow', url: '/api/grading/results/9/recordings/slow.mcap' }],
    },
};

describe('the Exercise view’s grading', () => {
    it('shows nothing for an exercise without grading', () => {
        expect(gradingItems(undefined, true)).toEqual([]);
        expect(gradingItems({ graded: false, latest: null, run: null }, true)).toEqual([]);
    });

    it('offers Submit for grading to the owner before the first grade', () => {
        const [row] = gradingItems({ graded: true, latest: null, run: null }, true);
        expect(row).toMatchObject({ label: 'Grading', description: 'not graded yet', expanded: true });
        expect(row?.children).toEqual([expect.objectContaining({ label: 'Submit for grading', command: SUBMIT_COMMAND })]);
        // An instructor looking at the workspace cannot submit in the student's name.
        expect(gradingItems({ graded: true, latest: null, run: null }, false)[0]?.children).toEqual([]);
    });

    it('shows the grade, each criterion with its feedback opening the model element at its line, and the recordings', () => {
        const [row] = gradingItems(GRADED, true);
        expect(row?.description).toMatch(/^62\.5 \/ 100 \(graded /);
        const labels = row?.children?.map((c) => c.label);
        expect(labels).toEqual(['Submit for grading', 'The model has no errors', 'The robot serves toast', 'Recording of slow']);
        expect(row?.children?.[1]).toMatchObject({ description: '10 / 10', icon: 'pass' });
        const scenarios = row?.children?.[2];
        expect(scenarios).toMatchObject({ description: '15 / 30', icon: 'warning' });
        expect(scenarios?.children?.[0]).toMatchObject({
            label: "Scenario 'Slow toaster' failed: no toast on the plate after 60.0 s",
            description: 'scenario slow, at 60 s, in state Toasting, toast/Controller.arc:22',
            icon: 'error',
            file: 'toast/Controller.arc',
            line: 22,
        });
        expect(row?.children?.[3]).toMatchObject({ url: '/api/grading/results/9/recordings/slow.mcap' });
    });

    it('shows a run that goes on instead of the submit action, and a failed run with its reason', () => {
        const running = gradingItems({ ...GRADED, run: { ...GRADED.run!, status: 'running', done: 1 } }, true)[0];
        expect(running?.children?.[0]).toMatchObject({ label: 'Grading', description: '1 of 4 tasks done…' });
        expect(running?.children?.some((c) => c.command === SUBMIT_COMMAND)).toBe(false);
        const failed = gradingItems({ ...GRADED, run: { ...GRADED.run!, status: 'failed', error: 'Ray is not there' } }, true)[0];
        expect(failed?.children?.[1]).toMatchObject({ label: 'The last grading failed', description: 'Ray is not there' });
        expect([runGoesOn(GRADED.run), runGoesOn({ ...GRADED.run!, status: 'queued' }), runGoesOn(null)]).toEqual([false, true, false]);
    });

    it('accepts the lab’s answer and refuses one without its fields', () => {
        expect(parseGradingState(GRADED)).toBe(GRADED);
        expect(() => parseGradingState({ latest: null, run: null })).toThrow(/graded/);
        expect(() => parseGradingState({ graded: true, latest: { score: 'x' }, run: null })).toThrow(/score/);
    });
});
