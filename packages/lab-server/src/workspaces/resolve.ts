// Which workspace a request names and what its sender may do there (docs/lab.md "Workspaces"):
// a workspace is `/api/ws/<course>/<exercise>/<owner login>`; its owner may do everything, an
// instructor may read any workspace of a course (every write but a reset is 403), anyone else
// gets 403 before anything about the workspace (whether it exists) is looked up.
import type { ReleasedExercise } from '@maa/protocol/exercise';
import { HttpError } from '@maa/ide-server/http';
import type { Authenticated } from '../auth/sessions.js';
import { ExerciseError } from '../exercises/errors.js';
import { specOf } from '../exercises/spec.js';
import { openExerciseWorkspace } from '../exercises/workspace.js';
import type { Course, Exercise, LabStore, User, Workspace } from '../storage/index.js';

/** The route prefix of one workspace; the IDE's `/api/...` routes continue below it. */
export const WS_PREFIX = '/api/ws/:course/:exercise/:owner';

/** The URL path of a workspace's prefix (each name encoded as one segment). */
export function workspacePrefix(course: string, exercise: string, owner: string): string {
    return `/api/ws/${[course, exercise, owner].map(encodeURIComponent).join('/')}`;
}

export interface OpenedWorkspace {
    workspace: Workspace;
    course: Course;
    exercise: Exercise;
    spec: ReleasedExercise;
    owner: User;
    /** the sender is an instructor looking at someone else's workspace: reads only */
    viewer: boolean;
    /** this workspace's route prefix */
    prefix: string;
}

/**
 * The workspace of the route's `course`, `exercise` and `owner`, opened (with the starter on
 * first use) for the sender: 403 when it is not theirs and they are no instructor, 404 when the
 * course, the released exercise, the owner or the owner's enrollment does not exist.
 */
export async function openWorkspaceFor(store: LabStore, auth: Authenticated, params: Record<string, string>): Promise<OpenedWorkspace> {
    const courseName = params['course'] ?? '';
    const exerciseName = params['exercise'] ?? '';
    const ownerLogin = params['owner'] ?? '';
    const own = auth.user.login === ownerLogin;
    if (!own && auth.user.role !== 'instructor') throw new HttpError(403, 'a student may open only their own workspaces');
    const course = await store.findCourse(courseName);
    if (!course) throw new HttpError(404, `there is no course ${JSON.stringify(courseName)}`);
    const exercise = await store.findExercise(course.id, exerciseName);
    if (!exercise?.releasedAt)
        throw new HttpError(404, `the course ${course.name} has no released exercise ${JSON.stringify(exerciseName)}`);
    const owner = own ? auth.user : await store.findUserByLogin(ownerLogin);
    const enrolled = owner && (await store.listEnrolled(course.id)).some((u) => u.id === owner.id);
    if (!owner || !enrolled) throw new HttpError(404, `${JSON.stringify(ownerLogin)} is not enrolled in the course ${course.name}`);
    let workspace: Workspace;
    let spec: ReleasedExercise;
    try {
        workspace = await openExerciseWorkspace(store, exercise, owner.id, auth.user.id);
        spec = specOf(exercise);
    } catch (e) {
        if (e instanceof ExerciseError) throw new HttpError(409, e.message);
        throw e;
    }
    return {
        workspace,
        course,
        exercise,
        spec,
        owner,
        viewer: !own,
        prefix: workspacePrefix(course.name, exercise.name, owner.login),
    };
}

/** 403 for an instructor's write into a student's workspace. */
export function requireOwner(opened: OpenedWorkspace, what: string): void {
    if (opened.viewer)
        throw new HttpError(
            403,
            `an instructor sees ${opened.owner.login}'s workspace read-only and cannot ${what} (only POST ${opened.prefix}/reset changes it)`,
        );
}

/** 403 for a platform the exercise does not offer. */
export function requirePlatform(opened: OpenedWorkspace, platform: string): void {
    if (!opened.spec.platforms.includes(platform))
        throw new HttpError(
            403,
            `the exercise ${opened.exercise.name} offers the platforms ${opened.spec.platforms.join(', ')}, not ${platform}`,
        );
}
