// Exercises on both storage backends: release to a course, the starter on first open, and
// starter updates merged into students' files (clean, conflict, read-only), through the API and
// through `maa-lab exercise release | update` on a commander program of its own.
import { mkdtempSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import path from 'node:path';
import { Command } from 'commander';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import {
    CONFLICT_SUFFIX,
    ExerciseError,
    loadExercise,
    openExerciseWorkspace,
    registerExerciseCommands,
    releaseExercise,
    specOf,
    updateExercise,
} from '../src/exercises/index.js';
import { type LabStore, openLabStore, type StorageOptions } from '../src/storage/index.js';
import { BACKENDS, type Backend, startBackend } from './backends.js';
import { MANIFEST, STARTER, writeExercise, writeFiles } from './exercise-folder.js';

describe.each(BACKENDS)('exercises on %s', (backendName) => {
    let backend: Backend;
    let store: LabStore;
    let dir: string;
    let unique = 0;
    const fresh = (prefix: string) => `${prefix}${++unique}`;

    beforeAll(async () => {
        backend = await startBackend(backendName);
        store = await openLabStore(await backend.freshStorage());
        dir = mkdtempSync(path.join(tmpdir(), 'maa-lab-exercises-'));
    });
    afterAll(async () => {
        await store?.close();
        await backend?.dispose();
        if (dir) rmSync(dir, { recursive: true, force: true });
    });

    /** A course with an instructor and the given students enrolled. */
    async function course(students: number) {
        const c = await store.createCourse({ name: fresh('course'), title: 'Robotics lab' });
        const teacher = await store.createUser({ login: fresh('teacher'), name: 'T', role: 'instructor' });
        await store.enroll(c.id, teacher.id);
        const users = [];
        for (let i = 0; i < students; i++) {
            const u = await store.createUser({ login: fresh('student'), name: `S${i}`, role: 'student' });
            await store.enroll(c.id, u.id);
            users.push(u);
        }
        return { course: c, teacher, students: users };
    }

    async function files(workspaceId: number): Promise<Record<string, string>> {
        const out: Record<string, string> = {};
        for (const f of await store.listFiles(workspaceId)) out[f.path] = (await store.readFile(workspaceId, f.path))?.content ?? '';
        return out;
    }

    it('releases an exercise: spec, starter for every enrolled user, solution never', async () => {
        const { course: c, teacher, students } = await course(2);
        const loaded = await loadExercise(writeExercise(dir, fresh('lamp'), STARTER));
        const released = await releaseExercise(store, loaded, { course: c.name, authorId: teacher.id });
        expect(released.workspaces).toEqual([teacher.login, ...students.map((s) => s.login)].sort());
        expect(released.exercise.releasedAt).toBeInstanceOf(Date);
        expect(specOf(released.exercise)).toMatchObject({ name: loaded.name, starterVersion: 1, files: Object.keys(STARTER) });
        for (const s of students) {
            const ws = await store.workspace(s.id, released.exercise.id);
            expect(await files(ws.id)).toEqual(STARTER);
            expect((await store.starterFiles(ws.id)).map((f) => [f.path, f.baseVersion, f.conflictVersion])).toEqual(
                Object.keys(STARTER).map((p) => [p, 1, null]),
            );
        }
        await expect(releaseExercise(store, loaded, { course: c.name, authorId: teacher.id })).rejects.toThrow(/already: update it/);
    });

    it('an exercise with a base: students get the merged starter, and a change of the base reaches them as an update', async () => {
        const { course: c, teacher, students } = await course(1);
        const [student] = students as [(typeof students)[0]];
        // dir/<example> is the base, dir/lab/<name> the exercise (the base lies beside the exercises).
        const example = fresh('example');
        const writeBase = (files: Record<string, string>) => writeFiles(path.join(dir, example), files);
        writeBase({ ...STARTER, 'hello/Lamp.arc': 'package hello;\ncomponent Lamp {\n  // the solution\n}\n', 'README.md': '# example\n' });
        const stub = { 'hello/Lamp.arc': STARTER['hello/Lamp.arc'] as string };
        const manifest = { ...MANIFEST, base: `../../${example}`, omit: ['README.md'] };
        const folder = writeExercise(path.join(dir, 'lab'), fresh('lamp'), stub, manifest);
        const released = await releaseExercise(store, await loadExercise(folder), { course: c.name, authorId: teacher.id });
        expect(specOf(released.exercise).files).toEqual(Object.keys(STARTER));
        const ws = (await store.workspace(student.id, released.exercise.id)).id;
        expect(await files(ws)).toEqual(STARTER);
        // A fix in the example (a read-only file of the exercise) is a new starter version.
        writeBase({ 'lib/Toggle.arc': 'package lib;\ncomponent Toggle {\n  port in boolean press;\n}\n' });
        const updated = await updateExercise(store, await loadExercise(folder), { course: c.name, authorId: teacher.id });
        expect(updated.newStarter).toBe(true);
        expect(updated.spec.starterVersion).toBe(2);
        expect((await files(ws))['lib/Toggle.arc']).toBe('package lib;\ncomponent Toggle {\n  port in boolean press;\n}\n');
        expect((await files(ws))['hello/Lamp.arc']).toBe(STARTER['hello/Lamp.arc']);
    });

    it('a student enrolled after the release gets the starter when first opening it, once', async () => {
        const { course: c, teacher } = await course(0);
        const loaded = await loadExercise(writeExercise(dir, fresh('lamp'), STARTER));
        const { exercise } = await releaseExercise(store, loaded, { course: c.name, authorId: teacher.id });
        const late = await store.createUser({ login: fresh('late'), name: 'Late', role: 'student' });
        await store.enroll(c.id, late.id);
        const ws = await openExerciseWorkspace(store, exercise, late.id);
        expect(await files(ws.id)).toEqual(STARTER);
        await store.saveFile({ workspaceId: ws.id, path: 'hello/Lamp.arc', content: 'mine\n', authorId: late.id });
        await openExerciseWorkspace(store, exercise, late.id);
        expect((await store.readFile(ws.id, 'hello/Lamp.arc'))?.content).toBe('mine\n');
        expect((await store.history(ws.id, 'hello/Lamp.arc')).length).toBe(2);
    });

    it('an update: untouched files take the new starter, edits merge cleanly, the same lines conflict, read-only files are replaced', async () => {
        const { course: c, teacher, students } = await course(3);
        const [untouched, editor, clasher] = students as [(typeof students)[0], (typeof students)[0], (typeof students)[0]];
        const name = fresh('lamp');
        const folder = writeExercise(dir, name, STARTER);
        const { exercise } = await releaseExercise(store, await loadExercise(folder), { course: c.name, authorId: teacher.id });
        const ws = async (u: { id: number }) => (await store.workspace(u.id, exercise.id)).id;
        const save = async (u: { id: number }, p: string, content: string) =>
            store.saveFile({ workspaceId: await ws(u), path: p, content, authorId: u.id });
        // The editor adds lines below the TODO, the clasher changes the port line; the editor edits the read-only Toggle.
        await save(
            editor,
            'hello/Lamp.arc',
            'package hello;\ncomponent Lamp {\n  port in boolean button;\n\n  // TODO\n\n  Toggle t;\n}\n',
        );
        await save(
            clasher,
            'hello/Lamp.arc',
            'package hello;\ncomponent Lamp {\n  port in boolean button, in boolean extra;\n\n  // TODO\n}\n',
        );
        await save(editor, 'lib/Toggle.arc', 'edited a read-only file\n');
        // The editor also changes the app (the starter does not) and the stream test (the update drops it).
        await save(editor, 'App.arcapp', `${STARTER['App.arcapp']}// mine\n`);
        await save(editor, 'hello/Lamp.stream', 'component hello.Lamp;\n// my test\n');
        // The update: the port line changes, Toggle changes, a new file, the stream test is gone.
        const next: Record<string, string> = {
            ...STARTER,
            'hello/Lamp.arc': 'package hello;\ncomponent Lamp {\n  port in boolean button, out boolean lamp;\n\n  // TODO\n}\n',
            'lib/Toggle.arc': 'package lib;\ncomponent Toggle {\n  port in boolean press;\n}\n',
            'lib/Extra.arc': 'package lib;\ncomponent Extra {\n}\n',
        };
        delete next['hello/Lamp.stream'];
        const manifest = { ...JSON.parse((await import('node:fs')).readFileSync(path.join(folder, 'exercise.json'), 'utf8')), tests: [] };
        rmSync(folder, { recursive: true });
        writeExercise(dir, name, next, manifest);
        const updated = await updateExercise(store, await loadExercise(folder), { course: c.name, authorId: teacher.id });
        expect(updated.newStarter).toBe(true);
        expect(updated.spec.starterVersion).toBe(2);
        expect(specOf(updated.exercise).tests).toEqual([]);

        const outcomes = (login: string) =>
            Object.fromEntries(updated.workspaces.find((w) => w.login === login)?.files.map((f) => [f.path, f.outcome]) ?? []);
        expect(outcomes(untouched.login)).toMatchObject({
            'hello/Lamp.arc': 'replaced',
            'lib/Toggle.arc': 'replaced',
            'lib/Extra.arc': 'added',
            'hello/Lamp.stream': 'removed',
            'App.arcapp': 'unchanged',
        });
        expect(await files(await ws(untouched))).toEqual(next);

        // Clean merge: the new port line and the student's Toggle line; the read-only file is the starter's again.
        expect(outcomes(editor.login)).toMatchObject({
            'hello/Lamp.arc': 'merged',
            'lib/Toggle.arc': 'replaced',
            'App.arcapp': 'unchanged',
            'hello/Lamp.stream': 'kept',
        });
        const edited = await files(await ws(editor));
        expect(edited['hello/Lamp.arc']).toBe(
            'package hello;\ncomponent Lamp {\n  port in boolean button, out boolean lamp;\n\n  // TODO\n\n  Toggle t;\n}\n',
        );
        expect(edited['lib/Toggle.arc']).toBe(next['lib/Toggle.arc']);
        expect(edited['App.arcapp']).toBe(`${STARTER['App.arcapp']}// mine\n`);
        expect(edited['hello/Lamp.stream']).toBe('component hello.Lamp;\n// my test\n');
        expect((await store.history(await ws(editor), 'hello/Lamp.arc')).map((r) => r.authorId)).toEqual([
            teacher.id,
            editor.id,
            teacher.id,
        ]);

        // Conflict: the student's file stays; the markers are beside it; the record says which versions.
        expect(outcomes(clasher.login)).toMatchObject({ 'hello/Lamp.arc': 'conflict' });
        const clashed = await files(await ws(clasher));
        expect(clashed['hello/Lamp.arc']).toBe(
            'package hello;\ncomponent Lamp {\n  port in boolean button, in boolean extra;\n\n  // TODO\n}\n',
        );
        expect(clashed[`hello/Lamp.arc${CONFLICT_SUFFIX}`]).toContain('<<<<<<< your hello/Lamp.arc\n');
        expect(clashed[`hello/Lamp.arc${CONFLICT_SUFFIX}`]).toContain('>>>>>>> starter version 2 (the update)\n');
        const record = (await store.starterFiles(await ws(clasher))).find((f) => f.path === 'hello/Lamp.arc');
        expect(record).toMatchObject({ baseVersion: 1, conflictVersion: 2 });

        // The student resolves it (takes the starter's port line, works below); the next update merges from the old base and clears the conflict.
        await save(
            clasher,
            'hello/Lamp.arc',
            'package hello;\ncomponent Lamp {\n  port in boolean button, out boolean lamp;\n\n  Toggle mine;\n}\n',
        );
        const third = { ...next, 'App.arcapp': `${next['App.arcapp']}// v3\n` };
        rmSync(folder, { recursive: true });
        writeExercise(dir, name, third, manifest);
        const again = await updateExercise(store, await loadExercise(folder), { course: c.name, authorId: teacher.id });
        expect(again.spec.starterVersion).toBe(3);
        const after = await files(await ws(clasher));
        expect(after[`hello/Lamp.arc${CONFLICT_SUFFIX}`]).toBeUndefined();
        expect(after['App.arcapp']).toBe(third['App.arcapp']);
        expect((await store.starterFiles(await ws(clasher))).find((f) => f.path === 'hello/Lamp.arc')).toMatchObject({
            baseVersion: 3,
            conflictVersion: null,
        });
    });

    it('an update with the same starter files keeps the starter version and touches no workspace', async () => {
        const { course: c, teacher } = await course(1);
        const name = fresh('lamp');
        const folder = writeExercise(dir, name, STARTER);
        await releaseExercise(store, await loadExercise(folder), { course: c.name, authorId: teacher.id });
        writeFileSync(path.join(folder, 'description.md'), '# A better description\n');
        const updated = await updateExercise(store, await loadExercise(folder), { course: c.name, authorId: teacher.id });
        expect(updated).toMatchObject({ newStarter: false, workspaces: [] });
        expect(specOf(updated.exercise)).toMatchObject({ starterVersion: 1, description: '# A better description\n' });
    });

    it('refuses an update of an exercise never released and a release to a course that does not exist', async () => {
        const { course: c, teacher } = await course(0);
        const loaded = await loadExercise(writeExercise(dir, fresh('lamp'), STARTER));
        await expect(updateExercise(store, loaded, { course: c.name, authorId: teacher.id })).rejects.toThrow(/release it first/);
        await expect(releaseExercise(store, loaded, { course: 'no-such-course', authorId: teacher.id })).rejects.toThrow(ExerciseError);
    });

    it('maa-lab exercise release and update on a commander program', async () => {
        // The commands open their own store: PGlite's data directory belongs to one process at a time.
        const storage: StorageOptions = await backend.freshStorage();
        const own = await openLabStore(storage);
        const c = await own.createCourse({ name: fresh('course'), title: 'Lab' });
        const teacher = await own.createUser({ login: fresh('teacher'), name: 'T', role: 'instructor' });
        const ada = await own.createUser({ login: fresh('ada'), name: 'Ada', role: 'student' });
        await own.enroll(c.id, teacher.id);
        await own.enroll(c.id, ada.id);
        await own.close();
        const out: string[] = [];
        const io = {
            cwd: dir,
            env: 'databaseUrl' in storage && storage.databaseUrl ? { DATABASE_URL: storage.databaseUrl } : {},
            out: (t: string) => void out.push(t),
        };
        const dataDir = 'dataDir' in storage && storage.dataDir ? ['--data-dir', storage.dataDir] : [];
        const run = (...args: string[]) => {
            const program = new Command('maa-lab').exitOverride();
            registerExerciseCommands(program, io);
            return program.parseAsync(['node', 'maa-lab', ...args, '--course', c.name, ...dataDir]);
        };
        const name = fresh('lamp');
        const folder = writeExercise(dir, name, STARTER);
        await run('exercise', 'release', name);
        expect(out.join('')).toContain(`released ${name} to ${c.name}: 4 starter files, 2 workspaces (${ada.login}, ${teacher.login})`);
        writeExercise(dir, name, { ...STARTER, 'lib/Toggle.arc': 'package lib;\ncomponent Toggle { }\n' });
        out.length = 0;
        await run('exercise', 'update', folder);
        expect(out.join('')).toContain(`updated ${name} in ${c.name}: starter version 2\n`);
        expect(out.join('')).toContain(`  ${ada.login}: lib/Toggle.arc: replaced\n`);
        expect(out.join('')).toContain('2 workspaces, 0 with conflicts\n');
        await expect(run('exercise', 'release', path.join(dir, 'missing'))).rejects.toThrow(/exercise\.json: not found/);
    });
});
