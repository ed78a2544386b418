// Autograding's tables (migration 0004): an exercise's grading as released, grading runs and
// their results. src/grading runs the gradings; this file only stores.
import type { Kysely, Selectable } from 'kysely';
import { checkWorkspacePath } from './paths.js';
import type { Database } from './schema.js';
import {
    type ExerciseGrading,
    type GradingRecording,
    type GradingResult,
    type GradingRun,
    type GradingRunKind,
    type GradingRunUpdate,
    type OwnedSubmission,
    StorageConflictError,
} from './types.js';

type Row<T extends keyof Database> = Selectable<Database[T]>;

function toRun(r: Row<'grading_runs'>): GradingRun {
    return {
        id: r.id,
        exerciseId: r.exercise_id,
        kind: r.kind,
        requestedBy: r.requested_by,
        status: r.status,
        done: r.done,
        total: r.total,
        error: r.error,
        createdAt: r.created_at,
        startedAt: r.started_at,
        finishedAt: r.finished_at,
    };
}

function toResult(r: Row<'grading_results'>): GradingResult {
    return {
        id: r.id,
        runId: r.run_id,
        submissionId: r.submission_id,
        userId: r.user_id,
        score: r.score,
        maxScore: r.max_score,
        grade: r.criteria,
        recordings: r.recordings,
        createdAt: r.created_at,
    };
}

function toOwnedSubmission(r: Row<'submissions'> & { owner_id: number }): OwnedSubmission {
    return {
        id: r.id,
        workspaceId: r.workspace_id,
        submittedBy: r.submitted_by,
        files: r.files,
        createdAt: r.created_at,
        ownerId: r.owner_id,
    };
}

export async function findSubmission(db: Kysely<Database>, id: number): Promise<OwnedSubmission | undefined> {
    const row = await db
        .selectFrom('submissions')
        .innerJoin('workspaces', 'workspaces.id', 'submissions.workspace_id')
        .selectAll('submissions')
        .select('workspaces.owner_id')
        .where('submissions.id', '=', id)
        .executeTakeFirst();
    return row && toOwnedSubmission(row);
}

export async function latestSubmissions(db: Kysely<Database>, exerciseId: number): Promise<OwnedSubmission[]> {
    const rows = await db
        .selectFrom('submissions')
        .innerJoin('workspaces', 'workspaces.id', 'submissions.workspace_id')
        .selectAll('submissions')
        .select('workspaces.owner_id')
        .distinctOn('submissions.workspace_id')
        .where('workspaces.exercise_id', '=', exerciseId)
        .orderBy('submissions.workspace_id')
        .orderBy('submissions.id', 'desc')
        .execute();
    return rows.map(toOwnedSubmission).sort((a, b) => a.ownerId - b.ownerId);
}

export async function upsertExerciseGrading(
    db: Kysely<Database>,
    exerciseId: number,
    grading: { spec: Record<string, unknown>; files: Record<string, string> },
): Promise<ExerciseGrading> {
    for (const path of Object.keys(grading.files)) checkWorkspacePath(path);
    const values = { spec: JSON.stringify(grading.spec), files: JSON.stringify(grading.files), updated_at: new Date() };
    const row = await db
        .insertInto('exercise_gradings')
        .values({ exercise_id: exerciseId, ...values })
        .onConflict((oc) => oc.column('exercise_id').doUpdateSet(values))
        .returningAll()
        .executeTakeFirstOrThrow();
    return { exerciseId: row.exercise_id, spec: row.spec, files: row.files, updatedAt: row.updated_at };
}

export async function selectExerciseGrading(db: Kysely<Database>, exerciseId: number): Promise<ExerciseGrading | undefined> {
    const row = await db.selectFrom('exercise_gradings').selectAll().where('exercise_id', '=', exerciseId).executeTakeFirst();
    return row && { exerciseId: row.exercise_id, spec: row.spec, files: row.files, updatedAt: row.updated_at };
}

export async function removeExerciseGrading(db: Kysely<Database>, exerciseId: number): Promise<void> {
    await db.deleteFrom('exercise_gradings').where('exercise_id', '=', exerciseId).execute();
}

