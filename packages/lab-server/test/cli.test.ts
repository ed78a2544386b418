// The maa-lab command, run in-process (runLab with an injected io) on both storage backends:
// --help everywhere, courses, users with a password from stdin or an invitation link, roster
// import (good, bad rows with line numbers, nothing imported on error), and serve.
import { mkdtempSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { type LabIo, runLab } from '../src/cli/main.js';
import { BACKENDS, type Backend, startBackend } from './backends.js';
import { Client } from './http-client.js';

interface Run {
    code: number;
    out: string;
    err: string;
}

describe.each(BACKENDS)('maa-lab on %s', (backendName) => {
    let backend: Backend;
    let dir: string;
    /** --data-dir for PGlite; the PostgreSQL backend comes through DATABASE_URL */
    let storageArgs: string[] = [];
    let env: NodeJS.ProcessEnv = {};
    /** Every secret handed to a command on stdin: none may appear in any output. */
    const secrets: string[] = [];

    beforeAll(async () => {
        backend = await startBackend(backendName);
        dir = mkdtempSync(path.join(tmpdir(), 'maa-lab-cli-'));
        const storage = await backend.freshStorage();
        if (storage.databaseUrl) env = { DATABASE_URL: storage.databaseUrl };
        else storageArgs = ['--data-dir', storage.dataDir];
    });
    afterAll(async () => {
        await backend?.dispose();
        if (dir) rmSync(dir, { recursive: true, force: true });
    });

    async function lab(args: string[], stdin = '', hooks?: Parameters<typeof runLab>[2]): Promise<Run> {
        let out = '';
        let err = '';
        const io: LabIo = {
            cwd: dir,
            env,
            out: (t) => void (out += t),
            err: (t) => void (err += t),
            readSecret: async () => stdin,
        };
        const code = await runLab(['node', 'maa-lab', ...args], io, hooks);
        for (const secret of secrets) expect(out + err).not.toContain(secret);
        return { code, out, err };
    }

    /** A command that opens the store gets the storage arguments after its own. */
    const withStorage = (args: string[]) => [...args, ...storageArgs];

    it('has --help for every command', async () => {
        const top = await lab(['--help']);
        expect(top.code).toBe(0);
        for (const name of ['serve', 'users', 'course', 'exercise']) expect(top.out).toContain(name);
        for (const command of [
            ['serve'],
            ['users', 'add'],
            ['users', 'import'],
            ['users', 'invite'],
            ['users', 'list'],
            ['course', 'create'],
            ['course', 'enroll'],
            ['exercise', 'release'],
            ['exercise', 'update'],
        ]) {
            const help = await lab([...command, '--help']);
            expect(help.code, command.join(' ')).toBe(0);
            expect(help.out).toContain(`Usage: maa-lab ${command.join(' ')}`);
        }
        const unknown = await lab(['frobnicate']);
        expect(unknown.code).toBe(2);
        expect(unknown.err).toContain("unknown command 'frobnicate'");
    });

    it('creates a course once, with a clear error for a taken or bad name', async () => {
        expect(await lab(withStorage(['course', 'create', 'robotics', '--title', 'Robotics lab']))).toMatchObject({
            code: 0,
            out: 'created the course robotics (Robotics lab)\n',
        });
        const again = await lab(withStorage(['course', 'create', 'robotics', '--title', 'Again']));
        expect(again).toMatchObject({ code: 1, err: 'maa-lab: error: the course robotics exists already\n' });
        const bad = await lab(withStorage(['course', 'create', 'Bad Name', '--title', 'x']));
        expect(bad.code).toBe(1);
        expect(bad.err).toContain('may hold only lower case letters');
        const noTitle = await lab(withStorage(['course', 'create', 'other']));
        expect(noTitle.code).toBe(2);
        expect(noTitle.err).toContain("required option '--title <title>' not specified");
    });

    it('adds the first instructor with a password from stdin (never echoed) and refuses a weak one', async () => {
        const weak = await lab(
            withStorage(['users', 'add', 'teacher', '--name', 'The Teacher', '--role', 'instructor', '--password-stdin']),
            'short',
        );
        expect(weak).toMatchObject({ code: 1, err: 'maa-lab: error: the password must have at least 10 characters\n' });
        secrets.push('a long instructor password');
        const added = await lab(
            withStorage([
                'users',
                'add',
                'teacher',
                '--name',
                'The Teacher',
                '--role',
                'instructor',
                '--course',
                'robotics',
                '--password-stdin',
            ]),
            'a long instructor password',
        );
        expect(added).toMatchObject({ code: 0, out: 'added instructor teacher with the password given on stdin\n' });
        const taken = await lab(withStorage(['users', 'add', 'teacher', '--name', 'Another', '--password-stdin']), 'another long password');
        expect(taken.code).toBe(1);
        expect(taken.err).toContain('is taken');
        const noCourse = await lab(withStorage(['users', 'add', 'x1', '--name', 'X', '--course', 'nope']));
        expect(noCourse.err).toContain('there is no course "nope"');
    });

    it('imports a roster into a course with one-time links, and imports nothing from a roster with a bad row', async () => {
        writeFileSync(
            path.join(dir, 'bad.csv'),
            'name,email,login,role\nAda,ada@uni.example,ada,student\nBob,bob@,bob,student\nCy,cy@uni.example,cy,wizard\n',
        );
        const bad = await lab(withStorage(['users', 'import', 'bad.csv', '--course', 'robotics']));
        expect(bad.code).toBe(1);
        expect(bad.err).toContain('line 3: "bob@" is not an e-mail address');
        expect(bad.err).toContain('line 4: the role "wizard" is neither student nor instructor');
        expect(bad.err).toContain('nothing was imported');
        expect((await lab(withStorage(['users', 'list']))).out).not.toContain('ada');

        writeFileSync(path.join(dir, 'taken.csv'), 'name,login\nAda,ada\nTeacher again,teacher\n');
        const taken = await lab(withStorage(['users', 'import', 'taken.csv']));
        expect(taken.code).toBe(1);
        expect(taken.err).toContain('line 3: the login teacher exists already');
        expect((await lab(withStorage(['users', 'list']))).out).not.toContain('ada');

        writeFileSync(
            path.join(dir, 'roster.csv'),
            'name,email,login,role\nAda Lovelace,ada@uni.example,ada,student\n"Hopper, Grace",grace@uni.example,,\nBob,bob@uni.example,bob,student\n',
        );
        const good = await lab(
            withStorage([
                'users',
                'import',
                'roster.csv',
                '--course',
                'robotics',
                '--out',
                'links.csv',
                '--public-url',
                'https://lab.example.org',
            ]),
        );
        expect(good).toMatchObject({
            code: 0,
            out: 'imported 3 users into robotics; their one-time invitation links (valid 14 days) are in links.csv\n',
        });
        const links = readFileSync(path.join(dir, 'links.csv'), 'utf8').trim().split('\n');
        expect(links[0]).toBe('login,name,email,link');
        expect(links[2]).toMatch(
            /^grace@uni\.example,"Hopper, Grace",grace@uni\.example,https:\/\/lab\.example\.org\/invite#[A-Za-z0-9_-]{43}$/,
        );
        const list = await lab(withStorage(['course', 'list', 'robotics']));
        expect(list.out).toBe(
            'ada\tstudent\tAda Lovelace\nbob\tstudent\tBob\ngrace@uni.example\tstudent\tHopper, Grace\nteacher\tinstructor\tThe Teacher\n',
        );
        const printed = await lab(withStorage(['users', 'add', 'dora', '--name', 'Dora', '--email', 'dora@uni.example']));
        expect(printed.out).toMatch(
            /^added student dora; the one-time invitation link \(valid 14 days\):\nhttp:\/\/127\.0\.0\.1:8090\/invite#[A-Za-z0-9_-]{43}\n$/,
        );
    });

    it('enrolls existing users and refuses unknown ones', async () => {
        const missing = await lab(withStorage(['course', 'enroll', 'robotics', 'dora', 'nobody']));
        expect(missing).toMatchObject({ code: 1, err: 'maa-lab: error: there is no user nobody (nobody was enrolled)\n' });
        expect((await lab(withStorage(['course', 'enroll', 'robotics', 'dora']))).out).toBe('enrolled dora in robotics\n');
        expect((await lab(withStorage(['course', 'list', 'robotics']))).out).toContain('dora\tstudent\tDora');
    });

    it('serves the lab: the instructor logs in, a student accepts an invitation from users invite, the roster is there', async () => {
        const invite = await lab(withStorage(['users', 'invite', 'ada', '--public-url', 'http://127.0.0.1:1']));
        const token = /#([A-Za-z0-9_-]{43})$/m.exec(invite.out)?.[1] ?? '';
        expect(token).not.toBe('');
        let stop: (() => Promise<void>) | undefined;
        let url = '';
        const serve = await lab(withStorage(['serve', '--port', '0', '--generate-threads', '2']), '', {
            onServing: (s, u) => {
                stop = s;
                url = u;
            },
        });
        expect(serve.code, serve.err).toBe(0);
        expect(serve.out).toMatch(/^maa-lab serves http:\/\/127\.0\.0\.1:\d+ \((embedded database|PostgreSQL)\); log in at /);
        try {
            const teacher = new Client(url);
            expect((await teacher.login('teacher', 'a long instructor password')).status).toBe(200);
            const students = await teacher.send('/api/courses/robotics/students');
            expect(students.json.students.map((s: { login: string }) => s.login)).toEqual(['ada', 'bob', 'dora', 'grace@uni.example']);
            secrets.push('ada-chose-this-one');
            const ada = new Client(url);
            expect((await ada.send('/api/invitations/accept', { body: { token, password: 'ada-chose-this-one' } })).status).toBe(200);
            expect((await ada.send('/api/courses/robotics/students')).status).toBe(403);
        } finally {
            await stop?.();
        }
    });

    it('releases an exercise to the course through the exercise command, with a clear error for an unknown course', async () => {
        const folder = fileURLToPath(new URL('../../../examples/lab/toast-controller', import.meta.url));
        const unknown = await lab(withStorage(['exercise', 'release', folder, '--course', 'nope']));
        expect(unknown.code).toBe(1);
        expect(unknown.err).toMatch(/^maa-lab: error: .*nope/);
        const released = await lab(withStorage(['exercise', 'release', folder, '--course', 'robotics']));
        expect(released.code, released.err).toBe(0);
        expect(released.out).toMatch(/^released toast-controller to robotics: \d+ starter files, \d+ workspaces/);
    });

    it('refuses single sign-on settings without the client secret, and a bad port', async () => {
        const noSecret = await lab(
            withStorage(['serve', '--port', '0', '--oidc-issuer', 'https://id.example.org', '--oidc-client-id', 'lab']),
        );
        expect(noSecret).toMatchObject({
            code: 1,
            err: 'maa-lab: error: single sign-on needs the client secret in the environment variable MAA_LAB_OIDC_CLIENT_SECRET\n',
        });
        const half = await lab(withStorage(['serve', '--oidc-issuer', 'https://id.example.org']));
        expect(half.err).toContain('needs both --oidc-issuer and --oidc-client-id');
        expect((await lab(withStorage(['serve', '--port', 'http']))).err).toContain('--port must be a port number');
        for (const bad of ['0', 'two', '65'])
            expect((await lab(withStorage(['serve', '--port', '0', '--generate-threads', bad]))).err).toBe(
                `maa-lab: error: --generate-threads must be a whole number from 1 to 64, not ${bad}\n`,
            );
    });
});
