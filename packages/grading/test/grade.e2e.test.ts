/**
 * End to end: the toast-controller reference solution and a broken variant graded through the real
 * Python driver (maa_sim.grading: local Ray, every task sandboxed) with real scenario runs. Uses the
 * exercise's grading folder (examples/lab/toast-controller/grading) when it exists, else this
 * package's fixture. Skips without the sim-server venv, the driver or bubblewrap.
 */
import { existsSync, statSync } from 'node:fs';
import path from 'node:path';
import { afterAll, beforeAll, describe, expect, test } from 'vitest';
import type { SubmissionGrade } from '@maa/protocol/grading';
import { defaultPython, type GradeProgress, gradeSubmissions, loadGradingSpec } from '../src/index.js';
import { fixtures, repoDir, tempDir, toastController } from './exercise.js';

const exerciseGrading = path.join(repoDir, 'examples', 'lab', 'toast-controller', 'grading');
const gradingDir = existsSync(path.join(exerciseGrading, 'grading.json')) ? exerciseGrading : path.join(fixtures, 'toast-controller');
const python = defaultPython();
const missing = [
    existsSync(python) ? undefined : `the sim-server venv (${python}; run sim-server/scripts/setup_env.sh)`,
    existsSync(path.join(repoDir, 'sim-server', 'src', 'maa_sim', 'grading', '__main__.py'))
        ? undefined
        : 'the grading driver maa_sim.grading',
    existsSync('/usr/bin/bwrap') ? undefined : 'bubblewrap (/usr/bin/bwrap)',
].filter(Boolean);
if (missing.length > 0) console.warn(`grade.e2e.test.ts skipped: missing ${missing.join(', ')}`);

/** The reference solution without its transition Toasting -> Serving: it toasts forever. */
const NEVER_SERVES = {
    'toast/Controller.arc': `package toast;

import toast.types.*;

component Controller(int threshold = 30) {
  port in int distance,
       in ToastColor color,
       in ArmStatus armStatus,
       <<delayed>> out ToasterCmd toaster,
       <<delayed>> out ArmProgram arm;

  int served = 0;

  <<sync>> automaton {
    initial { toaster = ToasterCmd.STOP; arm = ArmProgram.NONE; } state Idle;
    state Loading;
    state Toasting;
    state Serving;

    Idle -> Loading [distance < threshold] / { arm = ArmProgram.LOAD_BREAD; };
    Loading -> Toasting [armStatus == ArmStatus.DONE] / { toaster = ToasterCmd.START; };
    Serving -> Idle [armStatus == ArmStatus.DONE] / { served++; };
  }
}
`,
};

