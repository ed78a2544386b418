// The records and the typed API of the lab's storage (LabStore). The rest of the lab server uses
// only this; the SQL is in store.ts and the schema in ./migrations.
import type { GradingRunKind, GradingRunStatus, Role } from './schema.js';

export type { GradingRunKind, GradingRunStatus, Role };

export interface User {
    id: number;
    login: string;
    email: string | null;
    name: string;
    role: Role;
    passwordHash: string | null;
    oidcIssuer: string | null;
    oidcSubject: string | null;
    createdAt: Date;
}

export interface NewUser {
    login: string;
    name: string;
    role: Role;
    email?: string | null;
    passwordHash?: string | null;
    /** OpenID Connect: the issuer and the subject (both or neither) */
    oidcIssuer?: string | null;
    oidcSubject?: string | null;
}

/** A released exercise of a course (LabStore.listReleasedExercises). */
export interface EnrolledExercise {
    course: string;
    courseTitle: string;
    exercise: string;
    /** the exercise's title (its name when it has none) */
    title: string;
}

export interface Course {
    id: number;
    name: string;
    title: string;
    createdAt: Date;
}

export interface Exercise {
    id: number;
    courseId: number;
    name: string;
    releasedAt: Date | null;
    /** exercise.json as the instructor released it */
    spec: Record<string, unknown>;
    createdAt: Date;
}

/** One version of an exercise's starter files (1 at the release, +1 at each update that changed them). */
export interface StarterVersion {
    exerciseId: number;
    version: number;
    /** path → content */
    files: Record<string, string>;
    createdAt: Date;
}

/** A workspace file that came from the starter: the starter version it was last merged with. */
export interface StarterFile {
    path: string;
    /** the base of the next three-way merge */
    baseVersion: number;
    /** a newer starter version that could not be merged into the file (null: none) */
    conflictVersion: number | null;
    updatedAt: Date;
}

/** One student's (or the instructor's) workspace for one exercise. */
export interface Workspace {
    id: number;
    ownerId: number;
    exerciseId: number;
    createdAt: Date;
}

/** One saved version of one file (every save, delete and restore makes one). */
export interface FileRevision {
    path: string;
    revision: number;
    /** null: the file was deleted in this revision */
    content: string | null;
    authorId: number;
    /** the revision whose content a restore brought back */
    restoredFrom: number | null;
    createdAt: Date;
}

/** A file's latest revision without its content (listFiles, history). */
export type FileRevisionInfo = Omit<FileRevision, 'content'> & { size: number; deleted: boolean };

/** A workspace with what the instructor's dashboard shows of it. */
export interface WorkspaceSummary extends Workspace {
    /** the latest save, delete or restore in it (null: none yet) */
    lastActivity: Date | null;
}

/** The size of a workspace's current files (the latest revision of each that is not deleted). */
export interface WorkspaceSize {
    files: number;
    bytes: number;
}

export interface Submission {
    id: number;
    workspaceId: number;
    submittedBy: number;
    /** path → revision of every file the workspace had */
    files: Record<string, number>;
    createdAt: Date;
}

export interface TestResult {
    id: number;
    workspaceId: number;
    submissionId: number | null;
    passed: number;
    failed: number;
    skipped: number;
    details: unknown;
    createdAt: Date;
}

export interface SimulationResult {
    id: number;
    workspaceId: number;
    submissionId: number | null;
    goalReached: boolean;
    simulatedSeconds: number;
    details: unknown;
    createdAt: Date;
}

export interface Session {
    /** a hash of the session token (the caller hashes; the token itself is never stored) */
    id: string;
    userId: number;
    csrfSecret: string;
    createdAt: Date;
    expiresAt: Date;
}

/** A one-time invitation link: the user sets a password once through it. */
export interface Invitation {
    /** a hash of the link's token (the caller hashes; the token itself is never stored) */
    id: string;
    userId: number;
    createdAt: Date;
    expiresAt: Date;
    usedAt: Date | null;
}

/** What redeeming an invitation did: the user whose password is now set, or why it was refused. */
export type Redemption = { ok: true; user: User } | { ok: false; reason: 'unknown' | 'used' | 'expired' };

/** One user of an import, with the invitation link made for them (the token's hash). */
export interface ImportedUser {
    user: NewUser;
    invitation?: { id: string; expiresAt: Date };
}

/** An exercise's grading: grading.json and the hidden files it names, as released (never served to students). */
export interface ExerciseGrading {
    exerciseId: number;
    /** grading.json (format maa-grading/1) */
    spec: Record<string, unknown>;
    /** path (relative to the grading folder) → content */
    files: Record<string, string>;
    updatedAt: Date;
}

