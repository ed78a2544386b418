// Autograding (docs/lab.md "Grading"): an exercise's grading specification and hidden files as
// released (never served to students), the grading runs (a student's submission or a whole
// course) with their status and progress, and one result per graded submission (the score, each
// criterion with its feedback, and where its recordings lie in the data directory).
import { type Kysely, sql } from 'kysely';

// biome-ignore lint/suspicious/noExplicitAny: a migration runs against the schema as it was then, not the current Database type
export async function up(db: Kysely<any>): Promise<void> {
    await db.schema
        .createTable('exercise_gradings')
        .addColumn('exercise_id', 'integer', (c) => c.primaryKey().references('exercises.id').onDelete('cascade'))
        .addColumn('spec', 'jsonb', (c) => c.notNull())
        .addColumn('files', 'jsonb', (c) => c.notNull())
        .addColumn('updated_at', 'timestamptz', (c) => c.notNull().defaultTo(sql`now()`))
        .execute();
    await db.schema
        .createTable('grading_runs')
        .addColumn('id', 'serial', (c) => c.primaryKey())
        .addColumn('exercise_id', 'integer', (c) => c.notNull().references('exercises.id').onDelete('cascade'))
        .addColumn('kind', 'text', (c) => c.notNull().check(sql`kind in ('submission', 'course')`))
        .addColumn('requested_by', 'integer', (c) => c.notNull().references('users.id'))
        .addColumn('status', 'text', (c) => c.notNull().check(sql`status in ('queued', 'running', 'done', 'failed')`))
        .addColumn('done', 'integer', (c) => c.notNull().defaultTo(0))
        .addColumn('total', 'integer', (c) => c.notNull().defaultTo(0))
        .addColumn('error', 'text')
        .addColumn('created_at', 'timestamptz', (c) => c.notNull().defaultTo(sql`now()`))
        .addColumn('started_at', 'timestamptz')
        .addColumn('finished_at', 'timestamptz')
        .execute();
    await db.schema.createIndex('grading_runs_exercise').on('grading_runs').columns(['exercise_id', 'id']).execute();
    await db.schema
        .createTable('grading_results')
        .addColumn('id', 'serial', (c) => c.primaryKey())
        .addColumn('run_id', 'integer', (c) => c.notNull().references('grading_runs.id').onDelete('cascade'))
        .addColumn('submission_id', 'integer', (c) => c.notNull().references('submissions.id').onDelete('cascade'))
        .addColumn('user_id', 'integer', (c) => c.notNull().references('users.id'))
        .addColumn('score', 'double precision', (c) => c.notNull())
        .addColumn('max_score', 'double precision', (c) => c.notNull())
        .addColumn('criteria', 'jsonb', (c) => c.notNull())
        .addColumn('recordings', 'jsonb', (c) => c.notNull())
        .addColumn('created_at', 'timestamptz', (c) => c.notNull().defaultTo(sql`now()`))
        .execute();
    await db.schema.createIndex('grading_results_run').on('grading_results').column('run_id').execute();
    await db.schema.createIndex('grading_results_user').on('grading_results').columns(['user_id', 'id']).execute();
}

// biome-ignore lint/suspicious/noExplicitAny: see up()
export async function down(db: Kysely<any>): Promise<void> {
    await db.schema.dropTable('grading_results').execute();
    await db.schema.dropTable('grading_runs').execute();
    await db.schema.dropTable('exercise_gradings').execute();
}
