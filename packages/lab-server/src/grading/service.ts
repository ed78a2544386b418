// The lab's grading service (docs/lab.md "Grading"): a student's submission or every student's
// latest submission of an exercise graded by the engine (@maa/grading), one run at a time per
// exercise (the others wait in order), each run's progress and end stored. A run that fails is
// `failed` with its error, never stuck; the next run of the exercise starts anyway.
import { mkdtemp, rm } from 'node:fs/promises';
import { tmpdir } from 'node:os';
import path from 'node:path';
import { specOf } from '../exercises/spec.js';
import { gradingSpecContract, type SubmissionGrade, submissionGradeContract } from '../exercises/grading-spec.js';
import type { Exercise, GradingRun, LabStore, OwnedSubmission, User, Workspace } from '../storage/index.js';
import { defaultEngine, type EngineSubmission, type GradeEngine, type Progress, progressOf } from './engine.js';
import { keepRecordings, writeGradingDir, writeSubmissionRoot } from './files.js';

export interface GradingServiceOptions {
    /** the lab's data directory: recordings go to its `recordings/` */
    dataDir: string;
    /** the grading engine (default: @maa/grading's gradeSubmissions) */
    engine?: GradeEngine;
    /** the sim-server venv's interpreter (default: the engine's) */
    python?: string;
    /** a Ray cluster's address (default: RAY_ADDRESS of the environment, else local Ray) */
    rayAddress?: string;
    /** where runs keep their temporary folders (default: the system's temp directory) */
    workRoot?: string;
    log?: (line: string) => void;
    /** called with a run's progress whenever it changes (the CLI prints it) */
    onProgress?: (runId: number, progress: Progress) => void;
}

/** Why a run stopped early: the service closed. */
const CLOSED = 'the lab server stopped during the run';

export class GradingService {
    /** per exercise id, the end of its last queued run */
    private readonly queues = new Map<number, Promise<void>>();
    private readonly running = new Set<Promise<void>>();
    private readonly abort = new AbortController();
    private readonly engine: GradeEngine;

    constructor(
        private readonly store: LabStore,
        private readonly options: GradingServiceOptions,
    ) {
        this.engine = options.engine ?? defaultEngine;
    }

    /** Marks the runs a stopped server left queued or running as failed (call once at the server's start). */
    recover(): Promise<number> {
        return this.store.failUnfinishedGradingRuns(CLOSED);
    }

    /** Submits the workspace as it is now and queues its grading; returns the run (queued). */
    async submit(exercise: Exercise, workspace: Workspace, by: User): Promise<{ run: GradingRun; submission: OwnedSubmission }> {
        await this.requireGrading(exercise);
        if (await this.unfinished(exercise, (r) => r.kind === 'submission' && r.requestedBy === by.id))
            throw new GradingBusy('your last submission is still being graded: wait for its grade, then submit again');
        const submitted = await this.store.submit(workspace.id, by.id);
        const submission: OwnedSubmission = { ...submitted, ownerId: workspace.ownerId };
        const run = await this.store.createGradingRun({ exerciseId: exercise.id, kind: 'submission', requestedBy: by.id, total: 1 });
        this.enqueue(run, exercise, [submission]);
        return { run, submission };
    }

    /** Queues the grading of every student's latest submission of the exercise; returns the run (queued). */
    async gradeCourse(exercise: Exercise, by: User): Promise<GradingRun> {
        await this.requireGrading(exercise);
        if (await this.unfinished(exercise, (r) => r.kind === 'course'))
            throw new GradingBusy(`a grading of every submission of ${exercise.name} is queued or running already: follow that one`);
        const submissions = await this.store.latestSubmissions(exercise.id);
        const run = await this.store.createGradingRun({
            exerciseId: exercise.id,
            kind: 'course',
            requestedBy: by.id,
            total: submissions.length,
        });
        this.enqueue(run, exercise, submissions);
        return run;
    }

    /** Resolves when every queued run has ended. */
    async settled(): Promise<void> {
        while (this.running.size > 0) await Promise.allSettled([...this.running]);
    }

    /** Ends the running runs (they fail: the server stopped) and waits for them. */
    async close(): Promise<void> {
        this.abort.abort(new Error(CLOSED));
        await this.settled();
    }

    /** Whether a run of the exercise that `which` picks is queued or running (in this process: others' runs end as failed at a restart). */
    private async unfinished(exercise: Exercise, which: (run: GradingRun) => boolean): Promise<boolean> {
        const runs = await this.store.listGradingRuns(exercise.id, 100);
        return runs.some((r) => (r.status === 'queued' || r.status === 'running') && which(r));
    }

    private async requireGrading(exercise: Exercise): Promise<void> {
        if (!(await this.store.exerciseGrading(exercise.id)))
            throw new GradingUnavailable(
                `the exercise ${exercise.name} has no grading: add a grading/ folder with grading.json and update it (maa-lab exercise update)`,
            );
    }

    private enqueue(run: GradingRun, exercise: Exercise, submissions: OwnedSubmission[]): void {
        const previous = this.queues.get(exercise.id) ?? Promise.resolve();
        const next = previous.then(() => this.execute(run, exercise, submissions));
        this.queues.set(exercise.id, next);
        this.running.add(next);
        void next.finally(() => {
            this.running.delete(next);
            if (this.queues.get(exercise.id) === next) this.queues.delete(exercise.id);
        });
    }

