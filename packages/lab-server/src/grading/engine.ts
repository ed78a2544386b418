// The grading engine the lab calls: @maa/grading's gradeSubmissions (docs/lab.md "Grading"). The
// service takes any function of this shape (the tests of the routes give a small one of their
// own); the default loads @maa/grading on first use.
import type { GradingSpec, SubmissionGrade } from '../exercises/grading-spec.js';

/** One submission as the engine grades it: a model root on disk and its application file. */
export interface EngineSubmission {
    id: string;
    /** the materialized model root (absolute) */
    root: string;
    /** the `.arcapp` (absolute, inside root) */
    appFile: string;
}

export interface EngineOptions {
    spec: GradingSpec;
    /** the folder of grading.json and the hidden files */
    gradingDir: string;
    submissions: EngineSubmission[];
    workDir: string;
    /** the sim-server venv's interpreter (the engine's default when absent) */
    python?: string;
    /** a Ray cluster (RAY_ADDRESS); local Ray when absent */
    rayAddress?: string;
    /** progress events (the driver's lines or the engine's own; see progressOf) */
    onProgress?: (event: unknown) => void;
    signal?: AbortSignal;
}

export type GradeEngine = (options: EngineOptions) => Promise<SubmissionGrade[]>;

/** @maa/grading's gradeSubmissions, loaded on first use (the language services load with it, so not at the lab's start). */
export const defaultEngine: GradeEngine = async (options) => {
    const { gradeSubmissions } = await import('@maa/grading');
    return gradeSubmissions(options);
};

/** Progress as the run stores it. */
export interface Progress {
    done: number;
    total: number;
}

/**
 * The run's progress after an engine event: an event with numeric `done` and `total` says it;
 * the driver's `started` line gives the task count, each `task` line one more done (@maa/grading
 * forwards them as `{kind: 'driver', line}`). Anything else leaves the progress as it was.
 */
export function progressOf(event: unknown, before: Progress): Progress {
    if (typeof event !== 'object' || event === null) return before;
    const e = event as Record<string, unknown>;
    if (e['kind'] === 'driver') return progressOf(e['line'], before);
    if (typeof e['done'] === 'number' && typeof e['total'] === 'number') return { done: e['done'], total: e['total'] };
    if (e['event'] === 'started' && typeof e['tasks'] === 'number') return { done: 0, total: e['tasks'] };
    if (e['event'] === 'task') {
        const done = before.done + 1;
        return { done, total: Math.max(before.total, done) };
    }
    return before;
}
