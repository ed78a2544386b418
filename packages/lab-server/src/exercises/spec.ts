// The released exercise stored in an exercise's row (LabStore keeps it as plain JSON).
import { type ReleasedExercise, releasedExerciseContract } from '@maa/protocol/exercise';
import type { Exercise } from '../storage/index.js';
import { ExerciseError } from './errors.js';

/** The exercise's released spec, checked (a row written by another version fails here, by name). */
export function specOf(exercise: Exercise): ReleasedExercise {
    const issues = releasedExerciseContract.issues(exercise.spec);
    if (issues.length > 0) {
        const problems = issues.map((i) => `exercise ${exercise.name}: ${i.pointer || '/'}: ${i.message}`);
        throw new ExerciseError(`the stored exercise ${exercise.name} is not a released exercise:\n${problems.join('\n')}`, problems);
    }
    return exercise.spec as ReleasedExercise;
}
