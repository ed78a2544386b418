// What the grading routes answer: a run's status and progress, a result with its criteria and
// feedback, and the recordings' download links (never a path of the server's folders).
import type { GradingResult, GradingRun, User } from '../storage/index.js';

export interface RunView {
    id: number;
    kind: GradingRun['kind'];
    status: GradingRun['status'];
    done: number;
    total: number;
    error: string | null;
    createdAt: string;
    startedAt: string | null;
    finishedAt: string | null;
    /** `GET` this for the run's progress */
    url: string;
}

export interface CriterionView {
    id: string;
    title: string;
    kind: string;
    score: number;
    max: number;
    feedback: unknown[];
}

export interface ResultView {
    id: number;
    run: number;
    submission: number;
    student: { login: string; name: string };
    score: number;
    maxScore: number;
    criteria: CriterionView[];
    tasks: unknown[];
    recordings: Array<{ scenario: string; url: string }>;
    gradedAt: string;
}

/** `/api/courses/<course>/exercises/<exercise>/grading` */
export function gradingBase(course: string, exercise: string): string {
    return `/api/courses/${encodeURIComponent(course)}/exercises/${encodeURIComponent(exercise)}/grading`;
}

/** The download route of one recording. */
export function recordingUrl(resultId: number, scenario: string): string {
    return `/api/grading/results/${resultId}/recordings/${encodeURIComponent(scenario)}.mcap`;
}

export function runView(run: GradingRun, base: string): RunView {
    return {
        id: run.id,
        kind: run.kind,
        status: run.status,
        done: run.done,
        total: run.total,
        error: run.error,
        createdAt: run.createdAt.toISOString(),
        startedAt: run.startedAt?.toISOString() ?? null,
        finishedAt: run.finishedAt?.toISOString() ?? null,
        url: `${base}/runs/${run.id}`,
    };
}

function criteriaOf(grade: Record<string, unknown>): CriterionView[] {
    const criteria = grade['criteria'];
    return Array.isArray(criteria) ? (criteria as CriterionView[]) : [];
}

export function resultView(result: GradingResult, student: Pick<User, 'login' | 'name'>): ResultView {
    const tasks = result.grade['tasks'];
    return {
        id: result.id,
        run: result.runId,
        submission: result.submissionId,
        student: { login: student.login, name: student.name },
        score: result.score,
        maxScore: result.maxScore,
        criteria: criteriaOf(result.grade),
        tasks: Array.isArray(tasks) ? tasks : [],
        recordings: result.recordings.map((r) => ({ scenario: r.scenario, url: recordingUrl(result.id, r.scenario) })),
        gradedAt: result.createdAt.toISOString(),
    };
}
