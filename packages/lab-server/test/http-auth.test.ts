// The lab server's security rules, each attacked against a real server on an ephemeral port, on
// both storage backends: no session → 401, a student on an instructor route → 403, a forged
// request without the CSRF token → 403, a wrong Host or Origin → 403, too many failed logins →
// 429 with Retry-After, the cookie's flags, invitations used once, and no password in the log.
import { afterAll, beforeAll, describe, expect, it, vi } from 'vitest';
import { newInvitation } from '../src/auth/invitations.js';
import { hashPassword } from '../src/auth/passwords.js';
import { type LabServer, startLabServer } from '../src/http/server.js';
import { type LabStore, openLabStore } from '../src/storage/index.js';
import { BACKENDS, type Backend, startBackend } from './backends.js';
import { Client } from './http-client.js';

const INSTRUCTOR_PASSWORD = 'correct horse battery staple';
const STUDENT_PASSWORD = 'Tr0ub4dor&3-student';

describe.each(BACKENDS)('the lab server on %s', (backendName) => {
    let backend: Backend;
    let store: LabStore;
    let server: LabServer;
    const log: string[] = [];
    const consoleLines: string[] = [];
    /** Every password any test sent: none may appear in the log. */
    const sentPasswords = new Set<string>([INSTRUCTOR_PASSWORD, STUDENT_PASSWORD]);

    beforeAll(async () => {
        for (const method of ['log', 'error', 'warn', 'info'] as const)
            vi.spyOn(console, method).mockImplementation((...args: unknown[]) => void consoleLines.push(args.map(String).join(' ')));
        backend = await startBackend(backendName);
        store = await openLabStore(await backend.freshStorage());
        const teacher = await store.createUser({
            login: 'teacher',
            name: 'The Teacher',
            role: 'instructor',
            passwordHash: await hashPassword(INSTRUCTOR_PASSWORD),
        });
        const ada = await store.createUser({
            login: 'ada',
            name: 'Ada',
            role: 'student',
            email: 'ada@example.org',
            passwordHash: await hashPassword(STUDENT_PASSWORD),
        });
        const course = await store.createCourse({ name: 'robotics', title: 'Robotics lab' });
        await store.enroll(course.id, teacher.id);
        await store.enroll(course.id, ada.id);
        server = await startLabServer({
            store,
            port: 0,
            log: (line) => log.push(line),
        });
    });
    afterAll(async () => {
        await server?.close();
        await store?.close();
        await backend?.dispose();
        vi.restoreAllMocks();
    });

    const client = () => new Client(server.url);

    async function loggedIn(login: string, password: string): Promise<Client> {
        const c = client();
        const answer = await c.login(login, password);
        expect(answer.status, answer.text).toBe(200);
        return c;
    }

    it('refuses every route but login, invitations and the pages without a session (401)', async () => {
        const c = client();
        expect((await c.send('/api/me')).status).toBe(401);
        expect((await c.send('/api/courses/robotics/students')).status).toBe(401);
        expect((await c.send('/api/logout', { body: {} })).status).toBe(401);
        const page = await c.send('/anything', { headers: { Accept: 'text/html' } });
        expect(page.status).toBe(404);
        expect((await c.send('/login')).status).toBe(200);
        expect((await c.send('/invite')).status).toBe(200);
        // A session cookie that is not one opens nothing either.
        c.cookies.set('maa-lab-session', 'x'.repeat(43));
        expect((await c.send('/api/me')).status).toBe(401);
    });

    it('logs in with the right password and sets an HttpOnly, SameSite cookie on / (no Secure over plain http)', async () => {
        const c = client();
        const wrong = await c.login('teacher', 'not the password');
        expect(wrong.status).toBe(401);
        expect(wrong.headers['set-cookie']).toBeUndefined();
        const answer = await c.login('teacher', INSTRUCTOR_PASSWORD);
        expect(answer.status).toBe(200);
        expect(answer.json.user).toEqual({
            id: expect.any(Number),
            login: 'teacher',
            name: 'The Teacher',
            email: null,
            role: 'instructor',
        });
        expect(JSON.stringify(answer.json)).not.toContain('argon2');
        const cookie = answer.headers['set-cookie']?.[0] ?? '';
        expect(cookie).toMatch(/^maa-lab-session=[A-Za-z0-9_-]{43};/);
        expect(cookie).toContain('HttpOnly');
        expect(cookie).toMatch(/SameSite=(Lax|Strict)/);
        expect(cookie).toContain('Path=/');
        expect(cookie).not.toContain('Secure');
        const me = await c.send('/api/me');
        expect(me.status).toBe(200);
        expect(me.json.user.login).toBe('teacher');
        expect(me.json.csrfToken).toBe(answer.json.csrfToken);
    });

    it('keeps the instructor routes from students (403) and answers instructors', async () => {
        const student = await loggedIn('ada', STUDENT_PASSWORD);
        const refused = await student.send('/api/courses/robotics/students');
        expect(refused.status).toBe(403);
        expect(refused.json.error).toContain('instructor');
        const teacher = await loggedIn('teacher', INSTRUCTOR_PASSWORD);
        const answer = await teacher.send('/api/courses/robotics/students');
        expect(answer.status).toBe(200);
        expect(answer.json.students.map((s: { login: string }) => s.login)).toEqual(['ada']);
        expect((await teacher.send('/api/courses/nope/students')).status).toBe(404);
    });

    it("accepts a write from the lab's own pages without the token (their Origin), never from another origin or `null`", async () => {
        const c = await loggedIn('ada', STUDENT_PASSWORD);
        const own = new URL(c.base).origin;
        for (const origin of ['https://evil.example', 'null', `${own}.evil.example`]) {
            const answer = await c.send('/api/logout', { body: {}, headers: { Origin: origin } });
            expect(answer.status, origin).toBe(403);
        }
        expect((await c.send('/api/me')).status).toBe(200);
        const fromPage = await c.send('/api/logout', { body: {}, headers: { Origin: own } });
        expect(fromPage.status, fromPage.text).toBe(200);
        expect((await c.send('/api/me')).status).toBe(401);
    });

    it('refuses a forged state-changing request without the session CSRF token (403), and logs out with it', async () => {
        const c = await loggedIn('ada', STUDENT_PASSWORD);
        // A cross-site form or script has the cookie (the browser sends it) but not the token.
        const forged = await c.send('/api/logout', { body: {} });
        expect(forged.status).toBe(403);
        expect(forged.json.error).toContain('CSRF');
        const wrongToken = await c.send('/api/logout', { body: {}, headers: { 'X-CSRF-Token': 'A'.repeat(43) } });
        expect(wrongToken.status).toBe(403);
        // Another session's token is no good either.
        const other = await loggedIn('ada', STUDENT_PASSWORD);
        expect((await c.send('/api/logout', { body: {}, headers: { 'X-CSRF-Token': other.csrf ?? '' } })).status).toBe(403);
        expect((await c.send('/api/me')).status).toBe(200);
        const out = await c.post('/api/logout');
        expect(out.status).toBe(200);
        expect(out.headers['set-cookie']?.[0]).toMatch(/Max-Age=0/);
        expect(c.cookies.size).toBe(0);
        expect((await c.send('/api/me')).status).toBe(401);
        // The session is gone on the server too: the old cookie opens nothing.
        c.cookies.set('maa-lab-session', [...other.cookies.values()][0] ?? '');
        expect((await c.send('/api/me')).status).toBe(200);
    });

    it('refuses a wrong Host (DNS rebinding) and a foreign Origin (403)', async () => {
        const c = await loggedIn('teacher', INSTRUCTOR_PASSWORD);
        const rebound = await c.send('/api/me', { headers: { Host: `evil.example:${server.port}` } });
        expect(rebound.status).toBe(403);
        expect(rebound.json.error).toContain('does not serve the host');
        const otherPort = await c.send('/api/me', { headers: { Host: `127.0.0.1:${server.port + 1}` } });
        expect(otherPort.status).toBe(403);
        const foreign = await c.post('/api/logout', {}, { Origin: 'http://evil.example' });
        expect(foreign.status).toBe(403);
        expect(foreign.json.error).toContain('origin');
        const loginFromElsewhere = await client().send('/api/login', {
            body: { login: 'teacher', password: INSTRUCTOR_PASSWORD },
            headers: { Origin: 'http://evil.example' },
        });
        expect(loginFromElsewhere.status).toBe(403);
        expect((await c.send('/api/me', { headers: { Origin: server.url, Host: `localhost:${server.port}` } })).status).toBe(403);
        expect(
            (await c.send('/api/me', { headers: { Origin: `http://localhost:${server.port}`, Host: `localhost:${server.port}` } })).status,
        ).toBe(200);
    });

    it('limits request bodies (413) and takes only JSON (415)', async () => {
        const big = await client().send('/api/login', { raw: JSON.stringify({ login: 'x', password: 'y'.repeat(20_000) }) });
        expect(big.status).toBe(413);
        const form = await client().send('/api/login', {
            raw: 'login=teacher&password=x',
            headers: { 'Content-Type': 'application/x-www-form-urlencoded' },
        });
        expect(form.status).toBe(415);
        const notJson = await client().send('/api/login', { raw: '{not json' });
        expect(notJson.status).toBe(400);
    });

    /** A server of its own behind a "proxy" (X-Forwarded-For names the client), so each test has its own addresses. */
    async function withLimitedServer(run: (from: (address: string) => Client) => Promise<void>): Promise<void> {
        const limited = await startLabServer({
            store,
            port: 0,
            trustProxy: true,
            rateLimits: { perLogin: 3, perAddress: 5, windowMs: 60_000 },
            log: (line) => log.push(line),
        });
        try {
            await run((address) => {
                const c = new Client(limited.url);
                const send = c.send.bind(c);
                c.send = (path, options = {}) =>
                    send(path, { ...options, headers: { 'X-Forwarded-For': `10.9.9.9, ${address}`, ...options.headers } });
                return c;
            });
        } finally {
            await limited.close();
        }
    }

    it('rate-limits failed logins per login (429 with Retry-After), even with the right password then', async () => {
        await store.createUser({ login: 'grace', name: 'Grace', role: 'student', passwordHash: await hashPassword('grace-password-1') });
        await withLimitedServer(async (from) => {
            for (let i = 0; i < 3; i++) expect((await from(`10.0.0.${i}`).login('grace', `guess ${i}`)).status).toBe(401);
            const limited = await from('10.0.0.9').login('grace', 'grace-password-1');
            expect(limited.status).toBe(429);
            expect(Number(limited.headers['retry-after'])).toBeGreaterThan(0);
            expect(limited.json.error).toContain('too many failed logins');
            // Other logins are not affected.
            expect((await from('10.0.0.9').login('teacher', INSTRUCTOR_PASSWORD)).status).toBe(200);
        });
    });

    it('rate-limits failed logins per client address (the last X-Forwarded-For entry behind a trusted proxy)', async () => {
        await withLimitedServer(async (from) => {
            for (let i = 0; i < 5; i++) expect((await from('10.1.1.1').login(`nobody${i}`, 'whatever-guess')).status).toBe(401);
            const limited = await from('10.1.1.1').login('ada', STUDENT_PASSWORD);
            expect(limited.status).toBe(429);
            expect(limited.headers['retry-after']).toMatch(/^\d+$/);
            // Another address (the first X-Forwarded-For entry is the same: only the proxy's own counts).
            expect((await from('10.1.1.2').login('ada', STUDENT_PASSWORD)).status).toBe(200);
            expect(log.some((line) => line.includes('from 10.1.1.1'))).toBe(true);
        });
    });

    it('lets a student set a password once through an invitation link; a used, expired or unknown link is refused', async () => {
        const fresh = newInvitation();
        const expired = newInvitation();
        await store.importUsers([
            { user: { login: 'linus', name: 'Linus', role: 'student' }, invitation: { id: fresh.id, expiresAt: fresh.expiresAt } },
            {
                user: { login: 'late', name: 'Late', role: 'student' },
                invitation: { id: expired.id, expiresAt: new Date(Date.now() - 1000) },
            },
        ]);
        const password = 'linus-new-password';
        sentPasswords.add(password);
        const c = client();
        expect((await c.send('/api/invitations/accept', { body: { token: fresh.token, password: 'short' } })).status).toBe(400);
        const accepted = await c.send('/api/invitations/accept', { body: { token: fresh.token, password } });
        expect(accepted.status).toBe(200);
        expect(accepted.json.user.login).toBe('linus');
        expect((await c.send('/api/me')).json.user.login).toBe('linus');
        const again = await client().send('/api/invitations/accept', { body: { token: fresh.token, password: 'another-password-2' } });
        expect(again.status).toBe(410);
        expect(again.json.error).toContain('used already');
        expect((await loggedIn('linus', password)).cookies.size).toBe(1);
        const late = await client().send('/api/invitations/accept', { body: { token: expired.token, password: 'late-password-12' } });
        expect(late.status).toBe(410);
        expect(late.json.error).toContain('expired');
        const unknown = await client().send('/api/invitations/accept', {
            body: { token: newInvitation().token, password: 'late-password-12' },
        });
        expect(unknown.status).toBe(404);
    });

    it('adds routes of other parts behind the same checks', async () => {
        server.routes.add({
            method: 'POST',
            path: '/api/test/:thing/echo',
            access: 'user',
            handler: ({ res, params, auth }) => {
                res.writeHead(200, { 'Content-Type': 'application/json' });
                res.end(JSON.stringify({ thing: params['thing'], by: auth.user.login }));
            },
        });
        expect((await client().send('/api/test/a%20b/echo', { body: {} })).status).toBe(401);
        const c = await loggedIn('teacher', INSTRUCTOR_PASSWORD);
        expect((await c.send('/api/test/a%20b/echo', { body: {} })).status).toBe(403);
        const ok = await c.post('/api/test/a%20b/echo');
        expect(ok.json).toEqual({ thing: 'a b', by: 'teacher' });
        expect((await c.send('/api/test/a%20b/echo')).status).toBe(405);
    });

    it('never writes a password to its log', () => {
        expect(log.some((line) => line.startsWith('login: teacher'))).toBe(true);
        expect(log.some((line) => line.startsWith('login failed: "grace"'))).toBe(true);
        for (const line of [...log, ...consoleLines]) for (const password of sentPasswords) expect(line).not.toContain(password);
        for (const line of [...log, ...consoleLines]) expect(line).not.toMatch(/guess \d|argon2/);
    });
});

