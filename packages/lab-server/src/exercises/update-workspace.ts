// A starter update reaching one workspace without overwriting the student's edits.
import { isReadOnly, type ReleasedExercise } from '@maa/protocol/exercise';
import type { LabStore, StarterFile, StarterVersion } from '../storage/index.js';
import { mergeStarter } from './merge.js';

/** The suffix of the file that shows a student a conflict: `toast/Controller.arc.conflict`. */
export const CONFLICT_SUFFIX = '.conflict';

/** What an update did to one file of one workspace. */
export type FileOutcome =
    /** a new starter file, added */
    | 'added'
    /** the student had not changed it (or may not): it is the new starter now */
    | 'replaced'
    /** the student's edits and the starter's changes merged cleanly: a new revision */
    | 'merged'
    /** the starter's change was there already, or the file is the same in both starters */
    | 'unchanged'
    /** gone from the starter and unchanged by the student: deleted */
    | 'removed'
    /** gone from the starter but edited by the student: kept */
    | 'kept'
    /** both changed the same lines: the student's file stays, the markers are in `<path>.conflict` */
    | 'conflict';

export interface FileUpdate {
    path: string;
    outcome: FileOutcome;
}

/** One file's three versions: the base the student got, the student's and the new starter's (undefined: none). */
interface Versions {
    path: string;
    base: string | undefined;
    theirs: string | undefined;
    next: string | undefined;
    readOnly: boolean;
}

/** Starter versions by number, each read once per update. */
export type StarterCache = Map<number, Promise<StarterVersion | undefined>>;

function starterAt(store: LabStore, exerciseId: number, version: number, cache: StarterCache): Promise<StarterVersion | undefined> {
    let found = cache.get(version);
    if (!found) {
        found = store.starterVersion(exerciseId, version);
        cache.set(version, found);
    }
    return found;
}

/**
 * Brings the workspace to the starter `next`: every file of the new starter and every file that
 * came from an older one. A read-only file always takes the new starter; any other file is merged
 * three-way (base = the starter version the student's file was last merged with). A conflict
 * leaves the student's file as it is, writes the file with conflict markers beside it
 * (`<path>.conflict`) and records the conflict (StarterFile.conflictVersion); the base stays, so
 * the next update merges from it again. A later clean merge removes the `.conflict` file.
 */
export async function updateWorkspace(
    store: LabStore,
    workspaceId: number,
    spec: ReleasedExercise,
    next: StarterVersion,
    authorId: number,
    cache: StarterCache = new Map(),
): Promise<FileUpdate[]> {
    const known = new Map((await store.starterFiles(workspaceId)).map((f) => [f.path, f]));
    const paths = [...new Set([...Object.keys(next.files), ...known.keys()])].sort();
    const updates: FileUpdate[] = [];
    for (const path of paths) {
        const starterFile = known.get(path);
        const base = starterFile && (await starterAt(store, next.exerciseId, starterFile.baseVersion, cache))?.files[path];
        const theirs = (await store.readFile(workspaceId, path))?.content ?? undefined;
        const versions: Versions = { path, base, theirs, next: next.files[path], readOnly: isReadOnly(spec, path) };
        const outcome = await applyUpdate(store, workspaceId, versions, next.version, starterFile, authorId);
        updates.push({ path, outcome });
    }
    return updates;
}

async function applyUpdate(
    store: LabStore,
    workspaceId: number,
    v: Versions,
    nextVersion: number,
    starterFile: StarterFile | undefined,
    authorId: number,
): Promise<FileOutcome> {
    const write = async (content: string | undefined): Promise<void> => {
        if (content === v.theirs) return;
        if (content === undefined) await store.deleteFile({ workspaceId, path: v.path, authorId });
        else await store.saveFile({ workspaceId, path: v.path, content, authorId });
    };
    const settle = async (outcome: FileOutcome, conflictVersion: number | null = null): Promise<FileOutcome> => {
        const baseVersion = conflictVersion === null ? nextVersion : (starterFile?.baseVersion ?? nextVersion);
        await store.setStarterFile(workspaceId, { path: v.path, baseVersion, conflictVersion });
        if (conflictVersion === null && starterFile?.conflictVersion != null)
            await removeConflictFile(store, workspaceId, v.path, authorId);
        return outcome;
    };
    const outcome = plainOutcome(v);
    if (outcome) {
        if (outcome !== 'unchanged' && outcome !== 'kept') await write(v.next);
        return settle(outcome);
    }
    // Both changed the file: merge (a file the student added at a new starter path merges from empty).
    const merged = mergeStarter(v.base ?? '', v.theirs ?? '', v.next ?? '', {
        theirs: `your ${v.path}`,
        base: `starter version ${starterFile?.baseVersion ?? 0} (what you started from)`,
        next: `starter version ${nextVersion} (the update)`,
    });
    if (merged.clean && v.theirs !== undefined && v.next !== undefined) {
        await write(merged.content);
        return settle('merged');
    }
    const marked = merged.clean ? (v.next ?? '') : merged.marked;
    await store.saveFile({ workspaceId, path: `${v.path}${CONFLICT_SUFFIX}`, content: marked, authorId });
    return settle('conflict', nextVersion);
}

/** The outcome when no merge is needed, or undefined when both sides changed the file. */
function plainOutcome(v: Versions): FileOutcome | undefined {
    if (v.theirs === v.next) return 'unchanged';
    if (v.readOnly) return v.next === undefined ? 'removed' : v.theirs === undefined ? 'added' : 'replaced';
    if (v.base === v.next) return 'unchanged';
    if (v.theirs === v.base) return v.next === undefined ? 'removed' : v.theirs === undefined ? 'added' : 'replaced';
    if (v.next === undefined) return 'kept';
    return undefined;
}

async function removeConflictFile(store: LabStore, workspaceId: number, path: string, authorId: number): Promise<void> {
    const conflictPath = `${path}${CONFLICT_SUFFIX}`;
    if (await store.readFile(workspaceId, conflictPath)) await store.deleteFile({ workspaceId, path: conflictPath, authorId });
}
