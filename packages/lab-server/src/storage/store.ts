// LabStore on Kysely: the same queries for PGlite and PostgreSQL (connect.ts opens either).
import type { Kysely } from 'kysely';
import { type OpenDatabase, openDatabase, type StorageOptions } from './connect.js';
import {
    currentSize,
    exerciseWorkspaces,
    insertRevision,
    latestRevisions,
    readRevision,
    restoreRevision,
    revisionHistory,
} from './files.js';
import {
    failUnfinished,
    findSubmission,
    insertResult,
    insertRun,
    latestSubmissions,
    removeExerciseGrading,
    selectExerciseGrading,
    selectLatestResults,
    selectResult,
    selectRun,
    selectRunResults,
    selectRuns,
    updateRecordings,
    updateRun,
    upsertExerciseGrading,
} from './grading.js';
import { importAll, insertInvitation, insertUser, redeem, toInvitation } from './invitations.js';
import { toCourse, toExercise, toSession, toSimulationResult, toSubmission, toTestResult, toUser } from './rows.js';
import type { Database } from './schema.js';
import { insertStarterVersion, selectStarterFiles, selectStarterVersion, updateSpec, upsertStarterFile } from './starters.js';
import {
    type Course,
    type EnrolledExercise,
    type Exercise,
    type ExerciseGrading,
    type GradingRecording,
    type GradingResult,
    type GradingRun,
    type GradingRunKind,
    type GradingRunUpdate,
    type FileRevision,
    type FileRevisionInfo,
    type ImportedUser,
    type Invitation,
    type LabStore,
    type NewUser,
    type OwnedSubmission,
    type Redemption,
    type SaveFile,
    type Session,
    type SimulationResult,
    type StarterFile,
    type StarterVersion,
    StorageConflictError,
    type Submission,
    type TestResult,
    type User,
    type Workspace,
    type WorkspaceSize,
    type WorkspaceSummary,
} from './types.js';

/** Opens the store (PGlite on `dataDir` or PostgreSQL at `databaseUrl`) with its schema up to date. */
export async function openLabStore(options: StorageOptions): Promise<LabStore> {
    return new KyselyLabStore(await openDatabase(options));
}

/** PostgreSQL's error codes for a unique and a foreign-key violation. */
const CONFLICT_CODES = new Set(['23505', '23503']);

/** Runs an insert or update; a unique or foreign-key violation becomes a StorageConflictError. */
async function conflictsAsErrors<T>(what: string, run: () => Promise<T>): Promise<T> {
    try {
        return await run();
    } catch (error) {
        const code = (error as { code?: unknown }).code;
        if (typeof code === 'string' && CONFLICT_CODES.has(code)) {
            throw new StorageConflictError(`${what}: ${(error as Error).message}`, { cause: error });
        }
        throw error;
    }
}

class KyselyLabStore implements LabStore {
    readonly backend: LabStore['backend'];
    private readonly db: Kysely<Database>;

    constructor(private readonly opened: OpenDatabase) {
        this.db = opened.db;
        this.backend = opened.backend;
    }

    // --- users

    createUser(u: NewUser): Promise<User> {
        return conflictsAsErrors(`cannot create the user ${u.login}`, () => insertUser(this.db, u));
    }

    async findUserById(id: number): Promise<User | undefined> {
        const row = await this.db.selectFrom('users').selectAll().where('id', '=', id).executeTakeFirst();
        return row && toUser(row);
    }

    async findUserByLogin(login: string): Promise<User | undefined> {
        const row = await this.db.selectFrom('users').selectAll().where('login', '=', login).executeTakeFirst();
        return row && toUser(row);
    }

    async findUserByOidc(issuer: string, subject: string): Promise<User | undefined> {
        const row = await this.db
            .selectFrom('users')
            .selectAll()
            .where('oidc_issuer', '=', issuer)
            .where('oidc_subject', '=', subject)
            .executeTakeFirst();
        return row && toUser(row);
    }