describe('the session cookie behind https', () => {
    it('is Secure with the __Host- prefix when the public URL is https or a proxy is trusted', async () => {
        const backend = await startBackend('pglite');
        const store = await openLabStore(await backend.freshStorage());
        await store.createUser({ login: 'teacher', name: 'T', role: 'instructor', passwordHash: await hashPassword(INSTRUCTOR_PASSWORD) });
        const server = await startLabServer({ store, port: 0, publicUrl: 'https://lab.example.org', log: () => undefined });
        const proxied = await startLabServer({ store, port: 0, trustProxy: true, log: () => undefined });
        try {
            const answer = await new Client(server.url).send('/api/login', {
                body: { login: 'teacher', password: INSTRUCTOR_PASSWORD },
                headers: { Host: 'lab.example.org', Origin: 'https://lab.example.org' },
            });
            expect(answer.status, answer.text).toBe(200);
            const cookie = answer.headers['set-cookie']?.[0] ?? '';
            expect(cookie).toMatch(/^__Host-maa-lab-session=/);
            expect(cookie).toMatch(/; Secure$/);
            expect(cookie).toContain('HttpOnly');
            const viaProxy = await new Client(proxied.url).login('teacher', INSTRUCTOR_PASSWORD);
            expect(viaProxy.headers['set-cookie']?.[0]).toContain('; Secure');
        } finally {
            await server.close();
            await proxied.close();
            await store.close();
            await backend.dispose();
        }
    });
});
