// Releasing an exercise folder to a course.
import type { ReleasedExercise } from '@maa/protocol/exercise';
import type { Exercise, LabStore } from '../storage/index.js';
import { courseNamed } from './course.js';
import { ExerciseError } from './errors.js';
import { type LoadedExercise, releasedSpec } from './load.js';
import { openExerciseWorkspace } from './workspace.js';

export interface ReleaseOptions {
    /** the course's name */
    course: string;
    /** the instructor releasing it: the author of the starter revisions */
    authorId: number;
}

export interface Released {
    exercise: Exercise;
    spec: ReleasedExercise;
    /** the logins of the enrolled users who got a workspace with the starter */
    workspaces: string[];
}

/**
 * Releases the exercise to the course: stores its spec and starter (version 1), and gives every
 * enrolled user a workspace with the starter's files. Users enrolled later get theirs when they
 * first open it (openExerciseWorkspace). A name released before is refused: that is an update.
 */
export async function releaseExercise(store: LabStore, exercise: LoadedExercise, options: ReleaseOptions): Promise<Released> {
    const course = await courseNamed(store, options.course);
    if (await store.findExercise(course.id, exercise.name))
        throw new ExerciseError(
            `the course ${course.name} has the exercise ${exercise.name} already: update it (maa-lab exercise update ${exercise.folder} --course ${course.name})`,
        );
    const spec = releasedSpec(exercise, 1);
    const created = await store.createExercise({ courseId: course.id, name: exercise.name, spec: { ...spec } });
    await store.addStarterVersion(created.id, exercise.files);
    if (exercise.grading) await store.setExerciseGrading(created.id, exercise.grading);
    const released = await store.releaseExercise(created.id);
    const workspaces: string[] = [];
    for (const user of await store.listEnrolled(course.id)) {
        await openExerciseWorkspace(store, released, user.id, options.authorId);
        workspaces.push(user.login);
    }
    return { exercise: released, spec, workspaces };
}
