// The grading routes (docs/lab.md "Grading"), behind the lab's session, role, CSRF and Host/Origin
// checks: a student submits their workspace and reads their own grade; an instructor grades
// every student's latest submission, follows the run, reads everyone's results, exports them as
// CSV; a recording downloads for the instructor or the student it belongs to (403/404 else).
import { createReadStream } from 'node:fs';
import { stat } from 'node:fs/promises';
import { HttpError, sendJson } from '@maa/ide-server/http';
import { csvField } from '../dashboard/csv.js';
import type { AuthedRequest, LabRoutes } from '../http/routes.js';
import type { Course, Exercise, GradingResult, LabStore, User } from '../storage/index.js';
import { openWorkspaceFor, requireOwner, WS_PREFIX } from '../workspaces/resolve.js';
import { recordingFile } from './files.js';
import { GradingBusy, type GradingService, GradingUnavailable } from './service.js';
import { gradingBase, resultView, runView } from './views.js';

const EXERCISE_PREFIX = '/api/courses/:course/exercises/:exercise/grading';

/** The course and released exercise of the route; a student must be enrolled in the course (404 else, as for a missing one). */
async function courseExercise(
    store: LabStore,
    params: Record<string, string>,
    user: User,
): Promise<{ course: Course; exercise: Exercise }> {
    const course = await store.findCourse(params['course'] ?? '');
    const enrolled = course && (user.role === 'instructor' || (await store.listEnrolled(course.id)).some((u) => u.id === user.id));
    if (!course || !enrolled) throw new HttpError(404, `there is no course ${JSON.stringify(params['course'])}`);
    const exercise = await store.findExercise(course.id, params['exercise'] ?? '');
    if (!exercise?.releasedAt)
        throw new HttpError(404, `the course ${course.name} has no released exercise ${JSON.stringify(params['exercise'])}`);
    return { course, exercise };
}

/** The criteria of the exercise's grading (id, title, weight), or null when it has none. */
async function criteriaOf(store: LabStore, exercise: Exercise) {
    const grading = await store.exerciseGrading(exercise.id);
    const criteria = grading?.spec['criteria'];
    if (!Array.isArray(criteria)) return null;
    return (criteria as Array<{ id: string; title: string; kind: string; weight: number }>).map(({ id, title, kind, weight }) => ({
        id,
        title,
        kind,
        weight,
    }));
}

async function resultViews(store: LabStore, results: GradingResult[]) {
    const views = [];
    for (const result of results) {
        const user = await store.findUserById(result.userId);
        if (user) views.push(resultView(result, user));
    }
    return views.sort((a, b) => (a.student.login < b.student.login ? -1 : 1));
}

function asStarted<T>(work: () => Promise<T>): Promise<T> {
    return work().catch((e: unknown) => {
        if (e instanceof GradingUnavailable || e instanceof GradingBusy) throw new HttpError(409, e.message);
        throw e;
    });
}

export function addGradingRoutes(routes: LabRoutes, grading: GradingService, dataDir: string): void {
    // The student's submit: a submission of the workspace as it is, graded; the answer names the run.
    routes.add({
        method: 'POST',
        path: `${WS_PREFIX}/grading/submit`,
        access: 'user',
        handler: async ({ res, store, auth, params }) => {
            const opened = await openWorkspaceFor(store, auth, params);
            requireOwner(opened, 'submit it for grading');
            const { run, submission } = await asStarted(() => grading.submit(opened.exercise, opened.workspace, auth.user));
            sendJson(res, 202, { run: runView(run, gradingBase(opened.course.name, opened.exercise.name)), submission: submission.id });
        },
    });
    // The workspace's grading as the IDE shows it: whether the exercise is graded, the owner's newest grade and run.
    routes.add({
        method: 'GET',
        path: `${WS_PREFIX}/grading`,
        access: 'user',
        handler: async ({ res, store, auth, params }) => {
            const opened = await openWorkspaceFor(store, auth, params);
            const base = gradingBase(opened.course.name, opened.exercise.name);
            const [latest] = await store.latestGradingResults(opened.exercise.id, opened.owner.id);
            const run = (await store.listGradingRuns(opened.exercise.id, 50)).find(
                (r) => r.kind === 'submission' && r.requestedBy === opened.owner.id,
            );
            sendJson(res, 200, {
                graded: (await criteriaOf(store, opened.exercise)) !== null,
                latest: latest ? resultView(latest, opened.owner) : null,
                run: run ? runView(run, base) : null,
            });
        },
    });
    addExerciseRoutes(routes, grading);
    addRecordingRoute(routes, dataDir);
}

