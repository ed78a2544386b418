// Grading the lab exercises (examples/lab/<exercise>/grading/) with @maa/grading, as the lab does:
// the reference solution scores full marks, each broken variant (test/fixtures/grading/<exercise>/,
// overlays over the solution; what each must lose in variants.json) loses exactly the intended
// criteria, with feedback a student can act on. One gradeSubmissions call per exercise grades all
// its submissions (one local Ray run; tasks sandboxed with bubblewrap). Skipped, with the reason,
// where the sim-server venv or bwrap is missing.
import { existsSync, mkdtempSync, readFileSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import path from 'node:path';
import { gradeSubmissions } from '@maa/grading';
import type { GradingSpec, SubmissionGrade } from '@maa/protocol/grading';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { loadExercise } from '../src/exercises/index.js';
import { feedbackText, gradingUnavailable, materialize, repo, simPython } from './grading-helpers.js';

const FIXTURES = path.join(repo, 'packages/lab-server/test/fixtures/grading');

interface Variant {
    variant: string;
    what: string;
    /** criterion id → words its feedback must contain (the criterion must lose points) */
    loses: Record<string, string[]>;
    /** the Controller's state a failed scenario's feedback names */
    scenarioState?: string;
}
const VARIANTS = (JSON.parse(readFileSync(path.join(FIXTURES, 'variants.json'), 'utf8')) as { exercises: Record<string, Variant[]> })
    .exercises;

const unavailable = gradingUnavailable();
if (unavailable !== undefined) console.warn(`grading-examples.test.ts skipped: ${unavailable}`);

const work = mkdtempSync(path.join(tmpdir(), 'maa-grading-examples-'));
afterAll(() => rmSync(work, { recursive: true, force: true }));

/** Grades the solution and every variant of an exercise in one call. */
async function gradeExercise(name: string): Promise<{ spec: GradingSpec; grades: Map<string, SubmissionGrade> }> {
    const folder = path.join(repo, 'examples/lab', name);
    const { manifest, files } = await loadExercise(folder);
    const solution = path.join(folder, 'solution');
    const submissions = [
        { id: 'solution', overlays: [solution] },
        ...(VARIANTS[name] ?? []).map((v) => ({
            id: v.variant,
            overlays: [solution, path.join(FIXTURES, name, v.variant)],
        })),
    ].map(({ id, overlays }) => {
        const root = materialize(path.join(work, name, 'submissions', id), files, overlays);
        return { id, root, appFile: path.join(root, manifest.app) };
    });
    const gradingDir = path.join(folder, 'grading');
    const spec = JSON.parse(readFileSync(path.join(gradingDir, 'grading.json'), 'utf8')) as GradingSpec;
    const grades = await gradeSubmissions({ spec, gradingDir, submissions, workDir: path.join(work, name, 'work'), python: simPython });
    return { spec, grades: new Map(grades.map((g) => [g.submission, g])) };
}

function criterion(grade: SubmissionGrade, id: string): SubmissionGrade['criteria'][number] {
    const c = grade.criteria.find((x) => x.id === id);
    if (c === undefined) throw new Error(`${grade.submission}: no criterion ${id} in ${grade.criteria.map((x) => x.id).join(', ')}`);
    return c;
}

/** What a failed scenario's feedback must hold: the scenario, the simulated time, the state, a link into the Controller. */
function expectScenarioFeedback(grade: SubmissionGrade, spec: GradingSpec, state: string): void {
    const scenarios = spec.criteria.find((c) => c.kind === 'scenarios');
    if (scenarios?.kind !== 'scenarios') throw new Error('the spec has no scenarios criterion');
    const feedback = criterion(grade, scenarios.id).feedback;
    for (const scenario of scenarios.scenarios) {
        const item = feedback.find((f) => f.scenario === scenario.id || f.scenario === scenario.title);
        expect(item, `${grade.submission}: feedback on scenario ${scenario.id}`).toBeDefined();
        expect(item?.severity).toBe('error');
        expect(item?.text).toContain(scenario.title);
        expect(item?.simTime, `${scenario.id}: simulated time`).toBeCloseTo(scenario.timeLimit, 0);
        expect(item?.state, `${scenario.id}: the Controller's state`).toBe(state);
        expect(item?.text).toContain(state);
        expect(item?.element?.file, `${scenario.id}: link to the model`).toBe('toast/Controller.arc');
        expect(item?.element?.line).toBeGreaterThan(0);
    }
}

describe.each(['toast-controller', 'pick-and-place', 'line-follower'])('grading examples/lab/%s', (name) => {
    let spec: GradingSpec;
    let grades: Map<string, SubmissionGrade>;

    beforeAll(async () => {
        if (unavailable !== undefined) return;
        ({ spec, grades } = await gradeExercise(name));
    }, 1_800_000);

    it.skipIf(unavailable !== undefined)('the reference solution scores full marks, every task ok', () => {
        const grade = grades.get('solution');
        expect(grade).toBeDefined();
        if (grade === undefined) return;
        for (const c of grade.criteria)
            expect({ id: c.id, score: c.score, feedback: c.feedback }).toMatchObject({ id: c.id, score: c.max });
        expect(grade.maxScore).toBe(spec.criteria.reduce((sum, c) => sum + c.weight, 0));
        expect(grade.score).toBe(grade.maxScore);
        expect(grade.tasks.filter((t) => t.status !== 'ok')).toEqual([]);
        const scenarios = spec.criteria.flatMap((c) => (c.kind === 'scenarios' ? c.scenarios : []));
        // Every scenario run leaves its recording for the instructor and the student.
        expect(grade.recordings.map((r) => r.scenario).sort()).toEqual(scenarios.map((s) => s.id).sort());
        for (const r of grade.recordings) expect(existsSync(r.file), r.file).toBe(true);
    });

    it.skipIf(unavailable !== undefined).each((VARIANTS[name] ?? []).map((v) => [v.variant, v] as const))(
        'broken variant %s loses exactly the intended criteria, with feedback',
        (_id, variant) => {
            const grade = grades.get(variant.variant);
            expect(grade, `a grade of ${variant.variant}`).toBeDefined();
            if (grade === undefined) return;
            expect(grade.criteria.map((c) => c.id)).toEqual(spec.criteria.map((c) => c.id));
            for (const c of grade.criteria) {
                const words = variant.loses[c.id];
                if (words === undefined) {
                    expect({ criterion: c.id, score: c.score, feedback: c.feedback }).toMatchObject({ criterion: c.id, score: c.max });
                    continue;
                }
                expect(c.score, `${variant.variant}: ${c.id} loses points`).toBeLessThan(c.max);
                const text = feedbackText(c);
                expect(
                    c.feedback.some((f) => f.severity === 'error'),
                    `${c.id}: an error in the feedback`,
                ).toBe(true);
                for (const word of words) expect(text, `${variant.variant}: ${c.id} feedback`).toContain(word);
            }
            expect(grade.score).toBeLessThan(grade.maxScore);
            if (variant.scenarioState !== undefined) expectScenarioFeedback(grade, spec, variant.scenarioState);
        },
    );
});