    async findUserByEmail(email: string): Promise<User | undefined> {
        const row = await this.db
            .selectFrom('users')
            .selectAll()
            .where((eb) => eb(eb.fn('lower', ['email']), '=', email.toLowerCase()))
            .executeTakeFirst();
        return row && toUser(row);
    }

    linkOidc(userId: number, issuer: string, subject: string): Promise<User> {
        return conflictsAsErrors(`cannot link user ${userId} to ${issuer}`, async () => {
            const row = await this.db
                .updateTable('users')
                .set({ oidc_issuer: issuer, oidc_subject: subject })
                .where('id', '=', userId)
                .where('oidc_issuer', 'is', null)
                .returningAll()
                .executeTakeFirst();
            if (!row) throw new StorageConflictError(`user ${userId} does not exist or has a single sign-on identity already`);
            return toUser(row);
        });
    }

    async setPasswordHash(userId: number, passwordHash: string | null): Promise<void> {
        const { numUpdatedRows } = await this.db
            .updateTable('users')
            .set({ password_hash: passwordHash })
            .where('id', '=', userId)
            .executeTakeFirstOrThrow();
        if (numUpdatedRows === 0n) throw new StorageConflictError(`there is no user ${userId}`);
    }

    async listUsers(): Promise<User[]> {
        return (await this.db.selectFrom('users').selectAll().orderBy('login').execute()).map(toUser);
    }

    // --- courses and exercises

    createCourse(c: { name: string; title: string }): Promise<Course> {
        return conflictsAsErrors(`cannot create the course ${c.name}`, async () =>
            toCourse(await this.db.insertInto('courses').values(c).returningAll().executeTakeFirstOrThrow()),
        );
    }

    async findCourse(name: string): Promise<Course | undefined> {
        const row = await this.db.selectFrom('courses').selectAll().where('name', '=', name).executeTakeFirst();
        return row && toCourse(row);
    }

    enroll(courseId: number, userId: number): Promise<void> {
        return conflictsAsErrors(`cannot enroll user ${userId} in course ${courseId}`, async () => {
            await this.db
                .insertInto('enrollments')
                .values({ course_id: courseId, user_id: userId })
                .onConflict((oc) => oc.columns(['course_id', 'user_id']).doNothing())
                .execute();
        });
    }

    /** The released exercises, by course and name: of the courses `enrolledUserId` is enrolled in, or of every course. */
    async listReleasedExercises(enrolledUserId?: number): Promise<EnrolledExercise[]> {
        let query = this.db
            .selectFrom('courses')
            .innerJoin('exercises', 'exercises.course_id', 'courses.id')
            .select(['courses.name as course', 'courses.title as courseTitle', 'exercises.name as exercise', 'exercises.spec as spec'])
            .where('exercises.released_at', 'is not', null);
        if (enrolledUserId !== undefined)
            query = query.where((eb) =>
                eb.exists(
                    eb
                        .selectFrom('enrollments')
                        .select('enrollments.user_id')
                        .whereRef('enrollments.course_id', '=', 'courses.id')
                        .where('enrollments.user_id', '=', enrolledUserId),
                ),
            );
        const rows = await query.orderBy('courses.name').orderBy('exercises.name').execute();
        return rows.map((r) => ({
            course: r.course,
            courseTitle: r.courseTitle,
            exercise: r.exercise,
            title: typeof r.spec['title'] === 'string' ? r.spec['title'] : r.exercise,
        }));
    }

    async listEnrolled(courseId: number): Promise<User[]> {
        const rows = await this.db
            .selectFrom('users')
            .innerJoin('enrollments', 'enrollments.user_id', 'users.id')
            .selectAll('users')
            .where('enrollments.course_id', '=', courseId)
            .orderBy('users.login')
            .execute();
        return rows.map(toUser);
    }

