// The tables of the lab's database as Kysely sees them (the migrations in ./migrations create
// them). Only src/storage uses these types; the rest of the lab server goes through LabStore.
import type { ColumnType, Generated, JSONColumnType } from 'kysely';

/** A column the database fills on insert (`DEFAULT now()`), read back as a Date. */
type CreatedAt = ColumnType<Date, Date | undefined, never>;

export type Role = 'instructor' | 'student';

export interface UsersTable {
    id: Generated<number>;
    login: string;
    email: string | null;
    name: string;
    role: Role;
    password_hash: string | null;
    oidc_issuer: string | null;
    oidc_subject: string | null;
    created_at: CreatedAt;
}

export interface CoursesTable {
    id: Generated<number>;
    name: string;
    title: string;
    created_at: CreatedAt;
}

export interface EnrollmentsTable {
    course_id: number;
    user_id: number;
    created_at: CreatedAt;
}

export interface ExercisesTable {
    id: Generated<number>;
    course_id: number;
    name: string;
    released_at: Date | null;
    spec: JSONColumnType<Record<string, unknown>, string, string>;
    created_at: CreatedAt;
}

export interface WorkspacesTable {
    id: Generated<number>;
    owner_id: number;
    exercise_id: number;
    created_at: CreatedAt;
}

export interface FileRevisionsTable {
    id: Generated<number>;
    workspace_id: number;
    path: string;
    revision: number;
    /** null: the file was deleted in this revision. */
    content: string | null;
    author_id: number;
    /** the revision this one restored, if it is a restore */
    restored_from: number | null;
    created_at: CreatedAt;
}

export interface SubmissionsTable {
    id: Generated<number>;
    workspace_id: number;
    submitted_by: number;
    /** path → revision of every file at the time of the submission */
    files: JSONColumnType<Record<string, number>, string, never>;
    created_at: CreatedAt;
}

export interface TestResultsTable {
    id: Generated<number>;
    workspace_id: number;
    submission_id: number | null;
    passed: number;
    failed: number;
    skipped: number;
    details: ColumnType<unknown, string, never>;
    created_at: CreatedAt;
}

export interface SimulationResultsTable {
    id: Generated<number>;
    workspace_id: number;
    submission_id: number | null;
    goal_reached: boolean;
    simulated_seconds: number;
    details: ColumnType<unknown, string, never>;
    created_at: CreatedAt;
}

export interface SessionsTable {
    /** a hash of the session token (the token itself is only in the cookie) */
    id: string;
    user_id: number;
    csrf_secret: string;
    created_at: CreatedAt;
    expires_at: Date;
}

/** One-time invitation links (migration 0002). */
export interface InvitationsTable {
    /** a hash of the link's token (the token itself is only in the link) */
    id: string;
    user_id: number;
    created_at: CreatedAt;
    expires_at: Date;
    /** when the link was used (a used link is refused) */
    used_at: Date | null;
}

/** Every version of an exercise's starter files (migration 0003). */
export interface StarterVersionsTable {
    exercise_id: number;
    version: number;
    /** path → content */
    files: JSONColumnType<Record<string, string>, string, string>;
    created_at: CreatedAt;
}

/** Per workspace file from a starter: the starter version it was last merged with (migration 0003). */
export interface StarterFilesTable {
    workspace_id: number;
    path: string;
    base_version: number;
    /** a newer starter version that could not be merged into the file (null: none) */
    conflict_version: number | null;
    updated_at: Date;
}

/** An exercise's grading specification and hidden files as released (migration 0004). */
export interface ExerciseGradingsTable {
    exercise_id: number;
    /** grading.json (maa-grading/1) */
    spec: JSONColumnType<Record<string, unknown>, string, string>;
    /** the hidden files it names: path (relative to the grading folder) → content */
    files: JSONColumnType<Record<string, string>, string, string>;
    updated_at: Date;
}

export type GradingRunKind = 'submission' | 'course';
export type GradingRunStatus = 'queued' | 'running' | 'done' | 'failed';

/** One grading run: a student's submission or every student's latest of an exercise (migration 0004). */
export interface GradingRunsTable {
    id: Generated<number>;
    exercise_id: number;
    kind: GradingRunKind;
    requested_by: number;
    status: GradingRunStatus;
    done: ColumnType<number, number | undefined, number>;
    total: ColumnType<number, number | undefined, number>;
    error: string | null;
    created_at: CreatedAt;
    started_at: Date | null;
    finished_at: Date | null;
}

/** One graded submission of a run (migration 0004). */
export interface GradingResultsTable {
    id: Generated<number>;
    run_id: number;
    submission_id: number;
    user_id: number;
    score: number;
    max_score: number;
    /** the SubmissionGrade of @maa/protocol/grading (its recordings' paths as the engine gave them) */
    criteria: JSONColumnType<Record<string, unknown>, string, string>;
    /** scenario → the recording's path relative to the data directory */
    recordings: JSONColumnType<Array<{ scenario: string; path: string }>, string, string>;
    created_at: CreatedAt;
}

export interface Database {
    users: UsersTable;
    courses: CoursesTable;
    enrollments: EnrollmentsTable;
    exercises: ExercisesTable;
    workspaces: WorkspacesTable;
    file_revisions: FileRevisionsTable;
    submissions: SubmissionsTable;
    test_results: TestResultsTable;
    simulation_results: SimulationResultsTable;
    sessions: SessionsTable;
    starter_versions: StarterVersionsTable;
    starter_files: StarterFilesTable;
    invitations: InvitationsTable;
    exercise_gradings: ExerciseGradingsTable;
    grading_runs: GradingRunsTable;
    grading_results: GradingResultsTable;
}