function addExerciseRoutes(routes: LabRoutes, grading: GradingService): void {
    // Grade every student's latest submission (instructors).
    routes.add({
        method: 'POST',
        path: `${EXERCISE_PREFIX}/runs`,
        access: 'instructor',
        handler: async ({ res, store, auth, params }) => {
            const { course, exercise } = await courseExercise(store, params, auth.user);
            const run = await asStarted(() => grading.gradeCourse(exercise, auth.user));
            sendJson(res, 202, { run: runView(run, gradingBase(course.name, exercise.name)) });
        },
    });
    // A run's status and progress: instructors any run, a student the runs of their own submissions.
    routes.add({
        method: 'GET',
        path: `${EXERCISE_PREFIX}/runs/:run`,
        access: 'user',
        handler: async ({ res, store, auth, params }) => {
            const { course, exercise } = await courseExercise(store, params, auth.user);
            const id = Number(params['run']);
            const run = Number.isSafeInteger(id) ? await store.findGradingRun(id) : undefined;
            if (!run || run.exerciseId !== exercise.id)
                throw new HttpError(404, `the exercise ${exercise.name} has no grading run ${params['run']}`);
            if (auth.user.role !== 'instructor' && (run.kind !== 'submission' || run.requestedBy !== auth.user.id))
                throw new HttpError(403, 'a student may follow only the gradings of their own submissions');
            sendJson(res, 200, { run: runView(run, gradingBase(course.name, exercise.name)) });
        },
    });
    // The results: an instructor everyone's newest, a student their own.
    routes.add({
        method: 'GET',
        path: EXERCISE_PREFIX,
        access: 'user',
        handler: (r) => sendResults(r, false),
    });
    routes.add({
        method: 'GET',
        path: `${EXERCISE_PREFIX}/results.csv`,
        access: 'instructor',
        handler: (r) => sendResults(r, true),
    });
}

async function sendResults({ res, store, auth, params }: AuthedRequest, csv: boolean): Promise<void> {
    const { course, exercise } = await courseExercise(store, params, auth.user);
    const instructor = auth.user.role === 'instructor';
    const criteria = await criteriaOf(store, exercise);
    const results = await resultViews(store, await store.latestGradingResults(exercise.id, instructor ? undefined : auth.user.id));
    if (csv) {
        const ids = (criteria ?? []).map((c) => c.id);
        const lines = [['login', 'name', 'submission', 'graded_at', ...ids, 'score', 'max_score'].join(',')];
        for (const r of results) {
            const scores = ids.map((id) => r.criteria.find((c) => c.id === id)?.score ?? null);
            lines.push([r.student.login, r.student.name, r.submission, r.gradedAt, ...scores, r.score, r.maxScore].map(csvField).join(','));
        }
        const text = `${lines.join('\r\n')}\r\n`;
        const file = `${course.name}-${exercise.name}-grades.csv`.replace(/[^A-Za-z0-9._-]/g, '_');
        res.writeHead(200, {
            'Content-Type': 'text/csv; charset=utf-8',
            'Content-Disposition': `attachment; filename="${file}"`,
            'Cache-Control': 'no-store',
            'Content-Length': Buffer.byteLength(text),
        });
        res.end(text);
        return;
    }
    const base = gradingBase(course.name, exercise.name);
    const runs = instructor ? (await store.listGradingRuns(exercise.id, 10)).map((r) => runView(r, base)) : [];
    sendJson(res, 200, {
        course: course.name,
        exercise: exercise.name,
        criteria,
        results,
        runs,
        csv: instructor ? `${base}/results.csv` : null,
    });
}

function addRecordingRoute(routes: LabRoutes, dataDir: string): void {
    routes.add({
        method: 'GET',
        path: '/api/grading/results/:result/recordings/:file',
        access: 'user',
        handler: async ({ res, store, auth, params }) => {
            const id = Number(params['result']);
            const result = Number.isSafeInteger(id) && id > 0 ? await store.findGradingResult(id) : undefined;
            if (!result) throw new HttpError(404, `there is no grading result ${params['result']}`);
            if (auth.user.role !== 'instructor' && result.userId !== auth.user.id)
                throw new HttpError(403, 'a student may download only the recordings of their own gradings');
            const name = (params['file'] ?? '').replace(/\.mcap$/, '');
            const recording = result.recordings.find((r) => r.scenario === name);
            const file = recording && recordingFile(dataDir, recording);
            const size = file && (await stat(file).catch(() => undefined))?.size;
            if (!file || size === undefined)
                throw new HttpError(404, `the grading result ${id} has no recording ${JSON.stringify(params['file'])}`);
            const download = `${name.replace(/[^A-Za-z0-9_-]/g, '_')}-${id}.mcap`;
            res.writeHead(200, {
                'Content-Type': 'application/octet-stream',
                'Content-Disposition': `attachment; filename="${download}"`,
                'Content-Length': size,
                'Cache-Control': 'no-store',
                'X-Content-Type-Options': 'nosniff',
            });
            await new Promise<void>((resolve, reject) => {
                createReadStream(file).on('error', reject).pipe(res).on('finish', resolve).on('error', reject);
            });
        },
    });
}
