/**
 * gradeSubmissions: checks, generates and plans every submission (Node), runs all their tasks in
 * one grade job on the Python driver (Ray), then scores every criterion with feedback.
 */
import { mkdir, rm } from 'node:fs/promises';
import path from 'node:path';
import { formatIssues } from '@maa/protocol';
import {
    type Criterion,
    type CriterionGrade,
    type DriverTask,
    GRADING_FILE_NAME,
    type GradeTask,
    type GradingSpec,
    gradingSpecIssues,
    type SubmissionGrade,
} from '@maa/protocol/grading';
import { expectedAutomaton, gradeCoverage } from './coverage.js';
import { gradeDiagnostics } from './diagnostics.js';
import { DriverError, runDriver } from './driver.js';
import { generateTimesync } from './generate.js';
import { type AutomatonInstance, automatonInstances } from './instances.js';
import { loadSubmissionModel, type SubmissionModel } from './model.js';
import { readTaskOutput, type TaskOutput } from './outputs.js';
import { type PlannedTask, planTasks, taskKey } from './plan.js';
import { gradingPython } from './python.js';
import { gradeScenarios } from './scenarios.js';
import { GradingSpecError, loadGradingSpec } from './spec.js';
import { gradeStructure } from './structure.js';
import { gradeTests, stateLinkOf } from './tests.js';
import type { GradeOptions, Submission } from './types.js';

/** A submission checked, generated and planned. */
interface Prepared {
    readonly submission: Submission;
    readonly model: SubmissionModel;
    readonly instances: readonly AutomatonInstance[];
    readonly planned: readonly PlannedTask[];
    /** Why its tasks cannot run (the model does not generate). */
    readonly notRun?: string;
}

export async function gradeSubmissions(options: GradeOptions): Promise<SubmissionGrade[]> {
    const gradingDir = path.resolve(options.gradingDir);
    const spec = options.spec ? checkedSpec(options.spec, gradingDir) : await loadGradingSpec(gradingDir);
    const workDir = path.resolve(options.workDir);
    const outDir = path.join(workDir, 'out');
    await rm(outDir, { recursive: true, force: true });
    await mkdir(outDir, { recursive: true });
    const keys = uniqueKeys(options.submissions);
    const prepared: Prepared[] = [];
    for (const [i, submission] of options.submissions.entries()) {
        options.signal?.throwIfAborted();
        prepared.push(await prepare(spec, submission, keys[i]!, workDir, { ...options, gradingDir }));
    }
    const { ran, driverFailure } = await runTasks(prepared, workDir, outDir, options);
    const grades: SubmissionGrade[] = [];
    for (const p of prepared) {
        const outputs = new Map<string, TaskOutput>();
        for (const t of p.planned) outputs.set(t.task.id, await readTaskOutput(outDir, t.task.id, ran.get(t.task.id)));
        const grade = gradeOne(spec, p, outputs, gradingDir, p.notRun ?? driverFailure);
        grades.push(await grade);
        options.onProgress?.({
            kind: 'graded',
            submission: p.submission.id,
            score: grades.at(-1)!.score,
            maxScore: grades.at(-1)!.maxScore,
        });
    }
    return grades;
}

/** A specification given as an object keeps the format too (the hidden files are checked when the tasks are planned). */
function checkedSpec(spec: GradingSpec, gradingDir: string): GradingSpec {
    const issues = gradingSpecIssues(spec);
    if (issues.length === 0) return spec;
    const file = path.join(gradingDir, GRADING_FILE_NAME);
    throw new GradingSpecError(file, issues, `${file}: not a valid grading specification: ${formatIssues(issues, 5)}`);
}

/** Task id prefixes, one per submission, distinct. */
function uniqueKeys(submissions: readonly Submission[]): string[] {
    const used = new Set<string>();
    return submissions.map((s) => {
        let key = taskKey(s.id);
        for (let n = 2; used.has(key); n++) key = `${taskKey(s.id)}-${n}`;
        used.add(key);
        return key;
    });
}

async function prepare(spec: GradingSpec, submission: Submission, key: string, workDir: string, options: GradeOptions): Promise<Prepared> {
    const progress = (step: 'check' | 'generate' | 'plan', message: string) =>
        options.onProgress?.({ kind: 'submission', submission: submission.id, step, message });
    const root = path.resolve(submission.root);
    const appFile = path.resolve(root, submission.appFile);
    const dir = path.join(workDir, key);
    await rm(dir, { recursive: true, force: true });
    progress('check', `checking the model of ${submission.id}`);
    const model = await loadSubmissionModel(root, appFile);
    const instances = automatonInstances(model.appRoot);
    const needsRun = spec.criteria.some((c) => c.kind === 'tests' || c.kind === 'scenarios');
    if (!needsRun) return { submission, model, instances, planned: [] };
    progress('generate', `generating the timesync platform of ${submission.id}`);
    const generated = await generateTimesync(root, appFile, path.join(dir, 'gen'));
    if (!generated.ok) {
        const shown = generated.errors.slice(0, 3).join('; ');
        return { submission, model, instances, planned: [], notRun: `the model does not generate${shown ? `: ${shown}` : ''}` };
    }
    progress('plan', `preparing the tasks of ${submission.id}`);
    const planned = await planTasks({
        spec,
        gradingDir: options.gradingDir,
        key,
        build: generated.build,
        inputsDir: path.join(dir, 'inputs'),
    });
    return { submission, model, instances, planned };
}

