// Rows of the database → the records of the LabStore API (camelCase, no SQL names outside storage).
import type { Selectable } from 'kysely';
import type { Database } from './schema.js';
import type { Course, Exercise, FileRevision, FileRevisionInfo, Session, SimulationResult, Submission, TestResult, User } from './types.js';

type Row<T extends keyof Database> = Selectable<Database[T]>;

export function toUser(r: Row<'users'>): User {
    return {
        id: r.id,
        login: r.login,
        email: r.email,
        name: r.name,
        role: r.role,
        passwordHash: r.password_hash,
        oidcIssuer: r.oidc_issuer,
        oidcSubject: r.oidc_subject,
        createdAt: r.created_at,
    };
}

export function toCourse(r: Row<'courses'>): Course {
    return { id: r.id, name: r.name, title: r.title, createdAt: r.created_at };
}

export function toExercise(r: Row<'exercises'>): Exercise {
    return { id: r.id, courseId: r.course_id, name: r.name, releasedAt: r.released_at, spec: r.spec, createdAt: r.created_at };
}

export function toRevision(r: Omit<Row<'file_revisions'>, 'id' | 'workspace_id'>): FileRevision {
    return {
        path: r.path,
        revision: r.revision,
        content: r.content,
        authorId: r.author_id,
        restoredFrom: r.restored_from,
        createdAt: r.created_at,
    };
}

export function toRevisionInfo(
    r: Omit<Row<'file_revisions'>, 'id' | 'workspace_id' | 'content'> & { size: number | null; deleted: boolean },
): FileRevisionInfo {
    return {
        path: r.path,
        revision: r.revision,
        authorId: r.author_id,
        restoredFrom: r.restored_from,
        createdAt: r.created_at,
        size: r.size ?? 0,
        deleted: r.deleted,
    };
}

export function toSubmission(r: Row<'submissions'>): Submission {
    return { id: r.id, workspaceId: r.workspace_id, submittedBy: r.submitted_by, files: r.files, createdAt: r.created_at };
}

export function toTestResult(r: Row<'test_results'>): TestResult {
    return {
        id: r.id,
        workspaceId: r.workspace_id,
        submissionId: r.submission_id,
        passed: r.passed,
        failed: r.failed,
        skipped: r.skipped,
        details: r.details,
        createdAt: r.created_at,
    };
}

export function toSimulationResult(r: Row<'simulation_results'>): SimulationResult {
    return {
        id: r.id,
        workspaceId: r.workspace_id,
        submissionId: r.submission_id,
        goalReached: r.goal_reached,
        simulatedSeconds: r.simulated_seconds,
        details: r.details,
        createdAt: r.created_at,
    };
}

export function toSession(r: Row<'sessions'>): Session {
    return { id: r.id, userId: r.user_id, csrfSecret: r.csrf_secret, createdAt: r.created_at, expiresAt: r.expires_at };
}