    createExercise(e: { courseId: number; name: string; spec: Record<string, unknown> }): Promise<Exercise> {
        return conflictsAsErrors(`cannot create the exercise ${e.name}`, async () => {
            const row = await this.db
                .insertInto('exercises')
                .values({ course_id: e.courseId, name: e.name, spec: JSON.stringify(e.spec) })
                .returningAll()
                .executeTakeFirstOrThrow();
            return toExercise(row);
        });
    }

    async releaseExercise(exerciseId: number, at: Date = new Date()): Promise<Exercise> {
        const row = await this.db
            .updateTable('exercises')
            .set((eb) => ({ released_at: eb.fn.coalesce('released_at', eb.val(at)) }))
            .where('id', '=', exerciseId)
            .returningAll()
            .executeTakeFirst();
        if (!row) throw new StorageConflictError(`there is no exercise ${exerciseId}`);
        return toExercise(row);
    }

    async findExercise(courseId: number, name: string): Promise<Exercise | undefined> {
        const row = await this.db
            .selectFrom('exercises')
            .selectAll()
            .where('course_id', '=', courseId)
            .where('name', '=', name)
            .executeTakeFirst();
        return row && toExercise(row);
    }

    async listExercises(courseId: number): Promise<Exercise[]> {
        return (await this.db.selectFrom('exercises').selectAll().where('course_id', '=', courseId).orderBy('name').execute()).map(
            toExercise,
        );
    }

    updateExerciseSpec(exerciseId: number, spec: Record<string, unknown>): Promise<Exercise> {
        return updateSpec(this.db, exerciseId, spec);
    }

    addStarterVersion(exerciseId: number, files: Record<string, string>): Promise<StarterVersion> {
        return conflictsAsErrors(`cannot add a starter version to exercise ${exerciseId}`, () =>
            insertStarterVersion(this.db, exerciseId, files),
        );
    }

    starterVersion(exerciseId: number, version?: number): Promise<StarterVersion | undefined> {
        return selectStarterVersion(this.db, exerciseId, version);
    }

    starterFiles(workspaceId: number): Promise<StarterFile[]> {
        return selectStarterFiles(this.db, workspaceId);
    }

    setStarterFile(workspaceId: number, file: Omit<StarterFile, 'updatedAt'>): Promise<void> {
        return conflictsAsErrors(`cannot record the starter of ${file.path} in workspace ${workspaceId}`, () =>
            upsertStarterFile(this.db, workspaceId, file),
        );
    }

    // --- workspaces and files

    workspace(ownerId: number, exerciseId: number): Promise<Workspace> {
        return conflictsAsErrors(`cannot open the workspace of user ${ownerId} for exercise ${exerciseId}`, async () => {
            // Read first: opening an existing workspace (every request) writes nothing.
            const find = () =>
                this.db
                    .selectFrom('workspaces')
                    .selectAll()
                    .where('owner_id', '=', ownerId)
                    .where('exercise_id', '=', exerciseId)
                    .executeTakeFirst();
            const row =
                (await find()) ??
                (await this.db
                    .insertInto('workspaces')
                    .values({ owner_id: ownerId, exercise_id: exerciseId })
                    .onConflict((oc) => oc.columns(['owner_id', 'exercise_id']).doNothing())
                    .returningAll()
                    .executeTakeFirst()) ??
                // Created by a concurrent call between the two statements above.
                (await find());
            if (!row)
                throw new StorageConflictError(`the workspace of user ${ownerId} for exercise ${exerciseId} vanished while it was opened`);
            return { id: row.id, ownerId: row.owner_id, exerciseId: row.exercise_id, createdAt: row.created_at };
        });
    }

    listWorkspaces(exerciseId: number): Promise<WorkspaceSummary[]> {
        return exerciseWorkspaces(this.db, exerciseId);
    }

    workspaceSize(workspaceId: number): Promise<WorkspaceSize> {
        return currentSize(this.db, workspaceId);
    }

    saveFile(s: SaveFile): Promise<FileRevision> {
        return conflictsAsErrors(`cannot save ${s.path}`, () => insertRevision(this.db, s));
    }