/** Runs every planned task in one job; a driver that fails makes every task's criterion fail with its message. */
async function runTasks(
    prepared: readonly Prepared[],
    workDir: string,
    outDir: string,
    options: GradeOptions,
): Promise<{ ran: ReadonlyMap<string, DriverTask>; driverFailure?: string }> {
    const owner = new Map<string, string>();
    for (const p of prepared) for (const t of p.planned) owner.set(t.task.id, p.submission.id);
    if (owner.size === 0) return { ran: new Map() };
    try {
        const run = await runDriver({
            python: options.python ?? (await gradingPython()),
            jobFile: path.join(workDir, 'job.json'),
            outDir,
            tasks: prepared.flatMap((p) => p.planned.map((t) => t.task)),
            ...(options.rayAddress ? { rayAddress: options.rayAddress } : {}),
            ...(options.env ? { env: { ...process.env, ...options.env } } : {}),
            ...(options.signal ? { signal: options.signal } : {}),
            onLine: (line) => {
                const submission = line.event === 'task' ? owner.get(line.id) : undefined;
                options.onProgress?.({ kind: 'driver', line, ...(submission ? { submission } : {}) });
            },
        });
        return { ran: run.tasks };
    } catch (e) {
        if (!(e instanceof DriverError)) throw e;
        return { ran: new Map(), driverFailure: e.message };
    }
}

async function gradeOne(
    spec: GradingSpec,
    p: Prepared,
    outputs: ReadonlyMap<string, TaskOutput>,
    gradingDir: string,
    notRun: string | undefined,
): Promise<SubmissionGrade> {
    const criteria: CriterionGrade[] = [];
    for (const criterion of spec.criteria) criteria.push(await gradeCriterion(criterion, spec, p, outputs, gradingDir, notRun));
    const round = (n: number) => Math.round(n * 100) / 100;
    return {
        submission: p.submission.id,
        score: round(criteria.reduce((n, c) => n + c.score, 0)),
        maxScore: round(criteria.reduce((n, c) => n + c.max, 0)),
        criteria,
        recordings: p.planned.flatMap((t) => {
            const file = outputs.get(t.task.id)?.recording;
            return t.kind === 'scenario' && file ? [{ scenario: t.scenario.id, file }] : [];
        }),
        tasks: p.planned.map((t) => taskOf(t.task.id, outputs.get(t.task.id), notRun)),
    };
}

function gradeCriterion(
    criterion: Criterion,
    spec: GradingSpec,
    p: Prepared,
    outputs: ReadonlyMap<string, TaskOutput>,
    gradingDir: string,
    notRun: string | undefined,
): CriterionGrade | Promise<CriterionGrade> {
    switch (criterion.kind) {
        case 'structure':
            return gradeStructure(criterion, p.model);
        case 'diagnostics':
            return gradeDiagnostics(criterion, p.model.root, p.model.diagnostics);
        case 'tests': {
            const task = p.planned.find((t) => t.kind === 'tests');
            return gradeTests(criterion, gradingDir, task ? outputs.get(task.task.id) : undefined, notRun, stateLinkOf(p.model));
        }
        case 'scenarios':
            return gradeScenarios(criterion, p.planned, outputs, { model: p.model, instances: p.instances, focus: focusOf(spec) }, notRun);
        case 'coverage':
            return gradeCoverage(criterion, p.model, p.instances, outputs.values(), expectedAutomaton(spec, criterion.component));
    }
}

/** The components whose states scenario feedback names: those the coverage and structure criteria require as automata. */
function focusOf(spec: GradingSpec): Set<string> {
    const focus = new Set<string>();
    for (const c of spec.criteria) {
        if (c.kind === 'coverage') focus.add(c.component);
        if (c.kind === 'structure') for (const r of c.require) if (r.behavior?.kind === 'automaton') focus.add(r.component);
    }
    return focus;
}

function taskOf(id: string, output: TaskOutput | undefined, notRun: string | undefined): GradeTask {
    const result = output?.result;
    if (!result) return { id, status: 'error', seconds: 0, message: notRun ?? 'the grading driver reported no result for this task' };
    return { id, status: result.status, seconds: result.seconds, message: result.message };
}
