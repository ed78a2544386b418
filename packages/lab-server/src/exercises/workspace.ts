// A student's workspace for a released exercise: the starter's files on first open.
import type { Exercise, LabStore, Workspace } from '../storage/index.js';
import { ExerciseError } from './errors.js';

/**
 * The owner's workspace for the exercise. The first time (no file of it came from the starter
 * yet) it gets the newest starter's files, each saved as a revision by `authorId` (default: the
 * owner), and each recorded with the starter version it is, the base of later merges. So
 * students enrolled after the release get the starter when they first open the exercise.
 */
export async function openExerciseWorkspace(store: LabStore, exercise: Exercise, ownerId: number, authorId = ownerId): Promise<Workspace> {
    if (!exercise.releasedAt) throw new ExerciseError(`the exercise ${exercise.name} is not released`);
    const workspace = await store.workspace(ownerId, exercise.id);
    if ((await store.starterFiles(workspace.id)).length > 0) return workspace;
    const starter = await store.starterVersion(exercise.id);
    if (!starter) throw new ExerciseError(`the exercise ${exercise.name} has no starter`);
    for (const [path, content] of Object.entries(starter.files)) {
        // A file the owner saved before the starter came (not possible through the lab, but kept) stays.
        if (!(await store.readFile(workspace.id, path))) await store.saveFile({ workspaceId: workspace.id, path, content, authorId });
        await store.setStarterFile(workspace.id, { path, baseVersion: starter.version, conflictVersion: null });
    }
    return workspace;
}
