// The students' IDE in the lab (docs/lab.md "The IDE in the lab"): the page of a workspace with
// the session's CSRF token, the IDE's relative paths rewritten onto the workspace's routes (so
// they keep every check), and the attacks: another student's IDE, no session, writes without the
// token, paths that try to leave the workspace.
import { mkdirSync, mkdtempSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import path from 'node:path';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { CSRF_META, homePage, rewriteIdePath, WORKSPACE_META, withLabMeta } from '../src/ide/index.js';
import { startBackend, type Backend } from './backends.js';
import { Client } from './http-client.js';
import { COURSE, EXERCISE, type Lab, put, startLab } from './workspace-setup.js';

describe('rewriteIdePath', () => {
    it('maps the IDE’s relative paths onto the workspace’s routes and the app’s files', () => {
        const ide = '/ide/robotics/toast-controller/ada';
        const ws = '/api/ws/robotics/toast-controller/ada';
        expect(rewriteIdePath(`${ide}/api/files`)).toBe(`${ws}/files`);
        expect(rewriteIdePath(`${ide}/api/file`)).toBe(`${ws}/file`);
        expect(rewriteIdePath(`${ide}/api/generated/trace`)).toBe(`${ws}/generated/trace`);
        expect(rewriteIdePath(`${ide}/api/sim/start`)).toBe(`${ws}/sim/start`);
        expect(rewriteIdePath(`${ide}/api/exercise`)).toBe(ws);
        expect(rewriteIdePath(`${ide}/sim/viser/`)).toBe(`${ws}/sim/viser/`);
        expect(rewriteIdePath(`${ide}/sim/rosbridge`)).toBe(`${ws}/sim/rosbridge`);
        expect(rewriteIdePath(`${ide}/assets/main-abc.js`)).toBe('/assets/main-abc.js');
        expect(rewriteIdePath(`${ide}/maa-extension/files.json`)).toBe('/maa-extension/files.json');
        expect(rewriteIdePath('/ide/a%2Fb/e/o/api/files')).toBe('/api/ws/a%2Fb/e/o/files');
    });

    it('leaves the page itself and every other path alone', () => {
        for (const p of ['/ide/c/e/o', '/ide/c/e/o/', '/ide/c/e/o/index.html', '/ide/c/e', '/ide', '/api/ws/c/e/o/files', '/login', '/'])
            expect(rewriteIdePath(p), p).toBeUndefined();
    });
});

describe('withLabMeta', () => {
    it('puts escaped meta tags at the start of the head', () => {
        const html = withLabMeta('<!doctype html><html><head lang="en"><title>x</title></head></html>', { a: 'x"><script>', b: 'y' });
        expect(html).toBe(
            '<!doctype html><html><head lang="en"><meta name="a" content="x&quot;&gt;&lt;script&gt;"><meta name="b" content="y"><title>x</title></head></html>',
        );
    });

    it('refuses a page without a head', () => {
        expect(() => withLabMeta('<p>no head</p>', { a: 'b' })).toThrow(/no <head>/);
    });
});

describe('homePage', () => {
    it('links each released exercise to the IDE of the user’s own workspace, escaped', () => {
        const html = homePage({ login: 'ada', name: 'Ada <Lovelace>', role: 'student' }, [
            { course: 'robotics', courseTitle: 'Robotics & more', exercise: 'toast-controller', title: 'The "toast" robot' },
        ]);
        expect(html).toContain('<a href="/ide/robotics/toast-controller/ada/">The &quot;toast&quot; robot</a>');
        expect(html).toContain('Hello, Ada &lt;Lovelace&gt;');
        expect(html).toContain('<h2>Robotics &amp; more</h2>');
        expect(html).not.toContain('/dashboard/');
        expect(homePage({ login: 't', name: 'T', role: 'instructor' }, [])).toContain('No exercise has been released');
        // An instructor has no workspace of their own: the course's dashboard, the exercises unlinked.
        const teachers = homePage({ login: 't', name: 'T', role: 'instructor' }, [
            { course: 'robotics', courseTitle: 'Robotics', exercise: 'toast-controller', title: 'Toast' },
        ]);
        expect(teachers).toContain('<a href="/dashboard/robotics">Dashboard of Robotics</a>');
        expect(teachers).toContain('<li>Toast <small>(toast-controller)</small></li>');
        expect(teachers).not.toContain('/ide/');
    });
});

describe('the IDE of a workspace over HTTP', () => {
    let backend: Backend;
    let lab: Lab;
    let app: string;
    let ada: Client;
    let bob: Client;
    let teacher: Client;
    const ide = (owner: string) => `/ide/${COURSE}/${EXERCISE}/${owner}`;

    beforeAll(async () => {
        app = mkdtempSync(path.join(tmpdir(), 'maa-lab-app-'));
        mkdirSync(path.join(app, 'assets'));
        writeFileSync(path.join(app, 'index.html'), '<!doctype html><html><head><title>MAA</title></head><body></body></html>');
        writeFileSync(path.join(app, 'assets', 'main-abc.js'), 'export {};');
        backend = await startBackend('pglite');
        lab = await startLab(await backend.freshStorage(), { appDir: app });
        [ada, bob, teacher] = await Promise.all(['ada', 'bob', 'teacher'].map((l) => lab.as(l)));
    }, 120_000);
    afterAll(async () => {
        await lab?.dispose();
        await backend?.dispose();
        rmSync(app, { recursive: true, force: true });
    });

    it('serves the owner the page with the session’s CSRF token and the workspace, never cached', async () => {
        const redirect = await ada.send(ide('ada'));
        expect(redirect.status).toBe(302);
        expect(redirect.headers.location).toBe(`${ide('ada')}/`);
        const page = await ada.send(`${ide('ada')}/`);
        expect(page.status, page.text).toBe(200);
        expect(page.headers['content-type']).toContain('text/html');
        expect(page.headers['cache-control']).toBe('no-store');
        expect(page.text).toContain(`<meta name="${CSRF_META}" content="${ada.csrf}">`);
        expect(page.text).toContain(`<meta name="${WORKSPACE_META}" content="/api/ws/${COURSE}/${EXERCISE}/ada">`);
        expect((await ada.send(`${ide('ada')}/index.html`)).text).toContain(CSRF_META);
    });

    it('starts at a page that lists the exercises of the user’s courses (instructors: the dashboards too)', async () => {
        const home = await ada.send('/');
        expect(home.status, home.text).toBe(200);
        expect(home.headers['content-security-policy']).toContain("default-src 'none'");
        expect(home.text).toContain(`href="/ide/${COURSE}/${EXERCISE}/ada/"`);
        expect(home.text).toContain(`href="/ide/${COURSE}/toast-copy/ada/"`);
        expect(home.text).not.toContain('/dashboard/');
        const teachers = await teacher.send('/');
        expect(teachers.text).toContain(`href="/dashboard/${COURSE}"`);
        const anonymous = await new Client(lab.server.url).send('/', { headers: { Accept: 'text/html' } });
        expect(anonymous.status).toBe(302);
        expect(anonymous.headers.location).toBe('/login');
    });

    it('answers the IDE’s relative paths from the workspace: files, saves, the exercise, the app’s files', async () => {
        const files = await ada.send(`${ide('ada')}/api/files`);
        expect(files.status, files.text).toBe(200);
        expect(files.json.root).toBe(EXERCISE);
        const saved = await put(ada, `${ide('ada')}/api/file?path=toast/Notes.txt`, 'through the IDE\n');
        expect(saved.status, saved.text).toBe(200);
        expect((await ada.send(`/api/ws/${COURSE}/${EXERCISE}/ada/file?path=toast/Notes.txt`)).text).toBe('through the IDE\n');
        const exercise = await ada.send(`${ide('ada')}/api/exercise`);
        expect(exercise.status).toBe(200);
        expect(exercise.json).toMatchObject({ exercise: EXERCISE, owner: 'ada', writable: true });
        expect(exercise.json.description).toMatch(/^#/);
        const asset = await ada.send(`${ide('ada')}/assets/main-abc.js`);
        expect(asset.status).toBe(200);
        expect(asset.text).toBe('export {};');
    });

    it('refuses another student’s IDE on every path, a page without a session, writes without the CSRF token', async () => {
        for (const p of [
            `${ide('ada')}/`,
            `${ide('ada')}/api/files`,
            `${ide('ada')}/api/file?path=toast/Controller.arc`,
            `${ide('ada')}/api/exercise`,
        ]) {
            const answer = await bob.send(p);
            expect(answer.status, p).toBe(403);
            expect(answer.text).not.toContain(CSRF_META);
        }
        expect((await put(bob, `${ide('ada')}/api/file?path=toast/Notes.txt`, 'bob was here')).status).toBe(403);
        const anonymous = new Client(lab.server.url);
        const page = await anonymous.send(`${ide('ada')}/`, { headers: { Accept: 'text/html' } });
        expect(page.status).toBe(302);
        expect(page.headers.location).toBe('/login');
        expect((await anonymous.send(`${ide('ada')}/api/files`)).status).toBe(401);
        const noToken = await ada.send(`${ide('ada')}/api/file?path=toast/Notes.txt`, { method: 'PUT', raw: 'no token' });
        expect(noToken.status).toBe(403);
        expect(noToken.json.error).toMatch(/CSRF/);
        // Dot segments are resolved before the rewrite: they cannot reach another workspace.
        const outside = await ada.send(`${ide('ada')}/api/../../bob/api/files`);
        expect(outside.status).not.toBe(200);
        // The instructor sees the student's IDE read-only.
        const viewed = await teacher.send(`${ide('ada')}/api/exercise`);
        expect(viewed.json).toMatchObject({ owner: 'ada', writable: false });
        expect((await put(teacher, `${ide('ada')}/api/file?path=toast/Notes.txt`, 'teacher')).status).toBe(403);
    });
});
