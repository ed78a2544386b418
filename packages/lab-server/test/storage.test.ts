// The LabStore on both backends (PGlite and a real PostgreSQL started here): the same suite,
// parameterized.
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { InvalidPathError, type LabStore, openLabStore, type StorageOptions, StorageConflictError } from '../src/storage/index.js';
import { BACKENDS, type Backend, startBackend } from './backends.js';

describe.each(BACKENDS)('LabStore on %s', (backendName) => {
    let backend: Backend;
    let storage: StorageOptions;
    let store: LabStore;
    let unique = 0;
    /** A name no other test of this store uses. */
    const fresh = (prefix: string) => `${prefix}${++unique}`;

    beforeAll(async () => {
        backend = await startBackend(backendName);
        storage = await backend.freshStorage();
        store = await openLabStore(storage);
    });
    afterAll(async () => {
        await store?.close();
        await backend?.dispose();
    });

    /** A student with a workspace for a new exercise of a new course. */
    async function studentWorkspace() {
        const student = await store.createUser({ login: fresh('student'), name: 'A Student', role: 'student' });
        const course = await store.createCourse({ name: fresh('course'), title: 'Robotics lab' });
        const exercise = await store.createExercise({ courseId: course.id, name: 'toast', spec: { title: 'Toast' } });
        const workspace = await store.workspace(student.id, exercise.id);
        return { student, course, exercise, workspace };
    }

    it('reports its backend', () => {
        expect(store.backend).toBe(backendName);
    });

    it('creates users and finds them by id, login and OpenID Connect subject', async () => {
        const login = fresh('ada');
        const created = await store.createUser({
            login,
            name: 'Ada',
            role: 'instructor',
            email: `${login}@example.org`,
            oidcIssuer: 'https://idp.example.org',
            oidcSubject: `sub-${login}`,
        });
        expect(created).toMatchObject({ login, name: 'Ada', role: 'instructor', passwordHash: null, email: `${login}@example.org` });
        expect(created.createdAt).toBeInstanceOf(Date);
        expect(await store.findUserById(created.id)).toEqual(created);
        expect(await store.findUserByLogin(login)).toEqual(created);
        expect(await store.findUserByOidc('https://idp.example.org', `sub-${login}`)).toEqual(created);
        expect(await store.findUserByOidc('https://other.example.org', `sub-${login}`)).toBeUndefined();
        expect(await store.findUserByLogin(fresh('nobody'))).toBeUndefined();
        expect((await store.listUsers()).map((u) => u.login)).toContain(login);
    });

    it('refuses a taken login, an unknown role and half an OpenID Connect identity', async () => {
        const login = fresh('bob');
        await store.createUser({ login, name: 'Bob', role: 'student' });
        await expect(store.createUser({ login, name: 'Bob 2', role: 'student' })).rejects.toBeInstanceOf(StorageConflictError);
        // @ts-expect-error: a role the type does not allow, as a request body could carry it
        await expect(store.createUser({ login: fresh('eve'), name: 'Eve', role: 'admin' })).rejects.toThrow(/check constraint/);
        await expect(store.createUser({ login: fresh('half'), name: 'Half', role: 'student', oidcSubject: 'x' })).rejects.toThrow(
            /check constraint/,
        );
    });

    it('sets and clears a password hash', async () => {
        const user = await store.createUser({ login: fresh('carol'), name: 'Carol', role: 'student' });
        await store.setPasswordHash(user.id, '$argon2id$v=19$m=65536,t=3,p=4$c2FsdA$aGFzaA');
        expect((await store.findUserById(user.id))?.passwordHash).toBe('$argon2id$v=19$m=65536,t=3,p=4$c2FsdA$aGFzaA');
        await store.setPasswordHash(user.id, null);
        expect((await store.findUserById(user.id))?.passwordHash).toBeNull();
        await expect(store.setPasswordHash(987654, 'x')).rejects.toBeInstanceOf(StorageConflictError);
    });

    it('keeps courses, enrollments and exercises; a release keeps its first time', async () => {
        const name = fresh('rob');
        const course = await store.createCourse({ name, title: 'Robotics' });
        expect(await store.findCourse(name)).toEqual(course);
        await expect(store.createCourse({ name, title: 'again' })).rejects.toBeInstanceOf(StorageConflictError);
        const [a, b] = [
            await store.createUser({ login: fresh('zed'), name: 'Z', role: 'student' }),
            await store.createUser({ login: fresh('amy'), name: 'A', role: 'student' }),
        ];
        await store.enroll(course.id, a.id);
        await store.enroll(course.id, b.id);
        await store.enroll(course.id, a.id); // twice is once
        expect((await store.listEnrolled(course.id)).map((u) => u.id).sort()).toEqual([a.id, b.id].sort());
        await expect(store.enroll(course.id, 987654)).rejects.toBeInstanceOf(StorageConflictError);

        const spec = { title: 'Toast', starter: ['Controller.arc'], readOnly: [], nested: { platforms: ['timesync'] } };
        const exercise = await store.createExercise({ courseId: course.id, name: 'toast', spec });
        expect(exercise).toMatchObject({ courseId: course.id, name: 'toast', releasedAt: null, spec });
        await expect(store.createExercise({ courseId: course.id, name: 'toast', spec })).rejects.toBeInstanceOf(StorageConflictError);
        const first = new Date('2026-01-05T10:00:00Z');
        expect((await store.releaseExercise(exercise.id, first)).releasedAt).toEqual(first);
        expect((await store.releaseExercise(exercise.id, new Date('2026-02-01T00:00:00Z'))).releasedAt).toEqual(first);
        await expect(store.releaseExercise(987654)).rejects.toBeInstanceOf(StorageConflictError);
        expect(await store.findExercise(course.id, 'toast')).toMatchObject({ id: exercise.id, releasedAt: first });
        expect((await store.listExercises(course.id)).map((e) => e.name)).toEqual(['toast']);
    });

    it('gives each student one workspace per exercise, and keeps workspaces apart', async () => {
        const { student, exercise, workspace } = await studentWorkspace();
        expect(await store.workspace(student.id, exercise.id)).toEqual(workspace);
        const [x, y] = await Promise.all([store.workspace(student.id, exercise.id), store.workspace(student.id, exercise.id)]);
        expect([x.id, y.id]).toEqual([workspace.id, workspace.id]);
        await expect(store.workspace(987654, exercise.id)).rejects.toBeInstanceOf(StorageConflictError);
        const other = await store.createUser({ login: fresh('other'), name: 'Other', role: 'student' });
        const theirs = await store.workspace(other.id, exercise.id);
        expect(theirs.id).not.toBe(workspace.id);
        await store.saveFile({ workspaceId: workspace.id, path: 'Mine.arc', content: 'mine', authorId: student.id });
        expect(await store.listFiles(theirs.id)).toEqual([]);
        expect(await store.readFile(theirs.id, 'Mine.arc')).toBeUndefined();
    });

    it('lists the workspaces of an exercise with their last activity, and measures a workspace', async () => {
        const { student, exercise, workspace } = await studentWorkspace();
        const idle = await store.createUser({ login: fresh('idle'), name: 'Idle', role: 'student' });
        const idleWorkspace = await store.workspace(idle.id, exercise.id);
        expect(await store.workspaceSize(workspace.id)).toEqual({ files: 0, bytes: 0 });
        await store.saveFile({ workspaceId: workspace.id, path: 'A.arc', content: 'aaaa', authorId: student.id });
        await store.saveFile({ workspaceId: workspace.id, path: 'A.arc', content: 'aa', authorId: student.id });
        await store.saveFile({ workspaceId: workspace.id, path: 'B.arc', content: 'ü', authorId: student.id });
        const last = await store.saveFile({ workspaceId: workspace.id, path: 'Gone.arc', content: 'gone', authorId: student.id });
        const deleted = await store.deleteFile({ workspaceId: workspace.id, path: 'Gone.arc', authorId: student.id });
        // the latest revision of each current file: A (2 bytes), B (ü: 2 bytes); Gone.arc is deleted
        expect(await store.workspaceSize(workspace.id)).toEqual({ files: 2, bytes: 4 });
        const listed = await store.listWorkspaces(exercise.id);
        expect(listed.map((w) => [w.id, w.ownerId])).toEqual(
            [
                [workspace.id, student.id],
                [idleWorkspace.id, idle.id],
            ].sort((a, b) => a[1]! - b[1]!),
        );
        expect(listed.find((w) => w.id === workspace.id)?.lastActivity).toEqual(deleted.createdAt);
        expect(deleted.createdAt.getTime()).toBeGreaterThanOrEqual(last.createdAt.getTime());
        expect(listed.find((w) => w.id === idleWorkspace.id)?.lastActivity).toBeNull();
    });

    it('makes every save a revision and reads the latest and any earlier one', async () => {
        const { student, workspace } = await studentWorkspace();
        const save = (path: string, content: string) => store.saveFile({ workspaceId: workspace.id, path, content, authorId: student.id });
        expect((await save('models/Controller.arc', 'v1')).revision).toBe(1);
        expect((await save('models/Controller.arc', 'v2')).revision).toBe(2);
        expect((await save('models/Controller.arc', 'v3 ü')).revision).toBe(3);
        expect((await save('app.arcapp', 'app')).revision).toBe(1);

        expect(await store.readFile(workspace.id, 'models/Controller.arc')).toMatchObject({
            revision: 3,
            content: 'v3 ü',
            authorId: student.id,
        });
        expect(await store.readFile(workspace.id, 'models/Controller.arc', 1)).toMatchObject({ revision: 1, content: 'v1' });
        expect(await store.readFile(workspace.id, 'models/Controller.arc', 4)).toBeUndefined();
        expect(await store.readFile(workspace.id, 'missing.arc')).toBeUndefined();
        const files = await store.listFiles(workspace.id);
        expect(files.map((f) => [f.path, f.revision, f.size])).toEqual([
            ['app.arcapp', 1, 3],
            ['models/Controller.arc', 3, 5], // bytes: ü is two
        ]);
        expect((await store.history(workspace.id, 'models/Controller.arc')).map((h) => h.revision)).toEqual([3, 2, 1]);
    });

    it('restores an earlier revision as a new one and keeps the history', async () => {
        const { student, workspace } = await studentWorkspace();
        const instructor = await store.createUser({ login: fresh('prof'), name: 'Prof', role: 'instructor' });
        const path = 'Controller.arc';
        for (const content of ['first', 'second', 'broken'])
            await store.saveFile({ workspaceId: workspace.id, path, content, authorId: student.id });
        const restored = await store.restore({ workspaceId: workspace.id, path, revision: 2, authorId: instructor.id });
        expect(restored).toMatchObject({ revision: 4, content: 'second', restoredFrom: 2, authorId: instructor.id });
        expect((await store.readFile(workspace.id, path))?.content).toBe('second');
        expect((await store.readFile(workspace.id, path, 3))?.content).toBe('broken');
        expect((await store.history(workspace.id, path)).map((h) => [h.revision, h.restoredFrom])).toEqual([
            [4, 2],
            [3, null],
            [2, null],
            [1, null],
        ]);
        await expect(store.restore({ workspaceId: workspace.id, path, revision: 99, authorId: student.id })).rejects.toBeInstanceOf(
            StorageConflictError,
        );
    });

    it('deletes a file as a revision; its history stays and a restore brings it back', async () => {
        const { student, workspace } = await studentWorkspace();
        const path = 'Old.arc';
        await store.saveFile({ workspaceId: workspace.id, path, content: 'old', authorId: student.id });
        expect(await store.deleteFile({ workspaceId: workspace.id, path, authorId: student.id })).toMatchObject({
            revision: 2,
            content: null,
        });
        expect(await store.readFile(workspace.id, path)).toBeUndefined();
        expect(await store.listFiles(workspace.id)).toEqual([]);
        expect((await store.history(workspace.id, path)).map((h) => [h.revision, h.deleted])).toEqual([
            [2, true],
            [1, false],
        ]);
        await store.restore({ workspaceId: workspace.id, path, revision: 1, authorId: student.id });
        expect(await store.readFile(workspace.id, path)).toMatchObject({ revision: 3, content: 'old' });
    });

    it('gives concurrent saves of one file distinct revisions', async () => {
        const { student, workspace } = await studentWorkspace();
        const saves = await Promise.all(
            Array.from({ length: 20 }, (_, i) =>
                store.saveFile({ workspaceId: workspace.id, path: 'Busy.arc', content: `save ${i}`, authorId: student.id }),
            ),
        );
        expect(saves.map((s) => s.revision).sort((a, b) => a - b)).toEqual(Array.from({ length: 20 }, (_, i) => i + 1));
        for (const s of saves) expect((await store.readFile(workspace.id, 'Busy.arc', s.revision))?.content).toBe(s.content);
    });

    it('refuses paths a workspace cannot hold, and saves to a workspace that does not exist', async () => {
        const { student, workspace } = await studentWorkspace();
        for (const path of [
            '',
            '/etc/passwd',
            '../other/Secret.arc',
            'a/../../b',
            'a//b',
            './a',
            'a/',
            'a\\b',
            'a\u0000b',
            'x'.repeat(513),
        ]) {
            await expect(
                store.saveFile({ workspaceId: workspace.id, path, content: 'x', authorId: student.id }),
                JSON.stringify(path),
            ).rejects.toBeInstanceOf(InvalidPathError);
            await expect(store.readFile(workspace.id, path)).rejects.toBeInstanceOf(InvalidPathError);
        }
        expect(
            (await store.saveFile({ workspaceId: workspace.id, path: `${'x'.repeat(508)}.arc`, content: 'x', authorId: student.id }))
                .revision,
        ).toBe(1);
        await expect(store.saveFile({ workspaceId: 987654, path: 'A.arc', content: 'x', authorId: student.id })).rejects.toBeInstanceOf(
            StorageConflictError,
        );
    });

    it('records a submission of the latest revisions and its test and simulation results', async () => {
        const { student, workspace } = await studentWorkspace();
        await store.saveFile({ workspaceId: workspace.id, path: 'A.arc', content: 'a1', authorId: student.id });
        await store.saveFile({ workspaceId: workspace.id, path: 'A.arc', content: 'a2', authorId: student.id });
        await store.saveFile({ workspaceId: workspace.id, path: 'B.arc', content: 'b1', authorId: student.id });
        const submission = await store.submit(workspace.id, student.id);
        expect(submission.files).toEqual({ 'A.arc': 2, 'B.arc': 1 });

        expect(await store.latestTestResult(workspace.id)).toBeUndefined();
        const details = { tests: [{ name: 'toasts', ok: false, message: 'expected 1, got 0' }] };
        await store.recordTestResult({ workspaceId: workspace.id, submissionId: null, passed: 3, failed: 1, skipped: 0, details });
        const latest = await store.recordTestResult({
            workspaceId: workspace.id,
            submissionId: submission.id,
            passed: 4,
            failed: 0,
            skipped: 1,
            details: [],
        });
        expect(await store.latestTestResult(workspace.id)).toEqual(latest);
        await expect(
            store.recordTestResult({ workspaceId: workspace.id, submissionId: null, passed: -1, failed: 0, skipped: 0, details: null }),
        ).rejects.toThrow(/check constraint/);

        const sim = await store.recordSimulationResult({
            workspaceId: workspace.id,
            submissionId: submission.id,
            goalReached: true,
            simulatedSeconds: 12.5,
            details: { toast: 'served' },
        });
        expect(sim).toMatchObject({ goalReached: true, simulatedSeconds: 12.5, details: { toast: 'served' } });
        expect(await store.latestSimulationResult(workspace.id)).toEqual(sim);
    });

    it('keeps sessions until they expire', async () => {
        const user = await store.createUser({ login: fresh('sess'), name: 'S', role: 'student' });
        const now = new Date('2026-03-01T12:00:00Z');
        const id = fresh('sha256-of-token-');
        const session = await store.createSession({ id, userId: user.id, csrfSecret: 'csrf', expiresAt: new Date('2026-03-01T13:00:00Z') });
        expect(await store.findSession(id, now)).toEqual(session);
        expect(await store.findSession(id, new Date('2026-03-01T13:00:00Z'))).toBeUndefined();
        await expect(store.createSession({ id, userId: user.id, csrfSecret: 'x', expiresAt: now })).rejects.toBeInstanceOf(
            StorageConflictError,
        );
        const gone = fresh('gone-');
        await store.createSession({ id: gone, userId: user.id, csrfSecret: 'c', expiresAt: new Date('2026-03-01T11:00:00Z') });
        expect(await store.deleteExpiredSessions(now)).toBeGreaterThanOrEqual(1);
        expect(await store.findSession(gone, new Date('2026-03-01T10:00:00Z'))).toBeUndefined();
        await store.deleteSession(id);
        expect(await store.findSession(id, now)).toBeUndefined();
    });

    it('keeps everything across a close and a reopen, and migrates a database once', async () => {
        const { student, workspace } = await studentWorkspace();
        await store.saveFile({ workspaceId: workspace.id, path: 'Kept.arc', content: 'kept', authorId: student.id });
        await store.close();
        store = await openLabStore(storage);
        expect(await store.readFile(workspace.id, 'Kept.arc')).toMatchObject({ revision: 1, content: 'kept' });
        expect(await store.findUserByLogin(student.login)).toEqual(student);
    });
});
