// The instructor's dashboard against a real server on both storage backends: the JSON of a course
// with 2 students × 2 exercises (one workspace with errors, one with its stream tests passed), the
// ETag (an unchanged dashboard is a 304, a save changes it), the CSV, the read-only workspace view,
// the pages under their CSP, and 403 for a student on every dashboard route; the checks in the
// checker thread: a request during a check answers at once with the cells still "checking", a
// crashed thread gives an error cell and the next check a new thread.
import { Worker } from 'node:worker_threads';
import { afterAll, beforeAll, describe, expect, it, vi } from 'vitest';
import { hashPassword } from '../src/auth/passwords.js';
import { buildDashboard, CheckThread, type FileDiagnostic, NO_LIVE_SIMULATIONS, WorkspaceChecker } from '../src/dashboard/index.js';
import { type LabServer, startLabServer } from '../src/http/server.js';
import { type LabStore, openLabStore, type User } from '../src/storage/index.js';
import { BACKENDS, type Backend, startBackend } from './backends.js';
import { Client } from './http-client.js';

const PASSWORD = 'correct horse battery staple';
const GOOD = 'package lamp;\ncomponent Lamp {\n  port in boolean on;\n  port out boolean light;\n}\n';
const BAD = 'package lamp;\ncomponent Lamp {\n  port in boolean on;\n  port out Nope light;\n}\n';
/** checker threads for the crash test (eval'd CommonJS): one that dies on its first check, one that answers */
const CRASHING = "require('node:worker_threads').parentPort.on('message', () => process.exit(7));";
const ANSWERING = `const { parentPort } = require('node:worker_threads');
parentPort.on('message', (m) => parentPort.postMessage({ id: m.id, diagnostics: m.files.map((f) =>
    ({ file: f.path, line: 1, column: 1, severity: 'error', code: 'test/fake', message: 'from the thread' })) }));`;
const WARNING: FileDiagnostic = { file: 'lamp/Lamp.arc', line: 1, column: 1, severity: 'warning', code: 'x/y', message: 'counted' };

