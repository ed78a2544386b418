// Students' workspaces over HTTP on both storage backends (docs/lab.md "Workspaces", "Quotas"):
// the IDE's file routes on the database (every save a revision, read-only exercise files
// refused), each access rule attacked through every route (a student on another's workspace,
// no session, an instructor's writes, the reset), the workspace quotas, and generation and the
// stream tests on the materialized folder with their results in LabStore.
import { existsSync, readdirSync } from 'node:fs';
import path from 'node:path';
import { afterAll, beforeAll, describe, expect, it, vi } from 'vitest';
import { BACKENDS, type Backend, startBackend } from './backends.js';
import { Client } from './http-client.js';
import { del, EXERCISE, type Lab, PYTHON, put, startLab } from './workspace-setup.js';

/** The starter of toast-controller: 20 files, 16 520 bytes. */
const QUOTAS = { workspaceFiles: 23, workspaceBytes: 16_520 + 4_000 };

describe.each(BACKENDS)('students’ workspaces over HTTP on %s', (backendName) => {
    let backend: Backend;
    let lab: Lab;
    let ada: Client;
    let bob: Client;
    let teacher: Client;

    beforeAll(async () => {
        vi.stubEnv('MAA_PYTHON', PYTHON);
        backend = await startBackend(backendName);
        lab = await startLab(await backend.freshStorage(), { workspaces: { quotas: QUOTAS } });
        [ada, bob, teacher] = await Promise.all(['ada', 'bob', 'teacher'].map((l) => lab.as(l)));
    }, 120_000);
    afterAll(async () => {
        await lab?.dispose();
        await backend?.dispose();
        vi.unstubAllEnvs();
    });

    const wsId = async (login: string) => {
        const user = await lab.store.findUserByLogin(login);
        const course = await lab.store.findCourse('robotics');
        const exercise = await lab.store.findExercise(course!.id, EXERCISE);
        return (await lab.store.workspace(user!.id, exercise!.id)).id;
    };

    it('lists, reads and saves the owner’s files in the database, every save a revision', async () => {
        const files = await ada.send(`${lab.ws('ada')}/files`);
        expect(files.status, files.text).toBe(200);
        expect(files.json.root).toBe(EXERCISE);
        expect(files.json.entries).toContainEqual({ path: 'toast', type: 'directory' });
        const controller = files.json.entries.find((e: { path: string }) => e.path === 'toast/Controller.arc');
        expect(controller).toMatchObject({ type: 'file' });
        const before = await ada.send(`${lab.ws('ada')}/file?path=toast/Controller.arc`);
        expect(before.status).toBe(200);
        expect(before.text.length).toBe(controller.size);
        const saved = await put(ada, `${lab.ws('ada')}/file?path=toast/Controller.arc`, `${before.text}\n// ada was here\n`);
        expect(saved.status, saved.text).toBe(200);
        expect(saved.json).toEqual({ ok: true });
        expect((await ada.send(`${lab.ws('ada')}/file?path=toast/Controller.arc`)).text).toContain('ada was here');
        const history = await lab.store.history(await wsId('ada'), 'toast/Controller.arc');
        expect(history.map((h) => h.revision)).toEqual([2, 1]);
        const created = await put(ada, `${lab.ws('ada')}/file?path=notes/todo.txt`, 'write the controller\n');
        expect(created.status).toBe(200);
        expect((await ada.send(`${lab.ws('ada')}/files`)).json.entries).toContainEqual({ path: 'notes', type: 'directory' });
        expect((await del(ada, `${lab.ws('ada')}/file?path=notes`)).status).toBe(200);
        expect((await ada.send(`${lab.ws('ada')}/file?path=notes/todo.txt`)).status).toBe(404);
        expect((await lab.store.history(await wsId('ada'), 'notes/todo.txt'))[0]?.deleted).toBe(true);
    });

    it('refuses the exercise’s read-only files with a clear 403, and paths that are not workspace paths', async () => {
        for (const answer of [
            await put(ada, `${lab.ws('ada')}/file?path=TR.arcapp`, 'application X'),
            await put(ada, `${lab.ws('ada')}/file?path=toast/types/New.cd`, 'classdiagram New {}'),
            await del(ada, `${lab.ws('ada')}/file?path=toast/types/Types.cd`),
            await del(ada, `${lab.ws('ada')}/file?path=toast`),
        ]) {
            expect(answer.status, answer.text).toBe(403);
            expect(answer.json.error).toMatch(/is part of the exercise toast-controller and read-only/);
        }
        expect((await ada.send(`${lab.ws('ada')}/file?path=TR.arcapp`)).text).not.toBe('application X');
        expect((await put(ada, `${lab.ws('ada')}/file?path=../escape.txt`, 'x')).status).toBe(400);
        expect((await put(ada, `${lab.ws('ada')}/file?path=a//b.txt`, 'x')).status).toBe(400);
        expect((await put(ada, `${lab.ws('ada')}/file?path=.git/hooks/pre-commit`, 'x')).status).toBe(403);
        expect((await put(ada, `${lab.ws('ada')}/file`, 'x')).status).toBe(400);
        expect((await ada.send(`${lab.ws('ada')}/file?path=toast/Nothing.arc`)).status).toBe(404);
        const binary = await ada.send(`${lab.ws('ada')}/file?path=blob.bin`, {
            method: 'PUT',
            raw: '\u00ff',
            headers: { 'X-CSRF-Token': ada.csrf!, 'Content-Type': 'application/octet-stream' },
        });
        expect(binary.status).toBe(200); // U+00FF sent as UTF-8 is text
    });

    /** Every route of a workspace, with a body where it takes one. */
    const everyRoute = (ws: string): Array<[string, string, unknown?]> => [
        ['GET', ws],
        ['GET', `${ws}/files`],
        ['GET', `${ws}/file?path=toast/Controller.arc`],
        ['PUT', `${ws}/file?path=toast/Controller.arc`, 'component Controller {}'],
        ['DELETE', `${ws}/file?path=toast/Controller.arc`],
        ['GET', `${ws}/apps`],
        ['POST', `${ws}/generate`, { app: 'TR.arcapp', platform: 'timesync' }],
        ['GET', `${ws}/generated/file?app=TR.arcapp&platform=timesync&path=app.py`],
        ['GET', `${ws}/generated/trace?app=TR.arcapp&platform=timesync`],
        ['POST', `${ws}/test`, { app: 'TR.arcapp' }],
        ['POST', `${ws}/sim/start`, { app: 'TR.arcapp', platform: 'timesync' }],
        ['GET', `${ws}/sim/topics?app=TR.arcapp&platform=timesync`],
        ['GET', `${ws}/sim/status`],
        ['POST', `${ws}/sim/stop`, {}],
        ['GET', `${ws}/sim/viser/`],
        ['GET', `${ws}/sim/viser/index.html`],
        ['GET', `${ws}/sim/rosbridge`],
        ['POST', `${ws}/reset`, {}],
    ];
    const send = (c: Client, [method, url, body]: [string, string, unknown?]) =>
        c.send(url, {
            method,
            ...(typeof body === 'string' ? { raw: body } : body !== undefined ? { body } : {}),
            headers: c.csrf ? { 'X-CSRF-Token': c.csrf } : {},
        });

    it('gives a student nothing of another student’s workspace, through every route (403)', async () => {
        const before = await lab.store.listFiles(await wsId('ada'));
        for (const route of everyRoute(lab.ws('ada'))) {
            const answer = await send(bob, route);
            expect(answer.status, `${route[0]} ${route[1]}: ${answer.text}`).toBe(route[1].endsWith('/reset') ? 403 : 403);
            expect(answer.text).not.toContain('component Controller');
        }
        // Nor of a workspace that does not exist (the answer does not tell).
        expect((await bob.send(lab.ws('nobody'))).status).toBe(403);
        expect(await lab.store.listFiles(await wsId('ada'))).toEqual(before);
    });

    it('refuses every route without a session (401) and every write without the CSRF token (403)', async () => {
        const anonymous = new Client(lab.server.url);
        for (const route of everyRoute(lab.ws('ada'))) expect((await send(anonymous, route)).status, route[1]).toBe(401);
        const forged = new Client(lab.server.url);
        for (const [k, v] of ada.cookies) forged.cookies.set(k, v);
        for (const route of everyRoute(lab.ws('ada')).filter(([m]) => m !== 'GET'))
            expect((await send(forged, route)).status, route[1]).toBe(403);
    });

    it('lets an instructor read any workspace but write none of it (403) except a reset', async () => {
        const info = await teacher.send(lab.ws('ada'));
        expect(info.status).toBe(200);
        expect(info.json).toMatchObject({ owner: 'ada', writable: false, exercise: EXERCISE });
        expect((await teacher.send(`${lab.ws('ada')}/file?path=toast/Controller.arc`)).text).toContain('ada was here');
        expect((await teacher.send(`${lab.ws('ada')}/files`)).status).toBe(200);
        for (const route of everyRoute(lab.ws('ada')).filter(([m, url]) => m !== 'GET' && !url.endsWith('/reset'))) {
            const answer = await send(teacher, route);
            expect(answer.status, `${route[0]} ${route[1]}`).toBe(403);
            expect(answer.json.error).toMatch(/read-only/);
        }
        for (const path of ['sim/viser/', 'sim/rosbridge']) expect((await teacher.send(`${lab.ws('ada')}/${path}`)).status).toBe(403);
        // A student cannot reset, not even their own workspace.
        expect((await send(ada, ['POST', `${lab.ws('ada')}/reset`, {}])).status).toBe(403);
        // Not enrolled, or no such exercise: 404.
        expect((await teacher.send(lab.ws('nobody'))).status).toBe(404);
        expect((await teacher.send('/api/ws/robotics/no-exercise/ada/files')).status).toBe(404);
    });

    it('resets a workspace to the starter as new revisions, keeping the history', async () => {
        const id = await wsId('ada');
        await put(ada, `${lab.ws('ada')}/file?path=extra.txt`, 'mine');
        const reset = await send(teacher, ['POST', `${lab.ws('ada')}/reset`, {}]);
        expect(reset.status, reset.text).toBe(200);
        expect(reset.json.saved).toEqual(['toast/Controller.arc']);
        expect(reset.json.deleted).toEqual(expect.arrayContaining(['extra.txt', 'blob.bin']));
        const starter = await lab.store.starterVersion(
            (await lab.store.findExercise((await lab.store.findCourse('robotics'))!.id, EXERCISE))!.id,
        );
        expect((await ada.send(`${lab.ws('ada')}/file?path=toast/Controller.arc`)).text).toBe(starter!.files['toast/Controller.arc']);
        expect((await ada.send(`${lab.ws('ada')}/file?path=extra.txt`)).status).toBe(404);
        const history = await lab.store.history(id, 'toast/Controller.arc');
        expect(history.map((h) => h.revision)).toEqual([3, 2, 1]);
        expect((await lab.store.readFile(id, 'toast/Controller.arc', 2))?.content).toContain('ada was here');
        // Reset twice: nothing left to change.
        expect((await send(teacher, ['POST', `${lab.ws('ada')}/reset`, {}])).json).toMatchObject({ saved: [], deleted: [] });
    });

    it('refuses a save past the workspace’s bytes or files with 413 naming the limit', async () => {
        const big = await put(bob, `${lab.ws('bob')}/file?path=big.txt`, 'x'.repeat(5_000));
        expect(big.status, big.text).toBe(413);
        expect(big.json).toMatchObject({ limit: 'workspaceBytes', value: QUOTAS.workspaceBytes });
        expect(big.json.error).toMatch(/at most 20520 bytes/);
        for (const name of ['a', 'b', 'c']) expect((await put(bob, `${lab.ws('bob')}/file?path=${name}.txt`, name)).status).toBe(200);
        const tooMany = await put(bob, `${lab.ws('bob')}/file?path=d.txt`, 'd');
        expect(tooMany.status).toBe(413);
        expect(tooMany.json).toMatchObject({ limit: 'workspaceFiles', value: 23 });
        expect(tooMany.json.error).toMatch(/at most 23 files/);
        // Replacing a file is no new file; deleting one frees room.
        expect((await put(bob, `${lab.ws('bob')}/file?path=a.txt`, 'aa')).status).toBe(200);
        expect((await del(bob, `${lab.ws('bob')}/file?path=a.txt`)).status).toBe(200);
        expect((await put(bob, `${lab.ws('bob')}/file?path=d.txt`, 'd')).status).toBe(200);
        expect((await lab.store.workspaceSize(await wsId('bob'))).files).toBe(23);
    });

    it('generates and runs the stream tests on the materialized folder, recording the results', async () => {
        const apps = await ada.send(`${lab.ws('ada')}/apps`);
        expect(apps.status, apps.text).toBe(200);
        expect(apps.json.apps.map((a: { path: string }) => a.path)).toEqual(['TR.arcapp']);
        expect((await send(ada, ['POST', `${lab.ws('ada')}/generate`, { app: 'TR.arcapp', platform: 'nope' }])).status).toBe(403);
        const generated = await send(ada, ['POST', `${lab.ws('ada')}/generate`, { app: 'TR.arcapp', platform: 'timesync' }]);
        expect(generated.status, generated.text).toBe(200);
        expect(generated.json.files.length).toBeGreaterThan(0);
        expect(generated.text).not.toContain(lab.dataDir);
        const file = await ada.send(`${lab.ws('ada')}/generated/file?app=TR.arcapp&platform=timesync&path=${generated.json.files[0].path}`);
        expect(file.status, file.text).toBe(200);
        // The folder holds the database's files, rewritten on change.
        const id = await wsId('ada');
        const folder = path.join(lab.dataDir, 'workspaces', String(id), EXERCISE);
        expect(readdirSync(folder).sort()).toEqual(['TR.arcapp', 'maa.json', 'toast']);
        const tests = await send(ada, ['POST', `${lab.ws('ada')}/test`, { app: 'TR.arcapp' }]);
        expect(tests.status, tests.text).toBe(200);
        expect(tests.json.ok, tests.text).toBe(true);
        const recorded = await lab.store.latestTestResult(id);
        expect(recorded).toMatchObject({ passed: tests.json.summary.passed, failed: tests.json.summary.failed });
        expect(tests.json.results.length).toBeGreaterThan(0);
        const info = await ada.send(lab.ws('ada'));
        expect(info.json.latestTests).toMatchObject({ passed: tests.json.summary.passed, failed: tests.json.summary.failed });
        // A workspace nobody uses loses its folder.
        const runtime = lab.server.workspaces.pool.find(id)!;
        runtime.lastUsed = 0;
        await lab.server.workspaces.pool.removeIdle();
        expect(existsSync(folder)).toBe(false);
        expect((await ada.send(`${lab.ws('ada')}/apps`)).status).toBe(200);
        expect(existsSync(folder)).toBe(true);
    }, 300_000);
});