export interface GradingRun {
    id: number;
    exerciseId: number;
    kind: GradingRunKind;
    requestedBy: number;
    status: GradingRunStatus;
    /** progress: the tasks (or submissions) finished of `total` */
    done: number;
    total: number;
    /** why a failed run failed */
    error: string | null;
    createdAt: Date;
    startedAt: Date | null;
    finishedAt: Date | null;
}

/** What a run's progress or end changes (undefined: unchanged). */
export interface GradingRunUpdate {
    status?: GradingRunStatus;
    done?: number;
    total?: number;
    error?: string | null;
    startedAt?: Date | null;
    finishedAt?: Date | null;
}

/** A recording of one scenario run of a graded submission: its path relative to the data directory. */
export interface GradingRecording {
    scenario: string;
    path: string;
}

export interface GradingResult {
    id: number;
    runId: number;
    submissionId: number;
    userId: number;
    score: number;
    maxScore: number;
    /** the SubmissionGrade (@maa/protocol/grading) */
    grade: Record<string, unknown>;
    recordings: GradingRecording[];
    createdAt: Date;
}

/** A submission with its workspace's owner (the student it is graded for). */
export interface OwnedSubmission extends Submission {
    ownerId: number;
}

export interface SaveFile {
    workspaceId: number;
    path: string;
    content: string;
    authorId: number;
}

export interface LabStore {
    readonly backend: 'pglite' | 'postgresql';

    createUser(user: NewUser): Promise<User>;
    findUserById(id: number): Promise<User | undefined>;
    findUserByLogin(login: string): Promise<User | undefined>;
    findUserByOidc(issuer: string, subject: string): Promise<User | undefined>;
    /** The user with this e-mail address (compared without regard to case). */
    findUserByEmail(email: string): Promise<User | undefined>;
    /** Gives a user without one their single sign-on identity (a StorageConflictError when taken or the user has one). */
    linkOidc(userId: number, issuer: string, subject: string): Promise<User>;
    setPasswordHash(userId: number, passwordHash: string | null): Promise<void>;
    listUsers(): Promise<User[]>;

    createCourse(course: { name: string; title: string }): Promise<Course>;
    findCourse(name: string): Promise<Course | undefined>;
    enroll(courseId: number, userId: number): Promise<void>;
    listEnrolled(courseId: number): Promise<User[]>;
    /** The released exercises, by course and name: of the courses `enrolledUserId` is enrolled in, or of every course. */
    listReleasedExercises(enrolledUserId?: number): Promise<EnrolledExercise[]>;

    createExercise(exercise: { courseId: number; name: string; spec: Record<string, unknown> }): Promise<Exercise>;
    /** Releases the exercise (now unless `at` says when); a released exercise stays released. */
    releaseExercise(exerciseId: number, at?: Date): Promise<Exercise>;
    findExercise(courseId: number, name: string): Promise<Exercise | undefined>;
    listExercises(courseId: number): Promise<Exercise[]>;
    /** Replaces the exercise's spec (an updated exercise.json). */
    updateExerciseSpec(exerciseId: number, spec: Record<string, unknown>): Promise<Exercise>;
    /** Stores the next version of the exercise's starter files (1 for the first) and returns it. */
    addStarterVersion(exerciseId: number, files: Record<string, string>): Promise<StarterVersion>;
    /** The given starter version of the exercise, or its newest; undefined when there is none. */
    starterVersion(exerciseId: number, version?: number): Promise<StarterVersion | undefined>;
    /** The workspace's files that came from the starter, by path. */
    starterFiles(workspaceId: number): Promise<StarterFile[]>;
    /** Records the starter version a workspace file was merged with (and a conflict, if any). */
    setStarterFile(workspaceId: number, file: Omit<StarterFile, 'updatedAt'>): Promise<void>;

    /** The owner's workspace for the exercise, created on first use. */
    workspace(ownerId: number, exerciseId: number): Promise<Workspace>;
    /** Every workspace of the exercise, by owner id, with its last activity. */
    listWorkspaces(exerciseId: number): Promise<WorkspaceSummary[]>;
    /** How many current files the workspace has and their size in bytes (for quotas). */
    workspaceSize(workspaceId: number): Promise<WorkspaceSize>;
    /** Saves a new revision of the file (1 for a new path) and returns it once it is durable. */
    saveFile(save: SaveFile): Promise<FileRevision>;
    /** Deletes the file: a new revision without content (its history stays). */
    deleteFile(remove: Omit<SaveFile, 'content'>): Promise<FileRevision>;
    /** The latest revision of the file, or the given one; undefined when there is none or it is deleted (latest only). */
    readFile(workspaceId: number, path: string, revision?: number): Promise<FileRevision | undefined>;
    /** The latest revision of every file that is not deleted, by path. */
    listFiles(workspaceId: number): Promise<FileRevisionInfo[]>;
    /** Every revision of the file, newest first. */
    history(workspaceId: number, path: string): Promise<FileRevisionInfo[]>;
    /** Brings an earlier revision back as a new revision (history is never rewritten). */
    restore(restore: { workspaceId: number; path: string; revision: number; authorId: number }): Promise<FileRevision>;

