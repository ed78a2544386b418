// Exercise starters (docs/lab.md "Exercises"): every version of an exercise's starter files, and
// per student file the starter version it was last merged with (the base of the next three-way
// merge) and the newer version that could not be merged into it, if any.
import { type Kysely, sql } from 'kysely';

// biome-ignore lint/suspicious/noExplicitAny: a migration runs against the schema as it was then, not the current Database type
export async function up(db: Kysely<any>): Promise<void> {
    await db.schema
        .createTable('starter_versions')
        .addColumn('exercise_id', 'integer', (c) => c.notNull().references('exercises.id').onDelete('cascade'))
        .addColumn('version', 'integer', (c) => c.notNull().check(sql`version > 0`))
        .addColumn('files', 'jsonb', (c) => c.notNull())
        .addColumn('created_at', 'timestamptz', (c) => c.notNull().defaultTo(sql`now()`))
        .addPrimaryKeyConstraint('starter_versions_pk', ['exercise_id', 'version'])
        .execute();
    await db.schema
        .createTable('starter_files')
        .addColumn('workspace_id', 'integer', (c) => c.notNull().references('workspaces.id').onDelete('cascade'))
        .addColumn('path', 'text', (c) => c.notNull())
        .addColumn('base_version', 'integer', (c) => c.notNull())
        .addColumn('conflict_version', 'integer')
        .addColumn('updated_at', 'timestamptz', (c) => c.notNull().defaultTo(sql`now()`))
        .addPrimaryKeyConstraint('starter_files_pk', ['workspace_id', 'path'])
        .execute();
}

// biome-ignore lint/suspicious/noExplicitAny: see up()
export async function down(db: Kysely<any>): Promise<void> {
    await db.schema.dropTable('starter_files').execute();
    await db.schema.dropTable('starter_versions').execute();
}