export async function insertRun(
    db: Kysely<Database>,
    run: { exerciseId: number; kind: GradingRunKind; requestedBy: number; total?: number },
): Promise<GradingRun> {
    const row = await db
        .insertInto('grading_runs')
        .values({ exercise_id: run.exerciseId, kind: run.kind, requested_by: run.requestedBy, status: 'queued', total: run.total ?? 0 })
        .returningAll()
        .executeTakeFirstOrThrow();
    return toRun(row);
}

export async function updateRun(db: Kysely<Database>, id: number, u: GradingRunUpdate): Promise<GradingRun> {
    const set = {
        ...(u.status !== undefined ? { status: u.status } : {}),
        ...(u.done !== undefined ? { done: u.done } : {}),
        ...(u.total !== undefined ? { total: u.total } : {}),
        ...(u.error !== undefined ? { error: u.error } : {}),
        ...(u.startedAt !== undefined ? { started_at: u.startedAt } : {}),
        ...(u.finishedAt !== undefined ? { finished_at: u.finishedAt } : {}),
    };
    const row =
        Object.keys(set).length === 0
            ? await db.selectFrom('grading_runs').selectAll().where('id', '=', id).executeTakeFirst()
            : await db.updateTable('grading_runs').set(set).where('id', '=', id).returningAll().executeTakeFirst();
    if (!row) throw new StorageConflictError(`there is no grading run ${id}`);
    return toRun(row);
}

export async function selectRun(db: Kysely<Database>, id: number): Promise<GradingRun | undefined> {
    const row = await db.selectFrom('grading_runs').selectAll().where('id', '=', id).executeTakeFirst();
    return row && toRun(row);
}

export async function selectRuns(db: Kysely<Database>, exerciseId: number, limit = 20): Promise<GradingRun[]> {
    const rows = await db
        .selectFrom('grading_runs')
        .selectAll()
        .where('exercise_id', '=', exerciseId)
        .orderBy('id', 'desc')
        .limit(limit)
        .execute();
    return rows.map(toRun);
}

export async function failUnfinished(db: Kysely<Database>, error: string): Promise<number> {
    const { numUpdatedRows } = await db
        .updateTable('grading_runs')
        .set({ status: 'failed', error, finished_at: new Date() })
        .where('status', 'in', ['queued', 'running'])
        .executeTakeFirstOrThrow();
    return Number(numUpdatedRows);
}

export async function insertResult(db: Kysely<Database>, r: Omit<GradingResult, 'id' | 'createdAt'>): Promise<GradingResult> {
    const row = await db
        .insertInto('grading_results')
        .values({
            run_id: r.runId,
            submission_id: r.submissionId,
            user_id: r.userId,
            score: r.score,
            max_score: r.maxScore,
            criteria: JSON.stringify(r.grade),
            recordings: JSON.stringify(r.recordings),
        })
        .returningAll()
        .executeTakeFirstOrThrow();
    return toResult(row);
}

export async function updateRecordings(db: Kysely<Database>, resultId: number, recordings: GradingRecording[]): Promise<void> {
    const { numUpdatedRows } = await db
        .updateTable('grading_results')
        .set({ recordings: JSON.stringify(recordings) })
        .where('id', '=', resultId)
        .executeTakeFirstOrThrow();
    if (numUpdatedRows === 0n) throw new StorageConflictError(`there is no grading result ${resultId}`);
}

export async function selectResult(db: Kysely<Database>, id: number): Promise<GradingResult | undefined> {
    const row = await db.selectFrom('grading_results').selectAll().where('id', '=', id).executeTakeFirst();
    return row && toResult(row);
}

export async function selectRunResults(db: Kysely<Database>, runId: number): Promise<GradingResult[]> {
    const rows = await db.selectFrom('grading_results').selectAll().where('run_id', '=', runId).orderBy('user_id').execute();
    return rows.map(toResult);
}

export async function selectLatestResults(db: Kysely<Database>, exerciseId: number, userId?: number): Promise<GradingResult[]> {
    let query = db
        .selectFrom('grading_results')
        .innerJoin('grading_runs', 'grading_runs.id', 'grading_results.run_id')
        .selectAll('grading_results')
        .distinctOn('grading_results.user_id')
        .where('grading_runs.exercise_id', '=', exerciseId);
    if (userId !== undefined) query = query.where('grading_results.user_id', '=', userId);
    const rows = await query.orderBy('grading_results.user_id').orderBy('grading_results.id', 'desc').execute();
    return rows.map(toResult);
}