describe.skipIf(missing.length > 0)('gradeSubmissions end to end (real driver, real scenarios)', () => {
    const work = tempDir('e2e');
    let grades: SubmissionGrade[];
    const events: GradeProgress[] = [];
    beforeAll(async () => {
        const reference = toastController(path.join(work.dir, 'reference'), { solution: true });
        const broken = toastController(path.join(work.dir, 'never-serves'), { solution: true, overlay: NEVER_SERVES });
        grades = await gradeSubmissions({
            gradingDir,
            submissions: [
                { id: 'reference', root: reference, appFile: 'TR.arcapp' },
                { id: 'never serves', root: broken, appFile: path.join(broken, 'TR.arcapp') },
            ],
            workDir: path.join(work.dir, 'work'),
            onProgress: (e) => events.push(e),
        });
    }, 900_000);
    afterAll(() => work.remove());

    test('the reference solution scores full marks, with a recording per scenario and every task ok', async () => {
        const spec = await loadGradingSpec(gradingDir);
        const [reference] = grades;
        expect(reference!.criteria.filter((c) => c.score !== c.max)).toEqual([]);
        expect(reference!.score).toBe(reference!.maxScore);
        expect(reference!.maxScore).toBe(spec.criteria.reduce((n, c) => n + c.weight, 0));
        const scenarioIds = spec.criteria.flatMap((c) => (c.kind === 'scenarios' ? c.scenarios.map((s) => s.id) : []));
        expect(reference!.recordings.map((r) => r.scenario).sort()).toEqual([...scenarioIds].sort());
        for (const r of reference!.recordings) expect(statSync(r.file).size).toBeGreaterThan(0);
        expect(reference!.tasks.every((t) => t.status === 'ok')).toBe(true);
    });

    test('the controller that never serves loses the tests, scenarios and coverage with feedback that says why', () => {
        const broken = grades[1]!;
        expect(broken.submission).toBe('never serves');
        const byKind = (kind: string) => broken.criteria.find((c) => c.kind === kind)!;
        expect(byKind('diagnostics').score).toBe(byKind('diagnostics').max);
        expect(byKind('structure').score).toBeLessThan(byKind('structure').max);
        expect(byKind('structure').feedback.map((f) => f.text)).toContainEqual(
            expect.stringMatching(/automaton of Controller has 3 transitions; it needs at least 4/),
        );
        expect(byKind('tests').score).toBeLessThan(byKind('tests').max);
        expect(byKind('tests').feedback.map((f) => f.text)).toContainEqual(
            expect.stringMatching(/^Hidden test '.*' failed( at tick \d+)?: .*the automaton (ended in|was in) state Toasting/),
        );
        const scenarios = byKind('scenarios');
        expect(scenarios.score).toBe(0);
        const failed = scenarios.feedback.filter((f) => f.scenario);
        expect(failed.length).toBeGreaterThan(0);
        for (const f of failed) {
            expect(f.text).toMatch(
                /^Scenario '.*' failed: no toast on the plate after \d+\.\d s of simulated time; .*Controller was in state Toasting \(toast\/Controller\.arc:\d+\)\.$/,
            );
            expect(f).toMatchObject({
                severity: 'error',
                state: 'Toasting',
                element: { qualifiedName: 'toast.Controller.Toasting', file: 'toast/Controller.arc' },
            });
        }
        const coverage = byKind('coverage');
        expect(coverage.score).toBeLessThan(coverage.max);
        expect(coverage.feedback.map((f) => f.text)).toContainEqual(
            expect.stringMatching(/^State Serving was never visited \(toast\/Controller\.arc:\d+\)\.$/),
        );
    });

    test('progress: each submission checked and generated, the driver started, a line per task, each graded', () => {
        const tasks = grades.flatMap((g) => g.tasks.map((t) => t.id));
        expect(
            events.filter((e) => e.kind === 'submission' && e.step === 'generate').map((e) => (e as { submission: string }).submission),
        ).toEqual(['reference', 'never serves']);
        expect(events.some((e) => e.kind === 'driver' && e.line.event === 'started')).toBe(true);
        const taskLines = events.flatMap((e) => (e.kind === 'driver' && e.line.event === 'task' ? [e.line.id] : []));
        expect(taskLines.sort()).toEqual([...tasks].sort());
        expect(tasks.filter((t) => t.startsWith('never_serves.'))).not.toHaveLength(0);
        expect(events.filter((e) => e.kind === 'graded')).toHaveLength(2);
    });
});

describe.skipIf(missing.length > 0)('gradeSubmissions stops when aborted', () => {
    const work = tempDir('abort');
    afterAll(() => work.remove());

    test('aborting once the driver started kills it and rejects', async () => {
        const reference = toastController(path.join(work.dir, 'reference'), { solution: true });
        const controller = new AbortController();
        const run = gradeSubmissions({
            gradingDir: path.join(fixtures, 'toast-controller'),
            submissions: [{ id: 'reference', root: reference, appFile: 'TR.arcapp' }],
            workDir: path.join(work.dir, 'work'),
            signal: controller.signal,
            onProgress: (e) => {
                if (e.kind === 'driver' && e.line.event === 'started') controller.abort(new Error('stopped by the test'));
            },
        });
        await expect(run).rejects.toThrow('stopped by the test');
    }, 300_000);
});