    deleteFile(d: Omit<SaveFile, 'content'>): Promise<FileRevision> {
        return conflictsAsErrors(`cannot delete ${d.path}`, () => insertRevision(this.db, { ...d, content: null }));
    }

    readFile(workspaceId: number, path: string, revision?: number): Promise<FileRevision | undefined> {
        return readRevision(this.db, workspaceId, path, revision);
    }

    listFiles(workspaceId: number): Promise<FileRevisionInfo[]> {
        return latestRevisions(this.db, workspaceId);
    }

    history(workspaceId: number, path: string): Promise<FileRevisionInfo[]> {
        return revisionHistory(this.db, workspaceId, path);
    }

    restore(r: { workspaceId: number; path: string; revision: number; authorId: number }): Promise<FileRevision> {
        return conflictsAsErrors(`cannot restore ${r.path}`, () => restoreRevision(this.db, r));
    }

    // --- submissions and results

    submit(workspaceId: number, submittedBy: number): Promise<Submission> {
        return conflictsAsErrors(`cannot submit workspace ${workspaceId}`, () =>
            this.db.transaction().execute(async (tx) => {
                const files = Object.fromEntries((await latestRevisions(tx, workspaceId)).map((f) => [f.path, f.revision]));
                const row = await tx
                    .insertInto('submissions')
                    .values({ workspace_id: workspaceId, submitted_by: submittedBy, files: JSON.stringify(files) })
                    .returningAll()
                    .executeTakeFirstOrThrow();
                return toSubmission(row);
            }),
        );
    }

    recordTestResult(r: Omit<TestResult, 'id' | 'createdAt'>): Promise<TestResult> {
        return conflictsAsErrors('cannot record the test result', async () => {
            const row = await this.db
                .insertInto('test_results')
                .values({
                    workspace_id: r.workspaceId,
                    submission_id: r.submissionId,
                    passed: r.passed,
                    failed: r.failed,
                    skipped: r.skipped,
                    details: JSON.stringify(r.details ?? null),
                })
                .returningAll()
                .executeTakeFirstOrThrow();
            return toTestResult(row);
        });
    }

    recordSimulationResult(r: Omit<SimulationResult, 'id' | 'createdAt'>): Promise<SimulationResult> {
        return conflictsAsErrors('cannot record the simulation result', async () => {
            const row = await this.db
                .insertInto('simulation_results')
                .values({
                    workspace_id: r.workspaceId,
                    submission_id: r.submissionId,
                    goal_reached: r.goalReached,
                    simulated_seconds: r.simulatedSeconds,
                    details: JSON.stringify(r.details ?? null),
                })
                .returningAll()
                .executeTakeFirstOrThrow();
            return toSimulationResult(row);
        });
    }

    async latestTestResult(workspaceId: number): Promise<TestResult | undefined> {
        const row = await this.db
            .selectFrom('test_results')
            .selectAll()
            .where('workspace_id', '=', workspaceId)
            .orderBy('created_at', 'desc')
            .orderBy('id', 'desc')
            .executeTakeFirst();
        return row && toTestResult(row);
    }

    async latestSimulationResult(workspaceId: number): Promise<SimulationResult | undefined> {
        const row = await this.db
            .selectFrom('simulation_results')
            .selectAll()
            .where('workspace_id', '=', workspaceId)
            .orderBy('created_at', 'desc')
            .orderBy('id', 'desc')
            .executeTakeFirst();
        return row && toSimulationResult(row);
    }

    // --- grading (grading.ts)

    findSubmission(id: number): Promise<OwnedSubmission | undefined> {
        return findSubmission(this.db, id);
    }

    latestSubmissions(exerciseId: number): Promise<OwnedSubmission[]> {
        return latestSubmissions(this.db, exerciseId);
    }

