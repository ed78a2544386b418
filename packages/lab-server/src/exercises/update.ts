// Bringing an updated exercise folder to a released exercise and to every student's workspace.
import type { ReleasedExercise } from '@maa/protocol/exercise';
import type { Exercise, LabStore } from '../storage/index.js';
import { courseNamed } from './course.js';
import { ExerciseError } from './errors.js';
import { type LoadedExercise, releasedSpec } from './load.js';
import type { ReleaseOptions } from './release.js';
import { specOf } from './spec.js';
import { type FileUpdate, type StarterCache, updateWorkspace } from './update-workspace.js';

export interface Updated {
    exercise: Exercise;
    spec: ReleasedExercise;
    /** whether the starter's files changed (a new starter version) */
    newStarter: boolean;
    /** per workspace owner's login, what happened to each file */
    workspaces: Array<{ login: string; files: FileUpdate[] }>;
}

function sameFiles(a: Record<string, string>, b: Record<string, string>): boolean {
    const keys = Object.keys(a);
    return keys.length === Object.keys(b).length && keys.every((k) => Object.hasOwn(b, k) && a[k] === b[k]);
}

/**
 * Brings the updated exercise folder to the released exercise: its spec (title, description,
 * read-only files, tests, platforms) is replaced; when the starter's files changed they become
 * the next starter version and reach every workspace without overwriting students' edits
 * (updateWorkspace: a three-way merge, or a conflict the student sees).
 */
export async function updateExercise(store: LabStore, exercise: LoadedExercise, options: ReleaseOptions): Promise<Updated> {
    const course = await courseNamed(store, options.course);
    const found = await store.findExercise(course.id, exercise.name);
    if (!found)
        throw new ExerciseError(
            `the course ${course.name} has no exercise ${exercise.name}: release it first (maa-lab exercise release ${exercise.folder} --course ${course.name})`,
        );
    const previous = specOf(found);
    const newest = await store.starterVersion(found.id);
    const newStarter = !newest || !sameFiles(newest.files, exercise.files);
    const next = newest && !newStarter ? newest : await store.addStarterVersion(found.id, exercise.files);
    const spec = releasedSpec(exercise, next.version);
    const updated = await store.updateExerciseSpec(found.id, { ...spec });
    // The grading follows the folder: replaced, or removed when the folder has none any more.
    if (exercise.grading) await store.setExerciseGrading(found.id, exercise.grading);
    else await store.deleteExerciseGrading(found.id);
    const workspaces: Updated['workspaces'] = [];
    const readOnlyChanged = previous.readOnly.join('\n') !== spec.readOnly.join('\n');
    if (newStarter || readOnlyChanged) {
        const cache: StarterCache = new Map();
        for (const ws of await store.listWorkspaces(found.id)) {
            const owner = await store.findUserById(ws.ownerId);
            const files = await updateWorkspace(store, ws.id, spec, next, options.authorId, cache);
            workspaces.push({ login: owner?.login ?? `#${ws.ownerId}`, files });
        }
    }
    return { exercise: updated, spec, newStarter, workspaces };
}
