// The storage of exercise starters on both backends: starter versions and, per workspace file,
// the starter version it was merged with (src/exercises/ uses them; exercises.test.ts tests that).
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { InvalidPathError, type LabStore, openLabStore, StorageConflictError } from '../src/storage/index.js';
import { BACKENDS, type Backend, startBackend } from './backends.js';

describe.each(BACKENDS)('starter storage on %s', (backendName) => {
    let backend: Backend;
    let store: LabStore;

    beforeAll(async () => {
        backend = await startBackend(backendName);
        store = await openLabStore(await backend.freshStorage());
    });
    afterAll(async () => {
        await store?.close();
        await backend?.dispose();
    });

    it('stores starter versions (numbered from 1) and per-file bases (upserted)', async () => {
        const c = await store.createCourse({ name: 'course', title: 'Robotics lab' });
        const student = await store.createUser({ login: 'student', name: 'S', role: 'student' });
        const exercise = await store.createExercise({ courseId: c.id, name: 'x', spec: {} });
        expect(await store.starterVersion(exercise.id)).toBeUndefined();
        const v1 = await store.addStarterVersion(exercise.id, { 'a.arc': 'one\n' });
        const v2 = await store.addStarterVersion(exercise.id, { 'a.arc': 'two\n', 'b.arc': '' });
        expect([v1.version, v2.version]).toEqual([1, 2]);
        expect((await store.starterVersion(exercise.id))?.files).toEqual({ 'a.arc': 'two\n', 'b.arc': '' });
        expect((await store.starterVersion(exercise.id, 1))?.files).toEqual({ 'a.arc': 'one\n' });
        expect(await store.starterVersion(exercise.id, 3)).toBeUndefined();
        const ws = await store.workspace(student.id, exercise.id);
        await store.setStarterFile(ws.id, { path: 'a.arc', baseVersion: 1, conflictVersion: null });
        await store.setStarterFile(ws.id, { path: 'a.arc', baseVersion: 1, conflictVersion: 2 });
        expect(await store.starterFiles(ws.id)).toEqual([
            { path: 'a.arc', baseVersion: 1, conflictVersion: 2, updatedAt: expect.any(Date) },
        ]);
        await expect(store.addStarterVersion(999_999, {})).rejects.toThrow(StorageConflictError);
        await expect(store.addStarterVersion(exercise.id, { '../x': '' })).rejects.toThrow(InvalidPathError);
        await expect(store.setStarterFile(999_999, { path: 'a.arc', baseVersion: 1, conflictVersion: null })).rejects.toThrow(
            StorageConflictError,
        );
        expect((await store.updateExerciseSpec(exercise.id, { title: 'new' })).spec).toEqual({ title: 'new' });
    });
});
