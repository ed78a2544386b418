// Workspace files with history: every save, delete and restore inserts a revision
// (workspace, path, revision, content, author, created_at); nothing is updated or removed.
import { type Kysely, sql, type Transaction } from 'kysely';
import { checkWorkspacePath } from './paths.js';
import { toRevision, toRevisionInfo } from './rows.js';
import type { Database } from './schema.js';
import { type FileRevision, type FileRevisionInfo, StorageConflictError, type WorkspaceSize, type WorkspaceSummary } from './types.js';

interface NewRevision {
    workspaceId: number;
    path: string;
    content: string | null;
    authorId: number;
    restoredFrom?: number;
}

/**
 * Inserts the next revision of a file. The workspace row is locked for the transaction, so two
 * saves of one workspace take turns and each gets its own revision number.
 */
export async function insertRevision(db: Kysely<Database>, r: NewRevision): Promise<FileRevision> {
    const path = checkWorkspacePath(r.path);
    return db.transaction().execute(async (tx) => {
        await lockWorkspace(tx, r.workspaceId);
        const { latest } = await tx
            .selectFrom('file_revisions')
            .select((eb) => eb.fn.max('revision').as('latest'))
            .where('workspace_id', '=', r.workspaceId)
            .where('path', '=', path)
            .executeTakeFirstOrThrow();
        const row = await tx
            .insertInto('file_revisions')
            .values({
                workspace_id: r.workspaceId,
                path,
                revision: (latest ?? 0) + 1,
                content: r.content,
                author_id: r.authorId,
                restored_from: r.restoredFrom ?? null,
            })
            .returningAll()
            .executeTakeFirstOrThrow();
        return toRevision(row);
    });
}

async function lockWorkspace(tx: Transaction<Database>, workspaceId: number): Promise<void> {
    const locked = await tx.selectFrom('workspaces').select('id').where('id', '=', workspaceId).forUpdate().executeTakeFirst();
    if (!locked) throw new StorageConflictError(`there is no workspace ${workspaceId}`);
}

export async function readRevision(
    db: Kysely<Database>,
    workspaceId: number,
    path: string,
    revision?: number,
): Promise<FileRevision | undefined> {
    let query = db
        .selectFrom('file_revisions')
        .select(['path', 'revision', 'content', 'author_id', 'restored_from', 'created_at'])
        .where('workspace_id', '=', workspaceId)
        .where('path', '=', checkWorkspacePath(path));
    query = revision === undefined ? query.orderBy('revision', 'desc').limit(1) : query.where('revision', '=', revision);
    const row = await query.executeTakeFirst();
    if (!row || (revision === undefined && row.content === null)) return undefined;
    return toRevision(row);
}

/** The columns of a revision without its content (the size and whether it is a deletion instead). */
function infoColumns() {
    return [
        'path',
        'revision',
        'author_id',
        'restored_from',
        'created_at',
        sql<number | null>`octet_length(content)`.as('size'),
        sql<boolean>`content IS NULL`.as('deleted'),
    ] as const;
}

export async function latestRevisions(db: Kysely<Database>, workspaceId: number): Promise<FileRevisionInfo[]> {
    const rows = await db
        .selectFrom('file_revisions')
        .distinctOn('path')
        .select(infoColumns())
        .where('workspace_id', '=', workspaceId)
        .orderBy('path')
        .orderBy('revision', 'desc')
        .execute();
    return rows.filter((r) => !r.deleted).map(toRevisionInfo);
}

export async function revisionHistory(db: Kysely<Database>, workspaceId: number, path: string): Promise<FileRevisionInfo[]> {
    const rows = await db
        .selectFrom('file_revisions')
        .select(infoColumns())
        .where('workspace_id', '=', workspaceId)
        .where('path', '=', checkWorkspacePath(path))
        .orderBy('revision', 'desc')
        .execute();
    return rows.map(toRevisionInfo);
}

/** A new revision with the content of an earlier one (restoring a deletion deletes the file again). */
export async function restoreRevision(
    db: Kysely<Database>,
    r: { workspaceId: number; path: string; revision: number; authorId: number },
): Promise<FileRevision> {
    const earlier = await readRevision(db, r.workspaceId, r.path, r.revision);
    if (!earlier) throw new StorageConflictError(`${r.path} has no revision ${r.revision} in workspace ${r.workspaceId}`);
    return insertRevision(db, {
        workspaceId: r.workspaceId,
        path: r.path,
        content: earlier.content,
        authorId: r.authorId,
        restoredFrom: r.revision,
    });
}

export async function currentSize(db: Kysely<Database>, workspaceId: number): Promise<WorkspaceSize> {
    const files = await latestRevisions(db, workspaceId);
    return { files: files.length, bytes: files.reduce((sum, f) => sum + f.size, 0) };
}

export async function exerciseWorkspaces(db: Kysely<Database>, exerciseId: number): Promise<WorkspaceSummary[]> {
    const rows = await db
        .selectFrom('workspaces')
        .leftJoin('file_revisions', 'file_revisions.workspace_id', 'workspaces.id')
        .select((eb) => [
            'workspaces.id',
            'workspaces.owner_id',
            'workspaces.exercise_id',
            'workspaces.created_at',
            eb.fn.max('file_revisions.created_at').as('last_activity'),
        ])
        .where('workspaces.exercise_id', '=', exerciseId)
        .groupBy(['workspaces.id', 'workspaces.owner_id', 'workspaces.exercise_id', 'workspaces.created_at'])
        .orderBy('workspaces.owner_id')
        .execute();
    return rows.map((r) => ({
        id: r.id,
        ownerId: r.owner_id,
        exerciseId: r.exercise_id,
        createdAt: r.created_at,
        lastActivity: r.last_activity,
    }));
}
