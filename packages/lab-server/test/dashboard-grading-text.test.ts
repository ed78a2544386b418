// The dashboard's grading section texts (web/dashboard/grading-text.ts): scores, runs, feedback.
import { describe, expect, it } from 'vitest';
import type { ResultView, RunView } from '../src/grading/views.js';
import { criterionCell, feedbackLine, points, runText, running } from '../web/dashboard/grading-text.js';

const run = (status: RunView['status'], more: Partial<RunView> = {}): RunView => ({
    id: 7,
    kind: 'course',
    status,
    done: 3,
    total: 8,
    error: null,
    createdAt: '2026-01-01T00:00:00.000Z',
    startedAt: null,
    finishedAt: null,
    url: '/x',
    ...more,
});

describe('the grading section’s texts', () => {
    it('says where a run is, and whether it goes on', () => {
        expect(runText(run('queued'))).toBe('Run 7 waits for the run before it');
        expect(runText(run('running'))).toBe('Run 7 grading… 3 of 8 tasks done');
        expect(runText(run('failed', { error: 'Ray is not there' }))).toBe('Run 7 failed: Ray is not there');
        expect(runText(run('done'))).toMatch(/^Run 7 finished .*\(every student\)$/);
        expect([running(run('queued')), running(run('running')), running(run('done')), running(run('failed')), running(undefined)]).toEqual(
            [true, true, false, false, false],
        );
    });

    it('shows scores without float noise and a dash for a criterion the result lacks', () => {
        expect(points(0.1 + 0.2)).toBe('0.3');
        const result = { criteria: [{ id: 'a', title: 'A', kind: 'tests', score: 12.5, max: 30, feedback: [] }] } as unknown as ResultView;
        expect(criterionCell(result, 'a')).toBe('12.5/30');
        expect(criterionCell(result, 'b')).toBe('—');
    });

    it('puts a feedback item in one line with its element, scenario, time and state', () => {
        expect(
            feedbackLine({
                severity: 'error',
                text: "Scenario 'Slow toaster' failed",
                element: { file: 'toast/Controller.arc', line: 22, qualifiedName: 'toast.Controller' },
                scenario: 'slow',
                simTime: 60,
                state: 'Toasting',
            }),
        ).toBe(
            "error: Scenario 'Slow toaster' failed [toast/Controller.arc:22 (toast.Controller), scenario slow, at 60 s, state Toasting]",
        );
        expect(feedbackLine({ severity: 'info', text: 'All good' })).toBe('info: All good');
    });
});
