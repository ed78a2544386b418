import type { Course, LabStore } from '../storage/index.js';
import { ExerciseError } from './errors.js';

/** The course of that name, or an {@link ExerciseError}. */
export async function courseNamed(store: LabStore, name: string): Promise<Course> {
    const course = await store.findCourse(name);
    if (!course) throw new ExerciseError(`there is no course ${JSON.stringify(name)}`);
    return course;
}
