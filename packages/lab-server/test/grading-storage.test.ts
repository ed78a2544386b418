// The storage of autograding on both backends (migration 0004): an exercise's grading, grading
// runs with their progress and end, results, the latest submission and result per student.
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { InvalidPathError, type LabStore, openLabStore, StorageConflictError } from '../src/storage/index.js';
import { BACKENDS, type Backend, startBackend } from './backends.js';

describe.each(BACKENDS)('grading storage on %s', (backendName) => {
    let backend: Backend;
    let store: LabStore;

    beforeAll(async () => {
        backend = await startBackend(backendName);
        store = await openLabStore(await backend.freshStorage());
    });
    afterAll(async () => {
        await store?.close();
        await backend?.dispose();
    });

    it('keeps an exercise’s grading (replaced by a second release, removed on request)', async () => {
        const c = await store.createCourse({ name: 'g1', title: 'G' });
        const exercise = await store.createExercise({ courseId: c.id, name: 'x', spec: {} });
        expect(await store.exerciseGrading(exercise.id)).toBeUndefined();
        await store.setExerciseGrading(exercise.id, { spec: { format: 'maa-grading/1', criteria: [] }, files: { 'a.stream': 'one' } });
        await store.setExerciseGrading(exercise.id, { spec: { format: 'maa-grading/1', criteria: [1] }, files: { 'b.stream': 'two' } });
        expect(await store.exerciseGrading(exercise.id)).toMatchObject({
            spec: { criteria: [1] },
            files: { 'b.stream': 'two' },
        });
        await expect(store.setExerciseGrading(exercise.id, { spec: {}, files: { '../up.stream': '' } })).rejects.toThrow(InvalidPathError);
        await expect(store.setExerciseGrading(999_999, { spec: {}, files: {} })).rejects.toThrow(StorageConflictError);
        await store.deleteExerciseGrading(exercise.id);
        expect(await store.exerciseGrading(exercise.id)).toBeUndefined();
    });

    it('records runs, their progress and results; the latest submission and result per student', async () => {
        const c = await store.createCourse({ name: 'g2', title: 'G' });
        const teacher = await store.createUser({ login: 'g2-teacher', name: 'T', role: 'instructor' });
        // One after the other: latestSubmissions lists by owner id, so ada's id must be the lower.
        const ada = await store.createUser({ login: 'g2-ada', name: 'g2-ada', role: 'student' });
        const bob = await store.createUser({ login: 'g2-bob', name: 'g2-bob', role: 'student' });
        const exercise = await store.createExercise({ courseId: c.id, name: 'x', spec: {} });
        const wsAda = await store.workspace(ada!.id, exercise.id);
        const wsBob = await store.workspace(bob!.id, exercise.id);
        await store.saveFile({ workspaceId: wsAda.id, path: 'a.arc', content: 'one', authorId: ada!.id });
        const first = await store.submit(wsAda.id, ada!.id);
        await store.saveFile({ workspaceId: wsAda.id, path: 'a.arc', content: 'two', authorId: ada!.id });
        const second = await store.submit(wsAda.id, ada!.id);
        const ofBob = await store.submit(wsBob.id, bob!.id);
        expect(await store.findSubmission(second.id)).toMatchObject({ ownerId: ada!.id, files: { 'a.arc': 2 } });
        expect(await store.findSubmission(999_999)).toBeUndefined();
        expect((await store.latestSubmissions(exercise.id)).map((s) => s.id)).toEqual([second.id, ofBob.id]);

        const run = await store.createGradingRun({ exerciseId: exercise.id, kind: 'course', requestedBy: teacher.id, total: 2 });
        expect(run).toMatchObject({ status: 'queued', done: 0, total: 2, error: null, startedAt: null });
        const started = await store.updateGradingRun(run.id, { status: 'running', startedAt: new Date() });
        expect(started.startedAt).toBeInstanceOf(Date);
        expect((await store.updateGradingRun(run.id, { done: 1, total: 4 })).done).toBe(1);
        const grade = { submission: String(first.id), score: 5, maxScore: 10, criteria: [], recordings: [], tasks: [] };
        const old = await store.recordGradingResult({
            runId: run.id,
            submissionId: first.id,
            userId: ada!.id,
            score: 5,
            maxScore: 10,
            grade,
            recordings: [],
        });
        const newer = await store.recordGradingResult({
            runId: run.id,
            submissionId: second.id,
            userId: ada!.id,
            score: 9,
            maxScore: 10,
            grade: { ...grade, score: 9 },
            recordings: [],
        });
        await store.setGradingRecordings(newer.id, [{ scenario: 'standard', path: 'recordings/1/2/standard.mcap' }]);
        await expect(store.setGradingRecordings(999_999, [])).rejects.toThrow(StorageConflictError);
        expect((await store.findGradingResult(newer.id))?.recordings).toEqual([
            { scenario: 'standard', path: 'recordings/1/2/standard.mcap' },
        ]);
        expect((await store.runResults(run.id)).map((r) => r.id)).toEqual([old.id, newer.id]);
        expect((await store.latestGradingResults(exercise.id)).map((r) => r.id)).toEqual([newer.id]);
        expect(await store.latestGradingResults(exercise.id, bob!.id)).toEqual([]);
        const done = await store.updateGradingRun(run.id, { status: 'done', done: 4, finishedAt: new Date() });
        expect(done).toMatchObject({ status: 'done', done: 4, total: 4 });
        await expect(store.updateGradingRun(999_999, { done: 1 })).rejects.toThrow(StorageConflictError);
        await expect(store.createGradingRun({ exerciseId: exercise.id, kind: 'course', requestedBy: 999_999 })).rejects.toThrow(
            StorageConflictError,
        );

        // A server that stopped during a run: its unfinished runs fail, with the reason, never stuck.
        const stuck = await store.createGradingRun({ exerciseId: exercise.id, kind: 'submission', requestedBy: ada!.id });
        expect(await store.failUnfinishedGradingRuns('the lab server stopped during the run')).toBe(1);
        expect(await store.findGradingRun(stuck.id)).toMatchObject({ status: 'failed', error: 'the lab server stopped during the run' });
        expect((await store.listGradingRuns(exercise.id)).map((r) => r.id)).toEqual([stuck.id, run.id]);
    });
});
