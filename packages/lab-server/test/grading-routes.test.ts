// The grading routes over HTTP (docs/lab.md "Grading") with a grading engine of the test's own
// (it scores what the submission's files say, and writes a recording): a student's submit and
// grade, the instructor's course grading, progress, results, CSV, recordings, and the attacks
// (another student's results, run and recording, a student starting a course grading, a
// recording name that walks out of its folder, no session, no CSRF token, a foreign Origin).
// The real engine runs in grading-run.test.ts.
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { BACKENDS, type Backend, startBackend } from './backends.js';
import { engine, releaseHeld } from './grading-engine.js';
import type { Client } from './http-client.js';
import { COURSE, EXERCISE, type Lab, put, startLab, until } from './workspace-setup.js';

const SPEC = {
    format: 'maa-grading/1',
    criteria: [
        { id: 'no-errors', title: 'The model has no errors', kind: 'diagnostics', weight: 10 },
        { id: 'hidden-tests', title: 'Hidden stream tests', kind: 'tests', weight: 30, files: ['Controller.hidden.stream'] },
    ],
};

describe.each(BACKENDS)('grading routes on %s', (backendName) => {
    let backend: Backend;
    let lab: Lab;
    let ada: Client;
    let bob: Client;
    let teacher: Client;
    const base = `/api/courses/${COURSE}/exercises/${EXERCISE}/grading`;

    beforeAll(async () => {
        backend = await startBackend(backendName);
        lab = await startLab(await backend.freshStorage(), { grading: { engine } });
        const course = await lab.store.findCourse(COURSE);
        const exercise = await lab.store.findExercise(course!.id, EXERCISE);
        await lab.store.setExerciseGrading(exercise!.id, { spec: SPEC, files: { 'Controller.hidden.stream': 'hidden test\n' } });
        // toast-copy stays without grading (the examples' toast-controller has a grading/ folder).
        await lab.store.deleteExerciseGrading((await lab.store.findExercise(course!.id, 'toast-copy'))!.id);
        [ada, bob, teacher] = await Promise.all(['ada', 'bob', 'teacher'].map((l) => lab.as(l)));
    }, 120_000);
    afterAll(async () => {
        await lab?.dispose();
        await backend?.dispose();
    });

    const controller = (c: Client, who: string, text: string) =>
        put(c, `${lab.ws(who)}/file?path=toast/Controller.arc`, `package toast;\ncomponent Controller {}\n${text}\n`);
    const finished = async (c: Client, url: string) => {
        let run: { status: string } = { status: 'queued' };
        await until(async () => {
            const answer = await c.send(url);
            run = answer.json.run;
            return run.status === 'done' || run.status === 'failed';
        }, `the run ${url}`);
        return run;
    };

    it("grades a student's submission: the run, its progress, the grade with feedback, the recording", async () => {
        expect((await controller(ada, 'ada', '// correct')).status).toBe(200);
        const submitted = await ada.post(`${lab.ws('ada')}/grading/submit`);
        expect(submitted.status, submitted.text).toBe(202);
        expect(submitted.json.run).toMatchObject({ kind: 'submission', total: 1, url: `${base}/runs/${submitted.json.run.id}` });
        const run = await finished(ada, submitted.json.run.url);
        expect(run).toMatchObject({ status: 'done', done: 1, total: 1, error: null });
        const mine = await ada.send(`${lab.ws('ada')}/grading`);
        expect(mine.status).toBe(200);
        expect(mine.json.graded).toBe(true);
        expect(mine.json.latest).toMatchObject({
            score: 10,
            maxScore: 40,
            student: { login: 'ada' },
            submission: submitted.json.submission,
        });
        expect(mine.json.latest.criteria[1].feedback[0]).toMatchObject({ element: { file: 'toast/Controller.arc', line: 3 } });
        const [recording] = mine.json.latest.recordings;
        expect(recording.scenario).toBe('standard');
        const download = await ada.send(recording.url);
        expect(download.status).toBe(200);
        expect(download.text).toBe(`mcap of ${submitted.json.submission}`);
        expect(download.headers['content-disposition']).toMatch(/^attachment; filename="standard-\d+\.mcap"$/);
        // Through the IDE's paths too.
        const viaIde = await ada.send(`/ide/${COURSE}/${EXERCISE}/ada/api/grading`);
        expect(viaIde.json.latest.score).toBe(10);
        // No absolute path of the server's folders in any answer.
        expect(mine.text).not.toContain(lab.dataDir);
    });

    it("keeps students apart: another's results, run and recording are 403, a course grading is an instructor's", async () => {
        const [adaRecording] = (await ada.send(`${lab.ws('ada')}/grading`)).json.latest.recordings;
        const adaRun = (await ada.send(`${lab.ws('ada')}/grading`)).json.run;
        expect((await bob.send(`${lab.ws('ada')}/grading`)).status).toBe(403);
        expect((await bob.post(`${lab.ws('ada')}/grading/submit`)).status).toBe(403);
        expect((await bob.send(adaRecording.url)).status).toBe(403);
        expect((await bob.send(adaRun.url)).status).toBe(403);
        expect((await bob.post(`${base}/runs`)).status).toBe(403);
        expect((await bob.send(`${base}/results.csv`)).status).toBe(403);
        const bobsResults = await bob.send(base);
        expect(bobsResults.status).toBe(200);
        expect(bobsResults.json.results).toEqual([]);
        expect(bobsResults.json.runs).toEqual([]);
        // An instructor sees ada's workspace read-only: no submission in her name.
        expect((await teacher.post(`${lab.ws('ada')}/grading/submit`)).status).toBe(403);
        expect((await teacher.send(adaRecording.url)).status).toBe(200);
    });

    it('refuses recording names that walk out of their folder, unknown results, and requests without session, token or with a foreign Origin', async () => {
        const [recording] = (await ada.send(`${lab.ws('ada')}/grading`)).json.latest.recordings;
        const result = recording.url.split('/')[4];
        for (const name of ['..%2F..%2F..%2Fetc%2Fpasswd', '..%2Fstandard.mcap', '%2E%2E', 'standard.mcap%00', 'other.mcap']) {
            const answer = await ada.send(`/api/grading/results/${result}/recordings/${name}`);
            expect([400, 404], `${name}: ${answer.status}`).toContain(answer.status);
        }
        expect((await ada.send(`/api/grading/results/${result}/recordings/../../../../etc/passwd`)).status).toBe(404);
        expect((await ada.send('/api/grading/results/999999/recordings/standard.mcap')).status).toBe(404);
        expect((await ada.send('/api/grading/results/abc/recordings/standard.mcap')).status).toBe(404);
        const { Client } = await import('./http-client.js');
        const anonymous = new Client(lab.server.url);
        expect((await anonymous.send(recording.url)).status).toBe(401);
        expect((await anonymous.send(base)).status).toBe(401);
        const noToken = await teacher.send(`${base}/runs`, { body: {} });
        expect(noToken.status).toBe(403);
        const foreign = await teacher.post(`${base}/runs`, {}, { Origin: 'http://evil.example' });
        expect(foreign.status).toBe(403);
    });

    it("grades every student's latest submission for the instructor: progress, results, CSV", async () => {
        await controller(bob, 'bob', '// correct // tested');
        const bobFirst = await bob.post(`${lab.ws('bob')}/grading/submit`);
        await finished(bob, bobFirst.json.run.url);
        await controller(ada, 'ada', '// tested');
        await ada.post(`${lab.ws('ada')}/grading/submit`).then((a) => finished(ada, a.json.run.url));
        const started = await teacher.post(`${base}/runs`);
        expect(started.status, started.text).toBe(202);
        expect(started.json.run).toMatchObject({ kind: 'course', total: 2 });
        expect(await finished(teacher, started.json.run.url)).toMatchObject({ status: 'done', done: 2, total: 2 });
        const all = await teacher.send(base);
        expect(all.json.criteria.map((c: { id: string }) => c.id)).toEqual(['no-errors', 'hidden-tests']);
        expect(
            all.json.results.map((r: { student: { login: string }; score: number; run: number }) => [r.student.login, r.score, r.run]),
        ).toEqual([
            ['ada', 30, started.json.run.id],
            ['bob', 40, started.json.run.id],
        ]);
        expect(all.json.runs[0]).toMatchObject({ id: started.json.run.id, status: 'done' });
        const csv = await teacher.send(`${base}/results.csv`);
        expect(csv.status).toBe(200);
        expect(csv.headers['content-disposition']).toBe(`attachment; filename="${COURSE}-${EXERCISE}-grades.csv"`);
        const lines = csv.text.split('\r\n');
        expect(lines[0]).toBe('login,name,submission,graded_at,no-errors,hidden-tests,score,max_score');
        expect(lines[1]).toMatch(/^ada,ada,\d+,[^,]+,0,30,30,40$/);
        expect(lines[2]).toMatch(/^bob,bob,\d+,[^,]+,10,30,40,40$/);
        // ada reads her own newest result (the course run's), not bob's.
        const own = await ada.send(base);
        expect(own.json.results.map((r: { student: { login: string } }) => r.student.login)).toEqual(['ada']);
        expect(own.json.csv).toBeNull();
    });

    it('ends a failing grading as failed with its error, and the next one still runs', async () => {
        await controller(ada, 'ada', '// explode');
        const failed = await ada.post(`${lab.ws('ada')}/grading/submit`);
        expect(await finished(ada, failed.json.run.url)).toMatchObject({ status: 'failed', error: 'the engine failed on purpose' });
        await controller(ada, 'ada', '// correct // tested');
        const next = await ada.post(`${lab.ws('ada')}/grading/submit`);
        expect(await finished(ada, next.json.run.url)).toMatchObject({ status: 'done' });
        expect((await ada.send(`${lab.ws('ada')}/grading`)).json.latest.score).toBe(40);
    });

    it('takes one grading at a time per student and one course grading at a time: 409 while one waits or runs', async () => {
        await controller(bob, 'bob', '// hold');
        const first = await bob.post(`${lab.ws('bob')}/grading/submit`);
        expect(first.status).toBe(202);
        const again = await bob.post(`${lab.ws('bob')}/grading/submit`);
        expect(again.status).toBe(409);
        expect(again.json.error).toMatch(/your last submission is still being graded/);
        // ada's submission waits behind bob's (one run at a time per exercise), then runs.
        const ada1 = await ada.post(`${lab.ws('ada')}/grading/submit`);
        expect(ada1.status).toBe(202);
        const course = await teacher.post(`${base}/runs`);
        expect(course.status).toBe(202);
        expect((await teacher.post(`${base}/runs`)).status).toBe(409);
        expect((await ada.send(ada1.json.run.url)).json.run.status).toBe('queued');
        await until(() => releaseHeld() > 0, "bob's grading to wait");
        await finished(bob, first.json.run.url);
        // The course run grades bob's held submission again: let it go too.
        await until(async () => {
            releaseHeld();
            return (await teacher.send(course.json.run.url)).json.run.status === 'done';
        }, 'the course run');
        expect((await ada.send(ada1.json.run.url)).json.run.status).toBe('done');
    });

    it('says 409 for an exercise without grading', async () => {
        const copy = await ada.post(`${lab.ws('ada', 'toast-copy')}/grading/submit`);
        expect(copy.status).toBe(409);
        expect(copy.json.error).toMatch(/has no grading/);
        expect((await teacher.post(`/api/courses/${COURSE}/exercises/toast-copy/grading/runs`)).status).toBe(409);
        expect((await ada.send(`${lab.ws('ada', 'toast-copy')}/grading`)).json).toMatchObject({ graded: false, latest: null });
    });
});
