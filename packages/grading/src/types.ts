/** The options and progress events of {@link gradeSubmissions}. */
import type { DriverLine, GradingSpec } from '@maa/protocol/grading';

export interface Submission {
    /** The submission's id (a student, a variant): `SubmissionGrade.submission`. */
    readonly id: string;
    /** The materialized model root (absolute folder). */
    readonly root: string;
    /** Its application configuration (`.arcapp`), absolute or relative to `root`. */
    readonly appFile: string;
}

export interface GradeOptions {
    /** The grading specification (default: `loadGradingSpec(gradingDir)`). */
    readonly spec?: GradingSpec;
    /** The folder of grading.json and the hidden `.stream` files it names. */
    readonly gradingDir: string;
    readonly submissions: readonly Submission[];
    /** Where builds, task inputs, the job file and the task outputs (recordings) go; owned by this call. */
    readonly workDir: string;
    /** The Python of the grading driver (default: {@link gradingPython}: $MAA_GRADING_PYTHON, the clone's sim-server venv, else the launcher's cached venv with Ray, installed on first use). */
    readonly python?: string;
    /** A Ray cluster (RAY_ADDRESS); local Ray when absent. */
    readonly rayAddress?: string;
    /** More environment of the driver (a cluster's RAY_AUTH_MODE and RAY_AUTH_TOKEN), over this process's. */
    readonly env?: Readonly<Record<string, string>>;
    readonly onProgress?: (event: GradeProgress) => void;
    /** Stops grading: the driver and its tasks are killed and the call rejects with the signal's reason. */
    readonly signal?: AbortSignal;
}

/** What gradeSubmissions is doing: a submission's step, a line of the driver (a task finished), a submission graded. */
export type GradeProgress =
    | { readonly kind: 'submission'; readonly submission: string; readonly step: 'check' | 'generate' | 'plan'; readonly message: string }
    | { readonly kind: 'driver'; readonly line: DriverLine; readonly submission?: string }
    | { readonly kind: 'graded'; readonly submission: string; readonly score: number; readonly maxScore: number };