    /** Runs one grading; whatever happens, the run ends `done` or `failed` (never throws). */
    private async execute(run: GradingRun, exercise: Exercise, submissions: OwnedSubmission[]): Promise<void> {
        const log = this.options.log ?? (() => undefined);
        let work: string | undefined;
        try {
            if (this.abort.signal.aborted) throw new Error(CLOSED);
            await this.store.updateGradingRun(run.id, { status: 'running', startedAt: new Date(), done: 0 });
            work = await mkdtemp(path.join(this.options.workRoot ?? tmpdir(), `maa-grading-${run.id}-`));
            const graded = await this.grade(run, exercise, submissions, work);
            const done = await this.store.findGradingRun(run.id);
            await this.store.updateGradingRun(run.id, {
                status: 'done',
                done: Math.max(done?.done ?? 0, done?.total ?? 0),
                finishedAt: new Date(),
            });
            log(`grading run ${run.id} of ${exercise.name}: ${graded} submissions graded`);
        } catch (e) {
            const message = this.abort.signal.aborted ? CLOSED : e instanceof Error ? e.message : String(e);
            log(`grading run ${run.id} of ${exercise.name} failed: ${message}`);
            await this.store.updateGradingRun(run.id, { status: 'failed', error: message, finishedAt: new Date() }).catch(() => undefined);
        } finally {
            if (work) await rm(work, { recursive: true, force: true }).catch(() => undefined);
        }
    }

    /** Materializes, calls the engine, stores the results and recordings; returns how many were graded. */
    private async grade(run: GradingRun, exercise: Exercise, submissions: OwnedSubmission[], work: string): Promise<number> {
        if (submissions.length === 0) return 0;
        const grading = await this.store.exerciseGrading(exercise.id);
        if (!grading) throw new Error(`the exercise ${exercise.name} has no grading any more`);
        const spec = gradingSpecContract.parse(grading.spec, `the stored grading of ${exercise.name}`);
        const released = specOf(exercise);
        const starter = (await this.store.starterVersion(exercise.id))?.files ?? {};
        const gradingDir = path.join(work, 'grading');
        await writeGradingDir(gradingDir, spec, grading.files);
        const engineSubmissions: EngineSubmission[] = [];
        for (const submission of submissions) {
            const root = path.join(work, 'submissions', String(submission.id));
            await writeSubmissionRoot(this.store, submission, released, starter, root);
            engineSubmissions.push({ id: String(submission.id), root, appFile: path.join(root, ...released.app.split('/')) });
        }
        const workDir = path.join(work, 'engine');
        const progress = this.progressWriter(run);
        const grades = await this.engine({
            spec,
            gradingDir,
            submissions: engineSubmissions,
            workDir,
            ...(this.options.python ? { python: this.options.python } : {}),
            ...(this.rayAddress() ? { rayAddress: this.rayAddress() } : {}),
            onProgress: progress.event,
            signal: this.abort.signal,
        });
        await progress.flush();
        const byId = new Map(submissions.map((s) => [String(s.id), s]));
        let stored = 0;
        for (const grade of grades) {
            const submission = byId.get(grade.submission);
            if (!submission) continue;
            await this.storeGrade(run, submission, submissionGradeContract.parse(grade, 'the grading engine’s grade'), workDir);
            stored++;
        }
        const missing = submissions.filter((s) => !grades.some((g) => g.submission === String(s.id)));
        if (missing.length > 0)
            throw new Error(`the grading engine returned no grade for submission ${missing.map((s) => s.id).join(', ')}`);
        return stored;
    }

    private async storeGrade(run: GradingRun, submission: OwnedSubmission, grade: SubmissionGrade, workDir: string): Promise<void> {
        const result = await this.store.recordGradingResult({
            runId: run.id,
            submissionId: submission.id,
            userId: submission.ownerId,
            score: grade.score,
            maxScore: grade.maxScore,
            grade: { ...grade, recordings: [] },
            recordings: [],
        });
        const kept = await keepRecordings(this.options.dataDir, workDir, run.id, result.id, grade.recordings);
        if (kept.length > 0) await this.store.setGradingRecordings(result.id, kept);
    }

    private rayAddress(): string | undefined {
        return this.options.rayAddress ?? (process.env['RAY_ADDRESS'] || undefined);
    }

    /** Stores the run's progress as events come, one update at a time (the newest wins). */
    private progressWriter(run: GradingRun): { event: (e: unknown) => void; flush: () => Promise<void> } {
        let progress: Progress = { done: 0, total: run.total };
        let writing: Promise<unknown> = Promise.resolve();
        return {
            event: (e) => {
                const next = progressOf(e, progress);
                if (next.done === progress.done && next.total === progress.total) return;
                progress = next;
                this.options.onProgress?.(run.id, next);
                writing = writing.then(() => this.store.updateGradingRun(run.id, { ...next }).catch(() => undefined));
            },
            flush: async () => {
                await writing;
            },
        };
    }
}

/** The exercise cannot be graded: it has no grading folder. */
export class GradingUnavailable extends Error {}

/** A run of the same kind (the student's submission, the course's grading) is queued or running already. */
export class GradingBusy extends Error {}