describe.each(BACKENDS)('the dashboard on %s', (backendName) => {
    let backend: Backend;
    let store: LabStore;
    let server: LabServer;
    let ada: User;
    let adaLamp: number;

    beforeAll(async () => {
        backend = await startBackend(backendName);
        store = await openLabStore(await backend.freshStorage());
        const passwordHash = await hashPassword(PASSWORD);
        const teacher = await store.createUser({ login: 'teacher', name: 'The Teacher', role: 'instructor', passwordHash });
        ada = await store.createUser({ login: 'ada', name: 'Ada, "the first"', role: 'student', passwordHash });
        const bob = await store.createUser({ login: 'bob', name: 'Bob\nNewline', role: 'student', passwordHash });
        const course = await store.createCourse({ name: 'robotics', title: 'Robotics lab' });
        for (const u of [teacher, ada, bob]) await store.enroll(course.id, u.id);
        const lamp = await store.createExercise({ courseId: course.id, name: 'lamp', spec: { title: 'The lamp' } });
        const tests = await store.createExercise({ courseId: course.id, name: 'tests', spec: { title: 'Stream tests' } });
        await store.releaseExercise(lamp.id);
        await store.releaseExercise(tests.id);
        // ada: the lamp with an error; the tests exercise correct with every stream test passed.
        adaLamp = (await store.workspace(ada.id, lamp.id)).id;
        await store.saveFile({ workspaceId: adaLamp, path: 'lamp/Lamp.arc', content: BAD, authorId: ada.id });
        const adaTests = (await store.workspace(ada.id, tests.id)).id;
        await store.saveFile({ workspaceId: adaTests, path: 'lamp/Lamp.arc', content: GOOD, authorId: ada.id });
        await store.recordTestResult({ workspaceId: adaTests, submissionId: null, passed: 3, failed: 0, skipped: 0, details: null });
        await store.recordSimulationResult({
            workspaceId: adaTests,
            submissionId: null,
            goalReached: true,
            simulatedSeconds: 12,
            details: null,
        });
        // bob: has not opened anything.
        server = await startLabServer({ store, port: 0, log: () => undefined });
    });
    afterAll(async () => {
        await server?.close();
        await store?.close();
        await backend?.dispose();
    });

    async function loggedIn(login: string): Promise<Client> {
        const c = new Client(server.url);
        const answer = await c.login(login, PASSWORD);
        expect(answer.status, answer.text).toBe(200);
        return c;
    }

    /** The dashboard once no cell is checking any more (waits for the server's checker thread between tries). */
    async function complete(c: Client, path: string, headers: Record<string, string> = {}) {
        for (;;) {
            const answer = await c.send(path, { headers });
            if (answer.status !== 200 || !answer.json.cells.some((cell: { checking: boolean }) => cell.checking)) return answer;
            await server.dashboard.settled();
        }
    }

    it('gives the instructor students × exercises with diagnostics, tests, goal and activity', async () => {
        const teacher = await loggedIn('teacher');
        const answer = await complete(teacher, '/api/courses/robotics/dashboard');
        expect(answer.status, answer.text).toBe(200);
        const d = answer.json;
        expect(d.course).toEqual({ name: 'robotics', title: 'Robotics lab' });
        expect(d.exercises).toEqual([
            { name: 'lamp', title: 'The lamp', released: true },
            { name: 'tests', title: 'Stream tests', released: true },
        ]);
        expect(d.students).toEqual([
            { login: 'ada', name: 'Ada, "the first"' },
            { login: 'bob', name: 'Bob\nNewline' },
        ]);
        expect(d.cells.map((c: { student: string; exercise: string }) => `${c.student}/${c.exercise}`)).toEqual([
            'ada/lamp',
            'ada/tests',
            'bob/lamp',
            'bob/tests',
        ]);
        const [adaLampCell, adaTestsCell, bobLamp] = d.cells;
        expect(adaLampCell).toMatchObject({
            workspace: '/api/ws/robotics/lamp/ada',
            diagnostics: { errors: 1, warnings: 0 },
            checking: false,
            checkError: null,
            tests: null,
            simulation: null,
            simulating: false,
        });
        expect(Date.parse(adaLampCell.lastActivity)).not.toBeNaN();
        expect(adaTestsCell).toMatchObject({
            diagnostics: { errors: 0, warnings: 0 },
            tests: { passed: 3, total: 3 },
            simulation: { goalReached: true },
        });
        expect(bobLamp).toEqual({
            student: 'bob',
            exercise: 'lamp',
            workspace: null,
            diagnostics: null,
            checking: false,
            checkError: null,
            tests: null,
            simulation: null,
            lastActivity: null,
            simulating: false,
        });
        expect((await teacher.send('/api/courses/nope/dashboard')).status).toBe(404);
    });

    it('answers an unchanged dashboard with 304 and a changed one with a new ETag', async () => {
        const teacher = await loggedIn('teacher');
        const first = await complete(teacher, '/api/courses/robotics/dashboard');
        const etag = String(first.headers.etag);
        expect(etag).toMatch(/^"[^"]+"$/);
        const again = await teacher.send('/api/courses/robotics/dashboard', { headers: { 'If-None-Match': etag } });
        expect(again.status).toBe(304);
        expect(again.text).toBe('');
        await store.saveFile({ workspaceId: adaLamp, path: 'lamp/Lamp.arc', content: GOOD, authorId: ada.id });
        const changed = await complete(teacher, '/api/courses/robotics/dashboard', { 'If-None-Match': etag });
        expect(changed.status).toBe(200);
        expect(changed.headers.etag).not.toBe(etag);
        expect(changed.json.cells[0].diagnostics).toEqual({ errors: 0, warnings: 0 });
        await store.saveFile({ workspaceId: adaLamp, path: 'lamp/Lamp.arc', content: BAD, authorId: ada.id });
    });

    it("shows a workspace as simulating while the lab's workspaces have its simulation running", async () => {
        const teacher = await loggedIn('teacher');
        // The simulation itself is workspaces-sim.test.ts's (the real maa-sim); here only whether
        // the dashboard asks the server's runtime pool, as server.ts wires it.
        const realFind = server.workspaces.pool.find.bind(server.workspaces.pool);
        const find = vi
            .spyOn(server.workspaces.pool, 'find')
            .mockImplementation((id: number) => (id === adaLamp ? ({ sim: {} } as unknown as ReturnType<typeof realFind>) : realFind(id)));
        try {
            const answer = await teacher.send('/api/courses/robotics/dashboard');
            expect(answer.json.cells.map((c: { simulating: boolean }) => c.simulating)).toEqual([true, false, false, false]);
            const csv = await teacher.send('/api/courses/robotics/results.csv');
            expect(csv.text.split('\r\n')[1]).toMatch(/,yes$/);
        } finally {
            find.mockRestore();
        }
        expect((await teacher.send('/api/courses/robotics/dashboard')).json.cells[0].simulating).toBe(false);
    });

    it('exports one CSV row per student × exercise, names with commas, quotes and newlines quoted', async () => {
        const teacher = await loggedIn('teacher');
        const answer = await teacher.send('/api/courses/robotics/results.csv');
        expect(answer.status).toBe(200);
        expect(answer.headers['content-type']).toBe('text/csv; charset=utf-8');
        expect(answer.headers['content-disposition']).toBe('attachment; filename="robotics-results.csv"');
        const lines = answer.text.split('\r\n');
        expect(lines[0]).toBe('login,name,exercise,errors,warnings,tests_passed,tests_total,goal_reached,last_activity,simulating');
        expect(lines[1]).toMatch(/^ada,"Ada, ""the first""",lamp,1,0,,,,\d{4}-\d\d-\d\dT[^,]+,no$/);
        expect(lines[2]).toMatch(/^ada,"Ada, ""the first""",tests,0,0,3,3,yes,[^,]+,no$/);
        // bob's name holds a newline: one quoted field over two lines of text.
        expect(answer.text).toContain('bob,"Bob\nNewline",lamp,,,,,,,no\r\n');
        expect(answer.text).toContain('bob,"Bob\nNewline",tests,,,,,,,no\r\n');
        expect(answer.text.endsWith('\r\n')).toBe(true);
    });

    it("shows one student's workspace read-only with its files and their diagnostics", async () => {
        const teacher = await loggedIn('teacher');
        const answer = await teacher.send('/api/courses/robotics/dashboard/lamp/ada');
        expect(answer.status, answer.text).toBe(200);
        expect(answer.json).toMatchObject({ course: 'robotics', exercise: 'lamp', student: { login: 'ada' }, errors: 1 });
        expect(answer.json.files).toHaveLength(1);
        expect(answer.json.files[0]).toMatchObject({ path: 'lamp/Lamp.arc', content: BAD });
        expect(answer.json.files[0].diagnostics).toEqual([
            expect.objectContaining({ line: 4, severity: 'error', code: 'arc/unresolved-type' }),
        ]);
        expect((await teacher.send('/api/courses/robotics/dashboard/lamp/bob')).status).toBe(404);
        expect((await teacher.send('/api/courses/robotics/dashboard/lamp/nobody')).status).toBe(404);
    });

    it('serves the pages under the strict CSP, their script from /lab-assets', async () => {
        const teacher = await loggedIn('teacher');
        for (const path of ['/dashboard', '/dashboard/robotics', '/dashboard/robotics/lamp/ada']) {
            const page = await teacher.send(path, { headers: { Accept: 'text/html' } });
            expect(page.status).toBe(200);
            expect(page.headers['content-security-policy']).toContain("script-src 'self'");
            expect(page.headers['content-security-policy']).not.toContain('unsafe-eval');
            expect(page.text).toContain('<script src="/lab-assets/dashboard.js" defer></script>');
            expect(page.text).not.toMatch(/<script>/);
        }
        // Without a session the pages lead to the login page.
        const anonymous = await new Client(server.url).send('/dashboard/robotics', { headers: { Accept: 'text/html' } });
        expect(anonymous.status).toBe(302);
        expect(anonymous.headers.location).toBe('/login');
    });

    it('refuses a student every dashboard route (403)', async () => {
        const student = await loggedIn('ada');
        for (const path of [
            '/api/courses/robotics/dashboard',
            '/api/courses/robotics/results.csv',
            '/api/courses/robotics/dashboard/lamp/ada',
            '/api/courses/robotics/dashboard/lamp/bob',
            '/dashboard',
            '/dashboard/robotics',
            '/dashboard/robotics/lamp/ada',
        ]) {
            const answer = await student.send(path, { headers: { Accept: 'text/html' } });
            expect(answer.status, path).toBe(403);
            expect(answer.text, path).not.toContain('Lamp');
        }
        // and without a session: 401
        expect((await new Client(server.url).send('/api/courses/robotics/dashboard')).status).toBe(401);
        expect((await new Client(server.url).send('/api/courses/robotics/results.csv')).status).toBe(401);
    });

    it('checks a workspace again only when its files changed (cached by revision)', async () => {
        const seen: string[] = [];
        const checker = new WorkspaceChecker(
            store,
            async (files) => {
                seen.push(files.map((f) => f.path).join(' '));
                return files.map(() => WARNING);
            },
            { recheckMs: 0 }, // every poll re-checks a changed workspace (the interval has its own tests below)
        );
        const live = { isSimulating: (id: number) => id === adaLamp };
        await buildDashboard({ store, checker, live }, 'robotics');
        await checker.settled();
        expect(seen).toHaveLength(2); // ada's two workspaces; bob has none
        const first = await buildDashboard({ store, checker, live }, 'robotics');
        expect(first.cells[0]).toMatchObject({ diagnostics: { errors: 0, warnings: 1 }, checking: false, simulating: true });
        expect(first.cells[1]?.simulating).toBe(false);
        await Promise.all([buildDashboard({ store, checker, live }, 'robotics'), buildDashboard({ store, checker, live }, 'robotics')]);
        expect(seen).toHaveLength(2);
        expect(checker.checksRun).toBe(2);
        await store.saveFile({ workspaceId: adaLamp, path: 'lamp/Other.arc', content: GOOD, authorId: ada.id });
        const changed = await buildDashboard({ store, checker, live }, 'robotics');
        // the files last checked while the new ones are
        expect(changed.cells[0]).toMatchObject({ diagnostics: { errors: 0, warnings: 1 }, checking: true });
        await checker.settled();
        expect(seen).toHaveLength(3);
        expect(seen[2]?.split(' ').sort()).toEqual(['lamp/Lamp.arc', 'lamp/Other.arc']);
        expect((await buildDashboard({ store, checker, live }, 'robotics')).cells[0]).toMatchObject({
            diagnostics: { errors: 0, warnings: 2 },
            checking: false,
        });
        await store.deleteFile({ workspaceId: adaLamp, path: 'lamp/Other.arc', authorId: ada.id });
    });

    it('answers at once during a long check with the cells still checking, one workspace at a time, then the complete data', async () => {
        let release: () => void = () => undefined;
        const gate = new Promise<void>((resolve) => {
            release = resolve;
        });
        let active = 0;
        let mostActive = 0;
        const checker = new WorkspaceChecker(store, async (files) => {
            active++;
            mostActive = Math.max(mostActive, active);
            await gate;
            active--;
            return files.map(() => ({ ...WARNING, severity: 'error' as const }));
        });
        const sources = { store, checker, live: NO_LIVE_SIMULATIONS };
        const pending = await buildDashboard(sources, 'robotics');
        expect(pending.cells.map((c) => [c.checking, c.diagnostics])).toEqual([
            [true, null],
            [true, null],
            [false, null], // bob: no workspace
            [false, null],
        ]);
        // a second request while the check still runs answers too
        expect((await buildDashboard(sources, 'robotics')).cells[0]?.checking).toBe(true);
        release();
        await checker.settled();
        expect(mostActive).toBe(1);
        expect(checker.checksRun).toBe(2);
        const done = await buildDashboard(sources, 'robotics');
        expect(done.cells.slice(0, 2).map((c) => [c.checking, c.diagnostics, c.checkError])).toEqual([
            [false, { errors: 1, warnings: 0 }, null],
            [false, { errors: 1, warnings: 0 }, null],
        ]);
    });

    it('gives an error cell when the checker thread crashes, and a new thread checks the next time', async () => {
        let spawned = 0;
        const thread = new CheckThread(() => new Worker(++spawned === 1 ? CRASHING : ANSWERING, { eval: true }));
        const checker = new WorkspaceChecker(store, (files) => thread.check(files));
        const sources = { store, checker, live: NO_LIVE_SIMULATIONS };
        try {
            expect((await buildDashboard(sources, 'robotics')).cells[0]?.checking).toBe(true);
            await checker.settled();
            // ada's lamp was the crashed thread's check; her tests workspace the new thread's
            const failed = await buildDashboard(sources, 'robotics');
            expect(failed.cells[0]).toMatchObject({
                checking: false,
                diagnostics: null,
                checkError: expect.stringContaining('exit code 7'),
            });
            expect(failed.cells[1]).toMatchObject({ checking: false, diagnostics: { errors: 1, warnings: 0 }, checkError: null });
            expect(spawned).toBe(2);
            // the next request checks the failed workspace again
            expect((await buildDashboard(sources, 'robotics')).cells[0]).toMatchObject({ checking: true, checkError: null });
            await checker.settled();
            const again = await buildDashboard(sources, 'robotics');
            expect(again.cells[0]).toMatchObject({ checking: false, diagnostics: { errors: 1, warnings: 0 }, checkError: null });
            expect(spawned).toBe(2);
        } finally {
            await thread.close();
        }
    });

    it('coalesces the polls’ re-checks: one check per interval, of the files as they are then; a view checks at once', async () => {
        const seen: string[][] = [];
        const checker = new WorkspaceChecker(
            store,
            async (files) => {
                seen.push(files.map((f) => f.path).sort());
                return files.map(() => WARNING);
            },
            { recheckMs: 3_600_000 },
        );
        const sources = { store, checker, live: NO_LIVE_SIMULATIONS };
        const added = ['lamp/A.arc', 'lamp/B.arc', 'lamp/C.arc'];
        try {
            await buildDashboard(sources, 'robotics');
            await checker.settled();
            expect(checker.checksRun).toBe(2); // ada's two workspaces, checked at once the first time
            // three saves, each followed by a poll: within the interval no check runs, the cell says checking
            for (const file of added) {
                await store.saveFile({ workspaceId: adaLamp, path: file, content: GOOD, authorId: ada.id });
                const polled = await buildDashboard(sources, 'robotics');
                expect(polled.cells[0]).toMatchObject({ checking: true, diagnostics: { errors: 0, warnings: 1 } });
                expect(polled.cells[1]).toMatchObject({ checking: false });
            }
            expect(checker.checksRun).toBe(2);
            // what waits for the workspace (the read-only view, the CSV) checks now: once, the newest files
            const now = await checker.check(adaLamp);
            expect(checker.checksRun).toBe(3);
            expect(now.warnings).toBe(4);
            expect(seen.at(-1)).toEqual([...added, 'lamp/Lamp.arc']);
            await checker.settled();
            expect(checker.checksRun).toBe(3);
            expect((await buildDashboard(sources, 'robotics')).cells[0]).toMatchObject({ checking: false, diagnostics: { warnings: 4 } });
        } finally {
            await checker.close();
            for (const file of added) await store.deleteFile({ workspaceId: adaLamp, path: file, authorId: ada.id });
        }
    });

    it('runs a re-check that waited for its interval by itself, and drops a waiting one when closed', async () => {
        const seen: string[][] = [];
        const checkFiles = async (files: readonly { path: string }[]) => {
            seen.push(files.map((f) => f.path).sort());
            return files.map(() => WARNING);
        };
        const checker = new WorkspaceChecker(store, checkFiles, { recheckMs: 100 });
        const sources = { store, checker, live: NO_LIVE_SIMULATIONS };
        try {
            await buildDashboard(sources, 'robotics');
            await checker.settled();
            await store.saveFile({ workspaceId: adaLamp, path: 'lamp/D.arc', content: GOOD, authorId: ada.id });
            await buildDashboard(sources, 'robotics');
            await store.saveFile({ workspaceId: adaLamp, path: 'lamp/E.arc', content: GOOD, authorId: ada.id });
            await buildDashboard(sources, 'robotics');
            await checker.settled(); // the interval's timer queued it (no further poll)
            expect(seen.at(-1)).toEqual(['lamp/D.arc', 'lamp/E.arc', 'lamp/Lamp.arc']);
            expect((await buildDashboard(sources, 'robotics')).cells[0]).toMatchObject({ checking: false, diagnostics: { warnings: 3 } });
        } finally {
            await checker.close();
        }
        // a check waiting for a long interval is dropped by close() (settled() does not wait for it)
        const slow = new WorkspaceChecker(store, checkFiles, { recheckMs: 3_600_000 });
        await slow.check(adaLamp);
        await store.saveFile({ workspaceId: adaLamp, path: 'lamp/F.arc', content: GOOD, authorId: ada.id });
        expect((await buildDashboard({ store, checker: slow, live: NO_LIVE_SIMULATIONS }, 'robotics')).cells[0]?.checking).toBe(true);
        await slow.close();
        await slow.settled();
        // ada's lamp once (the view), her other workspace once (the poll); the lamp's re-check was dropped
        expect(slow.checksRun).toBe(2);
        for (const file of ['lamp/D.arc', 'lamp/E.arc', 'lamp/F.arc'])
            await store.deleteFile({ workspaceId: adaLamp, path: file, authorId: ada.id });
    });
});