    setExerciseGrading(
        exerciseId: number,
        grading: { spec: Record<string, unknown>; files: Record<string, string> },
    ): Promise<ExerciseGrading> {
        return conflictsAsErrors(`cannot store the grading of exercise ${exerciseId}`, () =>
            upsertExerciseGrading(this.db, exerciseId, grading),
        );
    }

    exerciseGrading(exerciseId: number): Promise<ExerciseGrading | undefined> {
        return selectExerciseGrading(this.db, exerciseId);
    }

    deleteExerciseGrading(exerciseId: number): Promise<void> {
        return removeExerciseGrading(this.db, exerciseId);
    }

    createGradingRun(run: { exerciseId: number; kind: GradingRunKind; requestedBy: number; total?: number }): Promise<GradingRun> {
        return conflictsAsErrors('cannot create the grading run', () => insertRun(this.db, run));
    }

    updateGradingRun(id: number, update: GradingRunUpdate): Promise<GradingRun> {
        return updateRun(this.db, id, update);
    }

    findGradingRun(id: number): Promise<GradingRun | undefined> {
        return selectRun(this.db, id);
    }

    listGradingRuns(exerciseId: number, limit?: number): Promise<GradingRun[]> {
        return selectRuns(this.db, exerciseId, limit);
    }

    failUnfinishedGradingRuns(error: string): Promise<number> {
        return failUnfinished(this.db, error);
    }

    recordGradingResult(result: Omit<GradingResult, 'id' | 'createdAt'>): Promise<GradingResult> {
        return conflictsAsErrors('cannot record the grading result', () => insertResult(this.db, result));
    }

    setGradingRecordings(resultId: number, recordings: GradingRecording[]): Promise<void> {
        return updateRecordings(this.db, resultId, recordings);
    }

    findGradingResult(id: number): Promise<GradingResult | undefined> {
        return selectResult(this.db, id);
    }

    runResults(runId: number): Promise<GradingResult[]> {
        return selectRunResults(this.db, runId);
    }

    latestGradingResults(exerciseId: number, userId?: number): Promise<GradingResult[]> {
        return selectLatestResults(this.db, exerciseId, userId);
    }

    // --- sessions

    createSession(s: Omit<Session, 'createdAt'>): Promise<Session> {
        return conflictsAsErrors('cannot create the session', async () => {
            const row = await this.db
                .insertInto('sessions')
                .values({ id: s.id, user_id: s.userId, csrf_secret: s.csrfSecret, expires_at: s.expiresAt })
                .returningAll()
                .executeTakeFirstOrThrow();
            return toSession(row);
        });
    }

    async findSession(id: string, now: Date = new Date()): Promise<Session | undefined> {
        const row = await this.db.selectFrom('sessions').selectAll().where('id', '=', id).where('expires_at', '>', now).executeTakeFirst();
        return row && toSession(row);
    }

    async deleteSession(id: string): Promise<void> {
        await this.db.deleteFrom('sessions').where('id', '=', id).execute();
    }

    async deleteExpiredSessions(now: Date = new Date()): Promise<number> {
        const { numDeletedRows } = await this.db.deleteFrom('sessions').where('expires_at', '<=', now).executeTakeFirstOrThrow();
        return Number(numDeletedRows);
    }

    // --- invitations

    createInvitation(i: Omit<Invitation, 'createdAt' | 'usedAt'>): Promise<Invitation> {
        return conflictsAsErrors('cannot create the invitation', () => insertInvitation(this.db, i));
    }

    async findInvitation(id: string): Promise<Invitation | undefined> {
        const row = await this.db.selectFrom('invitations').selectAll().where('id', '=', id).executeTakeFirst();
        return row && toInvitation(row);
    }

    redeemInvitation(id: string, passwordHash: string, now: Date = new Date()): Promise<Redemption> {
        return redeem(this.db, id, passwordHash, now);
    }

    importUsers(users: ImportedUser[], courseId?: number): Promise<User[]> {
        return conflictsAsErrors('cannot import the users', () => importAll(this.db, users, courseId));
    }

    close(): Promise<void> {
        return this.opened.close();
    }
}