    submit(workspaceId: number, submittedBy: number): Promise<Submission>;
    recordTestResult(result: Omit<TestResult, 'id' | 'createdAt'>): Promise<TestResult>;
    recordSimulationResult(result: Omit<SimulationResult, 'id' | 'createdAt'>): Promise<SimulationResult>;
    latestTestResult(workspaceId: number): Promise<TestResult | undefined>;
    latestSimulationResult(workspaceId: number): Promise<SimulationResult | undefined>;

    /** The submission, with its workspace's owner. */
    findSubmission(id: number): Promise<OwnedSubmission | undefined>;
    /** The newest submission of every workspace of the exercise, by owner. */
    latestSubmissions(exerciseId: number): Promise<OwnedSubmission[]>;

    /** Stores (or replaces) the exercise's grading specification and hidden files. */
    setExerciseGrading(
        exerciseId: number,
        grading: { spec: Record<string, unknown>; files: Record<string, string> },
    ): Promise<ExerciseGrading>;
    /** The exercise's grading, or undefined when it has none. */
    exerciseGrading(exerciseId: number): Promise<ExerciseGrading | undefined>;
    /** Removes the exercise's grading (an update whose folder has no grading/ any more). */
    deleteExerciseGrading(exerciseId: number): Promise<void>;
    /** A new run, queued. */
    createGradingRun(run: { exerciseId: number; kind: GradingRunKind; requestedBy: number; total?: number }): Promise<GradingRun>;
    updateGradingRun(id: number, update: GradingRunUpdate): Promise<GradingRun>;
    findGradingRun(id: number): Promise<GradingRun | undefined>;
    /** The exercise's runs, newest first (at most `limit`, default 20). */
    listGradingRuns(exerciseId: number, limit?: number): Promise<GradingRun[]>;
    /** Marks every queued or running run failed with `error` (a server that stopped during them); returns how many. */
    failUnfinishedGradingRuns(error: string): Promise<number>;
    recordGradingResult(result: Omit<GradingResult, 'id' | 'createdAt'>): Promise<GradingResult>;
    setGradingRecordings(resultId: number, recordings: GradingRecording[]): Promise<void>;
    findGradingResult(id: number): Promise<GradingResult | undefined>;
    /** The results of a run, by user. */
    runResults(runId: number): Promise<GradingResult[]>;
    /** The newest result of every student of the exercise (or of one student), by user id. */
    latestGradingResults(exerciseId: number, userId?: number): Promise<GradingResult[]>;

    createSession(session: Omit<Session, 'createdAt'>): Promise<Session>;
    /** The session if it exists and has not expired at `now`. */
    findSession(id: string, now?: Date): Promise<Session | undefined>;
    deleteSession(id: string): Promise<void>;
    /** Removes the sessions expired at `now`; returns how many. */
    deleteExpiredSessions(now?: Date): Promise<number>;

    createInvitation(invitation: Omit<Invitation, 'createdAt' | 'usedAt'>): Promise<Invitation>;
    /** The invitation whatever its state (undefined: no such link). */
    findInvitation(id: string): Promise<Invitation | undefined>;
    /**
     * Uses the invitation once: when it exists, is unused and has not expired at `now`, marks it
     * used and sets the user's password hash, in one transaction (two concurrent uses: one wins).
     */
    redeemInvitation(id: string, passwordHash: string, now?: Date): Promise<Redemption>;
    /**
     * Creates the users with their invitations (and enrolls them in the course) in one
     * transaction: all of them or, on any conflict (a taken login or e-mail), none.
     */
    importUsers(users: ImportedUser[], courseId?: number): Promise<User[]>;

    close(): Promise<void>;
}

/** Thrown for a path a workspace cannot hold (absolute, `..`, empty segments, too long). */
export class InvalidPathError extends Error {}
/** Thrown when a user, course, exercise or revision a call names does not exist, or a unique name is taken. */
export class StorageConflictError extends Error {}
