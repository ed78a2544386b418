// Exercise starters: the versions of an exercise's starter files and, per workspace file, the
// starter version it was last merged with (src/exercises/ merges; this file only stores).
import type { Kysely } from 'kysely';
import { checkWorkspacePath } from './paths.js';
import type { Database } from './schema.js';
import { type Exercise, type StarterFile, type StarterVersion, StorageConflictError } from './types.js';
import { toExercise } from './rows.js';

export async function updateSpec(db: Kysely<Database>, exerciseId: number, spec: Record<string, unknown>): Promise<Exercise> {
    const row = await db
        .updateTable('exercises')
        .set({ spec: JSON.stringify(spec) })
        .where('id', '=', exerciseId)
        .returningAll()
        .executeTakeFirst();
    if (!row) throw new StorageConflictError(`there is no exercise ${exerciseId}`);
    return toExercise(row);
}

/** Inserts the next starter version (1 for the first); the exercise row is locked so versions are distinct. */
export async function insertStarterVersion(
    db: Kysely<Database>,
    exerciseId: number,
    files: Record<string, string>,
): Promise<StarterVersion> {
    for (const path of Object.keys(files)) checkWorkspacePath(path);
    return db.transaction().execute(async (tx) => {
        const exercise = await tx.selectFrom('exercises').select('id').where('id', '=', exerciseId).forUpdate().executeTakeFirst();
        if (!exercise) throw new StorageConflictError(`there is no exercise ${exerciseId}`);
        const { latest } = await tx
            .selectFrom('starter_versions')
            .select((eb) => eb.fn.max('version').as('latest'))
            .where('exercise_id', '=', exerciseId)
            .executeTakeFirstOrThrow();
        const row = await tx
            .insertInto('starter_versions')
            .values({ exercise_id: exerciseId, version: (latest ?? 0) + 1, files: JSON.stringify(files) })
            .returningAll()
            .executeTakeFirstOrThrow();
        return { exerciseId: row.exercise_id, version: row.version, files: row.files, createdAt: row.created_at };
    });
}

export async function selectStarterVersion(
    db: Kysely<Database>,
    exerciseId: number,
    version?: number,
): Promise<StarterVersion | undefined> {
    let query = db.selectFrom('starter_versions').selectAll().where('exercise_id', '=', exerciseId);
    query = version === undefined ? query.orderBy('version', 'desc').limit(1) : query.where('version', '=', version);
    const row = await query.executeTakeFirst();
    return row && { exerciseId: row.exercise_id, version: row.version, files: row.files, createdAt: row.created_at };
}

export async function selectStarterFiles(db: Kysely<Database>, workspaceId: number): Promise<StarterFile[]> {
    const rows = await db.selectFrom('starter_files').selectAll().where('workspace_id', '=', workspaceId).orderBy('path').execute();
    return rows.map((r) => ({ path: r.path, baseVersion: r.base_version, conflictVersion: r.conflict_version, updatedAt: r.updated_at }));
}

export async function upsertStarterFile(db: Kysely<Database>, workspaceId: number, file: Omit<StarterFile, 'updatedAt'>): Promise<void> {
    const path = checkWorkspacePath(file.path);
    const values = { base_version: file.baseVersion, conflict_version: file.conflictVersion, updated_at: new Date() };
    await db
        .insertInto('starter_files')
        .values({ workspace_id: workspaceId, path, ...values })
        .onConflict((oc) => oc.columns(['workspace_id', 'path']).doUpdateSet(values))
        .execute();
}
