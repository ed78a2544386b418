// The first schema of the lab's database. Migrations are never edited once released: a change
// is a new file here, listed in ./index.ts.
import { type Kysely, sql } from 'kysely';

/** `created_at timestamptz NOT NULL DEFAULT now()` on every table. */
const now = sql`now()`;

// biome-ignore lint/suspicious/noExplicitAny: a migration runs against the schema as it was then, not the current Database type
export async function up(db: Kysely<any>): Promise<void> {
    await db.schema
        .createTable('users')
        .addColumn('id', 'integer', (c) => c.primaryKey().generatedAlwaysAsIdentity())
        .addColumn('login', 'text', (c) => c.notNull().unique())
        .addColumn('email', 'text', (c) => c.unique())
        .addColumn('name', 'text', (c) => c.notNull())
        .addColumn('role', 'text', (c) => c.notNull().check(sql`role IN ('instructor', 'student')`))
        .addColumn('password_hash', 'text')
        .addColumn('oidc_issuer', 'text')
        .addColumn('oidc_subject', 'text')
        .addColumn('created_at', 'timestamptz', (c) => c.notNull().defaultTo(now))
        .addUniqueConstraint('users_oidc_unique', ['oidc_issuer', 'oidc_subject'])
        .addCheckConstraint('users_oidc_pair', sql`(oidc_issuer IS NULL) = (oidc_subject IS NULL)`)
        .execute();
    await db.schema
        .createTable('courses')
        .addColumn('id', 'integer', (c) => c.primaryKey().generatedAlwaysAsIdentity())
        .addColumn('name', 'text', (c) => c.notNull().unique())
        .addColumn('title', 'text', (c) => c.notNull())
        .addColumn('created_at', 'timestamptz', (c) => c.notNull().defaultTo(now))
        .execute();
    await db.schema
        .createTable('enrollments')
        .addColumn('course_id', 'integer', (c) => c.notNull().references('courses.id').onDelete('cascade'))
        .addColumn('user_id', 'integer', (c) => c.notNull().references('users.id').onDelete('cascade'))
        .addColumn('created_at', 'timestamptz', (c) => c.notNull().defaultTo(now))
        .addPrimaryKeyConstraint('enrollments_pk', ['course_id', 'user_id'])
        .execute();
    await db.schema
        .createTable('exercises')
        .addColumn('id', 'integer', (c) => c.primaryKey().generatedAlwaysAsIdentity())
        .addColumn('course_id', 'integer', (c) => c.notNull().references('courses.id').onDelete('cascade'))
        .addColumn('name', 'text', (c) => c.notNull())
        .addColumn('released_at', 'timestamptz')
        .addColumn('spec', 'jsonb', (c) => c.notNull())
        .addColumn('created_at', 'timestamptz', (c) => c.notNull().defaultTo(now))
        .addUniqueConstraint('exercises_course_name', ['course_id', 'name'])
        .execute();
    await createWorkspaceTables(db);
    await createResultTables(db);
    await db.schema
        .createTable('sessions')
        .addColumn('id', 'text', (c) => c.primaryKey())
        .addColumn('user_id', 'integer', (c) => c.notNull().references('users.id').onDelete('cascade'))
        .addColumn('csrf_secret', 'text', (c) => c.notNull())
        .addColumn('created_at', 'timestamptz', (c) => c.notNull().defaultTo(now))
        .addColumn('expires_at', 'timestamptz', (c) => c.notNull())
        .execute();
    await db.schema.createIndex('sessions_expires').on('sessions').column('expires_at').execute();
}

