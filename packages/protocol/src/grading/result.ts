/** The grade of one submission: what `@maa/grading` returns and the lab stores and shows. */
import { Type, type Static } from '@sinclair/typebox';

/** A model element feedback links to: its qualified name, its file (model-root relative) and line (1-based). */
export const FeedbackElement = Type.Object(
    {
        qualifiedName: Type.String(),
        file: Type.String(),
        line: Type.Integer({ minimum: 1 }),
    },
    { title: 'FeedbackElement', additionalProperties: false },
);
export type FeedbackElement = Static<typeof FeedbackElement>;

export const FeedbackSeverity = Type.Union([Type.Literal('error'), Type.Literal('warning'), Type.Literal('info')]);
export type FeedbackSeverity = Static<typeof FeedbackSeverity>;

/** One sentence of feedback a student understands, with where it applies. */
export const Feedback = Type.Object(
    {
        severity: FeedbackSeverity,
        text: Type.String(),
        element: Type.Optional(FeedbackElement),
        /** The scenario's id (scenarios criterion). */
        scenario: Type.Optional(Type.String()),
        /** Simulated seconds (scenarios criterion). */
        simTime: Type.Optional(Type.Number()),
        /** The automaton's state at that time. */
        state: Type.Optional(Type.String()),
    },
    { title: 'Feedback', additionalProperties: false },
);
export type Feedback = Static<typeof Feedback>;

export const CriterionGrade = Type.Object(
    {
        id: Type.String(),
        title: Type.String(),
        kind: Type.Union(['structure', 'diagnostics', 'tests', 'scenarios', 'coverage'].map((k) => Type.Literal(k))),
        /** Points reached (0 ≤ score ≤ max). */
        score: Type.Number({ minimum: 0 }),
        /** The criterion's weight. */
        max: Type.Number({ minimum: 0 }),
        feedback: Type.Array(Feedback),
    },
    { title: 'CriterionGrade', additionalProperties: false },
);
export type CriterionGrade = Static<typeof CriterionGrade>;

export const GradeRecording = Type.Object(
    {
        /** The scenario's id. */
        scenario: Type.String(),
        /** Absolute path of the `.mcap` file in the work dir. */
        file: Type.String(),
    },
    { title: 'GradeRecording', additionalProperties: false },
);
export type GradeRecording = Static<typeof GradeRecording>;

export const TaskStatus = Type.Union(['ok', 'failed', 'timeout', 'killed', 'error'].map((k) => Type.Literal(k)));
export type TaskStatus = Static<typeof TaskStatus>;

/** A task of the submission as the driver reported it (or `error` when the driver never ran it). */
export const GradeTask = Type.Object(
    {
        id: Type.String(),
        status: TaskStatus,
        seconds: Type.Number({ minimum: 0 }),
        message: Type.Optional(Type.String()),
    },
    { title: 'GradeTask', additionalProperties: false },
);
export type GradeTask = Static<typeof GradeTask>;

export const SubmissionGrade = Type.Object(
    {
        /** The submission's id (as given to gradeSubmissions). */
        submission: Type.String(),
        score: Type.Number({ minimum: 0 }),
        maxScore: Type.Number({ minimum: 0 }),
        criteria: Type.Array(CriterionGrade),
        recordings: Type.Array(GradeRecording),
        tasks: Type.Array(GradeTask),
    },
    {
        $id: 'urn:maa:protocol:submission-grade',
        title: 'SubmissionGrade',
        description: 'the grade of one submission: score, per-criterion scores and feedback, recordings, tasks',
        additionalProperties: false,
    },
);
export type SubmissionGrade = Static<typeof SubmissionGrade>;
