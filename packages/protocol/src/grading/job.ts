/**
 * A grade job (`maa-grade-job/1`): the tasks `@maa/grading` hands the Python driver
 * (`python -m maa_sim.grading run --job JOB.json --out OUTDIR`), and the JSON lines the driver
 * prints on stdout (one object per line: started, task, finished).
 */
import { Type, type Static } from '@sinclair/typebox';
import { GRADE_JOB_FORMAT } from './formats.js';
import { TaskStatus } from './result.js';
import { TaskLimits } from './spec.js';

export const GradeJobTask = Type.Object(
    {
        /** Unique in the job; the task's outputs land in `OUTDIR/<id>/`. */
        id: Type.String({ pattern: '^[A-Za-z0-9][A-Za-z0-9._-]*$', errorMessage: 'a task id is letters, digits, ., _ and -' }),
        /** Absolute directory bundled into the task (read-only in the sandbox, `{input}`). */
        input: Type.String({ pattern: '^/', errorMessage: 'input must be an absolute directory' }),
        /** The command; `{python}`, `{input}` and `{output}` are resolved on the worker. */
        argv: Type.Array(Type.String(), { minItems: 1, errorMessage: 'argv must be a non-empty list of strings' }),
        limits: TaskLimits,
        /** Extra environment of the command (placeholders resolved too). */
        env: Type.Record(Type.String(), Type.String(), { errorMessage: 'env must map names to strings' }),
    },
    { title: 'GradeJobTask', additionalProperties: false, errorMessage: 'a task has id, input, argv, limits, env' },
);
export type GradeJobTask = Static<typeof GradeJobTask>;

export const GradeJob = Type.Object(
    {
        format: Type.Literal(GRADE_JOB_FORMAT, { errorMessage: `format must be '${GRADE_JOB_FORMAT}'` }),
        tasks: Type.Array(GradeJobTask, { errorMessage: 'tasks must be a list of tasks' }),
    },
    {
        $id: 'urn:maa:protocol:grade-job',
        title: 'GradeJob',
        description: 'a grade job: the tasks the grading driver runs (docs/lab.md "Grading")',
        additionalProperties: false,
        errorMessage: 'expected an object with format and tasks',
    },
);
export type GradeJob = Static<typeof GradeJob>;

export const DriverStarted = Type.Object(
    {
        event: Type.Literal('started'),
        tasks: Type.Integer({ minimum: 0 }),
        mode: Type.Union([Type.Literal('local'), Type.Literal('cluster')]),
        address: Type.Union([Type.String(), Type.Null()]),
        nodes: Type.Integer({ minimum: 0 }),
        cpus: Type.Number({ minimum: 0 }),
    },
    { title: 'DriverStarted', additionalProperties: false },
);
export type DriverStarted = Static<typeof DriverStarted>;

/** A finished task (also written as `OUTDIR/<id>/result.json`). */
export const DriverTask = Type.Object(
    {
        event: Type.Literal('task'),
        id: Type.String(),
        status: TaskStatus,
        exitCode: Type.Union([Type.Integer(), Type.Null()]),
        signal: Type.Union([Type.Integer(), Type.Null()]),
        seconds: Type.Number({ minimum: 0 }),
        node: Type.String(),
        /** Why, in words (`exited with 0`, `killed: wall time limit (120 s)`). */
        message: Type.String(),
    },
    { title: 'DriverTask', additionalProperties: false },
);
export type DriverTask = Static<typeof DriverTask>;

export const DriverFinished = Type.Object(
    {
        event: Type.Literal('finished'),
        wallSeconds: Type.Number({ minimum: 0 }),
        /** Tasks by status. */
        counts: Type.Record(Type.String(), Type.Integer({ minimum: 0 })),
    },
    { title: 'DriverFinished', additionalProperties: false },
);
export type DriverFinished = Static<typeof DriverFinished>;

export const DriverLine = Type.Union([DriverStarted, DriverTask, DriverFinished], {
    $id: 'urn:maa:protocol:grade-driver-line',
    title: 'DriverLine',
    description: 'one JSON line the grading driver prints on stdout',
});
export type DriverLine = Static<typeof DriverLine>;