/** Workspaces (one per student and exercise) and their files, every save a revision. */
// biome-ignore lint/suspicious/noExplicitAny: see up()
async function createWorkspaceTables(db: Kysely<any>): Promise<void> {
    await db.schema
        .createTable('workspaces')
        .addColumn('id', 'integer', (c) => c.primaryKey().generatedAlwaysAsIdentity())
        .addColumn('owner_id', 'integer', (c) => c.notNull().references('users.id').onDelete('cascade'))
        .addColumn('exercise_id', 'integer', (c) => c.notNull().references('exercises.id').onDelete('cascade'))
        .addColumn('created_at', 'timestamptz', (c) => c.notNull().defaultTo(now))
        .addUniqueConstraint('workspaces_owner_exercise', ['owner_id', 'exercise_id'])
        .execute();
    await db.schema
        .createTable('file_revisions')
        .addColumn('id', 'integer', (c) => c.primaryKey().generatedAlwaysAsIdentity())
        .addColumn('workspace_id', 'integer', (c) => c.notNull().references('workspaces.id').onDelete('cascade'))
        .addColumn('path', 'text', (c) => c.notNull())
        .addColumn('revision', 'integer', (c) => c.notNull().check(sql`revision > 0`))
        .addColumn('content', 'text')
        .addColumn('author_id', 'integer', (c) => c.notNull().references('users.id'))
        .addColumn('restored_from', 'integer')
        .addColumn('created_at', 'timestamptz', (c) => c.notNull().defaultTo(now))
        .addUniqueConstraint('file_revisions_unique', ['workspace_id', 'path', 'revision'])
        .execute();
}

/** Submissions and the results of stream tests and simulations (JSON details and summary columns). */
// biome-ignore lint/suspicious/noExplicitAny: see up()
async function createResultTables(db: Kysely<any>): Promise<void> {
    await db.schema
        .createTable('submissions')
        .addColumn('id', 'integer', (c) => c.primaryKey().generatedAlwaysAsIdentity())
        .addColumn('workspace_id', 'integer', (c) => c.notNull().references('workspaces.id').onDelete('cascade'))
        .addColumn('submitted_by', 'integer', (c) => c.notNull().references('users.id'))
        .addColumn('files', 'jsonb', (c) => c.notNull())
        .addColumn('created_at', 'timestamptz', (c) => c.notNull().defaultTo(now))
        .execute();
    await db.schema
        .createTable('test_results')
        .addColumn('id', 'integer', (c) => c.primaryKey().generatedAlwaysAsIdentity())
        .addColumn('workspace_id', 'integer', (c) => c.notNull().references('workspaces.id').onDelete('cascade'))
        .addColumn('submission_id', 'integer', (c) => c.references('submissions.id').onDelete('cascade'))
        .addColumn('passed', 'integer', (c) => c.notNull().check(sql`passed >= 0`))
        .addColumn('failed', 'integer', (c) => c.notNull().check(sql`failed >= 0`))
        .addColumn('skipped', 'integer', (c) => c.notNull().check(sql`skipped >= 0`))
        .addColumn('details', 'jsonb', (c) => c.notNull())
        .addColumn('created_at', 'timestamptz', (c) => c.notNull().defaultTo(now))
        .execute();
    await db.schema
        .createTable('simulation_results')
        .addColumn('id', 'integer', (c) => c.primaryKey().generatedAlwaysAsIdentity())
        .addColumn('workspace_id', 'integer', (c) => c.notNull().references('workspaces.id').onDelete('cascade'))
        .addColumn('submission_id', 'integer', (c) => c.references('submissions.id').onDelete('cascade'))
        .addColumn('goal_reached', 'boolean', (c) => c.notNull())
        .addColumn('simulated_seconds', 'double precision', (c) => c.notNull())
        .addColumn('details', 'jsonb', (c) => c.notNull())
        .addColumn('created_at', 'timestamptz', (c) => c.notNull().defaultTo(now))
        .execute();
    for (const table of ['test_results', 'simulation_results']) {
        await db.schema.createIndex(`${table}_workspace`).on(table).columns(['workspace_id', 'created_at']).execute();
    }
}

// biome-ignore lint/suspicious/noExplicitAny: see up()
export async function down(db: Kysely<any>): Promise<void> {
    for (const table of [
        'sessions',
        'simulation_results',
        'test_results',
        'submissions',
        'file_revisions',
        'workspaces',
        'exercises',
        'enrollments',
        'courses',
        'users',
    ]) {
        await db.schema.dropTable(table).execute();
    }
}
