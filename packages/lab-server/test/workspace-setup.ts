// A lab for the workspace tests: an instructor and two students in a course with the
// toast-controller exercise of examples/lab/ released, and a lab server on it.
import { mkdtempSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { expect } from 'vitest';
import { hashPassword } from '../src/auth/passwords.js';
import { loadExercise } from '../src/exercises/load.js';
import { releaseExercise } from '../src/exercises/release.js';
import { type LabServer, type LabServerOptions, startLabServer } from '../src/http/server.js';
import { type LabStore, openLabStore, type StorageOptions } from '../src/storage/index.js';
import { Client } from './http-client.js';
import './liftoff.js';

export const repo = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '../../..');
export const MAA_SIM = path.join(repo, 'sim-server', '.venv', 'bin', 'maa-sim');
export const PYTHON = path.join(repo, 'packages', 'generators-python', '.venv', 'bin', 'python');
export const PASSWORD = 'a long enough test password';
export const COURSE = 'robotics';
export const EXERCISE = 'toast-controller';

export interface Lab {
    store: LabStore;
    server: LabServer;
    dataDir: string;
    /** logs in as the user (a fresh client each call) on the server (default: the first) */
    as(login: string, on?: LabServer): Promise<Client>;
    /** `/api/ws/robotics/<exercise>/<owner>` */
    ws(owner: string, exercise?: string): string;
    /** a second server on the same store (other options) */
    serverWith(options: Partial<LabServerOptions>): Promise<LabServer>;
    dispose(): Promise<void>;
}

/** The store with users, course and released exercises (`toast-controller` and a copy `toast-copy`). */
export async function startLab(storage: StorageOptions, options: Partial<LabServerOptions> = {}): Promise<Lab> {
    const store = await openLabStore(storage);
    const hash = await hashPassword(PASSWORD);
    const teacher = await store.createUser({ login: 'teacher', name: 'Teacher', role: 'instructor', passwordHash: hash });
    const course = await store.createCourse({ name: COURSE, title: 'Robotics lab' });
    for (const login of ['ada', 'bob']) {
        const user = await store.createUser({ login, name: login, role: 'student', passwordHash: hash });
        await store.enroll(course.id, user.id);
    }
    const loaded = await loadExercise(path.join(repo, 'examples', 'lab', EXERCISE));
    await releaseExercise(store, loaded, { course: COURSE, authorId: teacher.id });
    await releaseExercise(store, { ...loaded, name: 'toast-copy' }, { course: COURSE, authorId: teacher.id });
    const dataDir = mkdtempSync(path.join(tmpdir(), 'maa-lab-ws-'));
    const servers: LabServer[] = [];
    const serverWith = async (more: Partial<LabServerOptions>) => {
        const s = await startLabServer({
            store,
            port: 0,
            log: () => undefined,
            ...options,
            ...more,
            workspaces: { dataDir, maaSim: MAA_SIM, ...options.workspaces, ...more.workspaces },
        });
        servers.push(s);
        return s;
    };
    const server = await serverWith({});
    return {
        store,
        server,
        dataDir,
        serverWith,
        ws: (owner, exercise = EXERCISE) => `/api/ws/${COURSE}/${exercise}/${owner}`,
        as: async (login, on = server) => {
            const c = new Client(on.url);
            const answer = await c.login(login, PASSWORD);
            expect(answer.status, answer.text).toBe(200);
            return c;
        },
        dispose: async () => {
            for (const s of servers) await s.close();
            await store.close();
            rmSync(dataDir, { recursive: true, force: true });
        },
    };
}

/** PUT of a file's text with the CSRF token. */
export function put(c: Client, url: string, text: string) {
    return c.send(url, { method: 'PUT', raw: text, headers: c.csrf ? { 'X-CSRF-Token': c.csrf } : {} });
}

/** DELETE with the CSRF token. */
export function del(c: Client, url: string) {
    return c.send(url, { method: 'DELETE', headers: c.csrf ? { 'X-CSRF-Token': c.csrf } : {} });
}

/** Waits until `check` holds (polling); fails after a bound generous for a loaded machine. */
export async function until(check: () => boolean | Promise<boolean>, what: string, boundMs = 60_000): Promise<void> {
    const deadline = Date.now() + boundMs;
    while (!(await check())) {
        if (Date.now() > deadline) throw new Error(`timed out waiting for ${what}`);
        await new Promise((r) => setTimeout(r, 100));
    }
}
