// What the instructor's dashboard shows (docs/lab.md "The instructor's dashboard"): the course's
// students × its exercises, per cell the diagnostics of the workspace's current files, the latest
// stream tests, the latest simulation's goal, the last activity and whether it simulates now.
import { HttpError } from '@maa/ide-server/http';
import type { LabStore, User, WorkspaceSummary } from '../storage/index.js';
import type { CheckState, WorkspaceChecker } from './checker.js';

/** Which workspaces simulate right now (the lab's running simulations). */
export interface LiveSimulations {
    isSimulating(workspaceId: number): boolean;
}

export interface DashboardExercise {
    name: string;
    title: string;
    released: boolean;
}

export interface DashboardStudent {
    login: string;
    name: string;
}

export interface DashboardCell {
    student: string;
    exercise: string;
    /** the workspace's route prefix (`/api/ws/<course>/<exercise>/<login>`); null: no workspace yet */
    workspace: string | null;
    /** errors and warnings in the current files (while `checking`: in the files last checked); null: no workspace or not checked yet */
    diagnostics: { errors: number; warnings: number } | null;
    /** the current files are being checked (the next poll brings their diagnostics) */
    checking: boolean;
    /** the check of the current files failed (e.g. the checker crashed); the next poll checks again */
    checkError: string | null;
    /** the latest stream test run; null: none yet */
    tests: { passed: number; total: number; at: string } | null;
    /** the latest simulation's goal; null: none yet */
    simulation: { goalReached: boolean; at: string } | null;
    /** the latest save, delete or restore (ISO); null: none */
    lastActivity: string | null;
    simulating: boolean;
}

export interface Dashboard {
    course: { name: string; title: string };
    exercises: DashboardExercise[];
    students: DashboardStudent[];
    /** one per student × exercise, students by login, then exercises in the course's order */
    cells: DashboardCell[];
}

export interface DashboardSources {
    store: LabStore;
    checker: WorkspaceChecker;
    live: LiveSimulations;
}

/**
 * The dashboard of the course (404 when there is no such course). Diagnostics still being checked
 * are `checking` (the answer does not wait for them) unless `complete` (the CSV export) waits.
 */
export async function buildDashboard(sources: DashboardSources, courseName: string, complete = false): Promise<Dashboard> {
    const { store } = sources;
    const course = await store.findCourse(courseName);
    if (!course) throw new HttpError(404, `there is no course ${JSON.stringify(courseName)}`);
    const students = (await store.listEnrolled(course.id)).filter((u) => u.role === 'student').sort(byLogin);
    const exercises = await store.listExercises(course.id);
    const cells: DashboardCell[] = [];
    const byExercise = await Promise.all(
        exercises.map(async (e) => new Map((await store.listWorkspaces(e.id)).map((w) => [w.ownerId, w] as const))),
    );
    // Every changed workspace of the students queued for the checker thread.
    const studentIds = new Set(students.map((s) => s.id));
    const workspaceIds = byExercise.flatMap((m) => [...m.values()].filter((w) => studentIds.has(w.ownerId)).map((w) => w.id));
    const checks = complete ? await sources.checker.completeStates(workspaceIds) : await sources.checker.states(workspaceIds);
    for (const student of students) {
        for (const [i, exercise] of exercises.entries()) {
            const workspace = byExercise[i]?.get(student.id);
            const cell: DashboardCell = {
                student: student.login,
                exercise: exercise.name,
                workspace: null,
                diagnostics: null,
                checking: false,
                checkError: null,
                tests: null,
                simulation: null,
                lastActivity: null,
                simulating: false,
            };
            if (workspace) await fillCell(sources, cell, workspace, checks.get(workspace.id), course.name);
            cells.push(cell);
        }
    }
    return {
        course: { name: course.name, title: course.title },
        exercises: exercises.map((e) => ({ name: e.name, title: titleOf(e.spec) ?? e.name, released: e.releasedAt !== null })),
        students: students.map((s) => ({ login: s.login, name: s.name })),
        cells,
    };
}

async function fillCell(
    { store, live }: DashboardSources,
    cell: DashboardCell,
    workspace: WorkspaceSummary,
    state: CheckState | undefined,
    course: string,
): Promise<void> {
    cell.workspace = `/api/ws/${[course, cell.exercise, cell.student].map(encodeURIComponent).join('/')}`;
    const [tests, sim] = await Promise.all([store.latestTestResult(workspace.id), store.latestSimulationResult(workspace.id)]);
    const check = state?.check;
    if (check) cell.diagnostics = { errors: check.errors, warnings: check.warnings };
    cell.checking = state?.checking ?? true;
    cell.checkError = state?.error ?? null;
    if (tests) cell.tests = { passed: tests.passed, total: tests.passed + tests.failed + tests.skipped, at: tests.createdAt.toISOString() };
    if (sim) cell.simulation = { goalReached: sim.goalReached, at: sim.createdAt.toISOString() };
    cell.lastActivity = workspace.lastActivity?.toISOString() ?? null;
    cell.simulating = live.isSimulating(workspace.id);
}

function byLogin(a: User, b: User): number {
    return a.login < b.login ? -1 : a.login > b.login ? 1 : 0;
}

function titleOf(spec: Record<string, unknown>): string | undefined {
    return typeof spec['title'] === 'string' ? spec['title'] : undefined;
}

/** No live simulations (a lab server without workspaces, or tests). */
export const NO_LIVE_SIMULATIONS: LiveSimulations = { isSimulating: () => false };
