// The lab bench's setup, through the real components: a store (PGlite in a fresh data directory,
// or the PostgreSQL server of a URL), a course with an instructor and N students, the
// toast-controller exercise released; then `maa-lab serve` as a process of its own.
import { spawn } from 'node:child_process';
import { readdirSync, readFileSync, statSync } from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { hashPassword } from '../dist/auth/passwords.js';
import { loadExercise, openLabStore, releaseExercise } from '../dist/index.js';

const here = path.dirname(fileURLToPath(import.meta.url));
export const REPO = path.resolve(here, '..', '..', '..');
const MAA_LAB = path.resolve(here, '..', 'bin', 'maa-lab.js');
export const COURSE = 'bench';
export const EXERCISE = 'toast-controller';
export const PASSWORD = 'the bench password of every user';
export const EXERCISE_DIR = path.join(REPO, 'examples', 'lab', EXERCISE);

export const studentLogin = (i) => `student${String(i + 1).padStart(2, '0')}`;

/** The course, the instructor `teacher`, the students and the released exercise. */
export async function setUpLab({ dataDir, databaseUrl, students }) {
    const store = await openLabStore(databaseUrl ? { databaseUrl } : { dataDir });
    try {
        const hash = await hashPassword(PASSWORD);
        const teacher = await store.createUser({ login: 'teacher', name: 'Teacher', role: 'instructor', passwordHash: hash });
        const course = await store.createCourse({ name: COURSE, title: 'Lab load benchmark' });
        await store.enroll(course.id, teacher.id);
        for (let i = 0; i < students; i++) {
            const login = studentLogin(i);
            const user = await store.createUser({ login, name: `Student ${i + 1}`, role: 'student', passwordHash: hash });
            await store.enroll(course.id, user.id);
        }
        const loaded = await loadExercise(EXERCISE_DIR);
        await releaseExercise(store, loaded, { course: COURSE, authorId: teacher.id });
    } finally {
        await store.close();
    }
}

/**
 * Starts `maa-lab serve --port 0` on loopback; resolves {url, pid, stop, stderrTail}.
 * `stop` sends SIGTERM and waits for the exit (SIGKILL after 30 s).
 */
export function startServer({ dataDir, databaseUrl, extraArgs = [] }) {
    const env = { ...process.env };
    if (databaseUrl) env.DATABASE_URL = databaseUrl;
    else delete env.DATABASE_URL;
    const child = spawn(process.execPath, [MAA_LAB, 'serve', '--port', '0', '--host', '127.0.0.1', '--data-dir', dataDir, ...extraArgs], {
        env,
        stdio: ['ignore', 'pipe', 'pipe'],
    });
    const tail = [];
    child.stderr.setEncoding('utf8');
    child.stderr.on('data', (text) => {
        for (const line of text.split('\n')) if (line && !/^maa-lab: (GET|POST|PUT|DELETE) /.test(line)) tail.push(line);
        tail.splice(0, Math.max(0, tail.length - 50));
    });
    const exited = new Promise((resolve) => child.once('exit', (code, signal) => resolve({ code, signal })));
    const stop = async () => {
        if (child.exitCode !== null || child.signalCode !== null) return exited;
        child.kill('SIGTERM');
        const timer = setTimeout(() => child.kill('SIGKILL'), 30_000);
        const result = await exited;
        clearTimeout(timer);
        return result;
    };
    return new Promise((resolve, reject) => {
        let out = '';
        child.stdout.setEncoding('utf8');
        child.stdout.on('data', (text) => {
            out += text;
            const m = /maa-lab serves (http:\/\/\S+)/.exec(out);
            if (m) resolve({ url: m[1], pid: child.pid, stop, stderrTail: () => tail.join('\n') });
        });
        exited.then(({ code, signal }) =>
            reject(new Error(`maa-lab serve ended (${code ?? signal}) before it served:\n${tail.join('\n')}`)),
        );
    });
}

/** The peak resident set of a process (VmHWM in /proc), in bytes; undefined when unreadable. */
export function peakRss(pid) {
    try {
        const m = /VmHWM:\s+(\d+) kB/.exec(readFileSync(`/proc/${pid}/status`, 'utf8'));
        return m ? Number(m[1]) * 1024 : undefined;
    } catch {
        return undefined;
    }
}

/** The bytes of every file below a folder. */
export function folderBytes(dir) {
    let total = 0;
    for (const entry of readdirSync(dir, { withFileTypes: true })) {
        const p = path.join(dir, entry.name);
        if (entry.isDirectory()) total += folderBytes(p);
        else if (entry.isFile()) total += statSync(p).size;
    }
    return total;
}

/** The database's size: PGlite's folder in the data directory, or pg_database_size. */
export async function databaseBytes({ dataDir, databaseUrl }) {
    if (!databaseUrl) {
        const workspaces = path.join(dataDir, 'workspaces');
        const entries = readdirSync(dataDir, { withFileTypes: true });
        let total = 0;
        for (const e of entries) {
            const p = path.join(dataDir, e.name);
            if (p === workspaces) continue; // the materialized workspace folders are not the database
            total += e.isDirectory() ? folderBytes(p) : statSync(p).size;
        }
        return total;
    }
    const { default: pg } = await import('pg');
    const client = new pg.Client({ connectionString: databaseUrl });
    await client.connect();
    try {
        const r = await client.query('SELECT pg_database_size(current_database())::bigint AS bytes');
        return Number(r.rows[0].bytes);
    } finally {
        await client.end();
    }
}

/** Processes whose command line names the folder (the simulations of this bench's workspaces). */
export function processesUnder(dir) {
    const found = [];
    for (const name of readdirSync('/proc')) {
        if (!/^\d+$/.test(name) || Number(name) === process.pid) continue;
        try {
            const cmd = readFileSync(`/proc/${name}/cmdline`, 'utf8').replaceAll('\0', ' ');
            if (cmd.includes(dir)) found.push({ pid: Number(name), cmd: cmd.slice(0, 200) });
        } catch {
            // gone meanwhile
        }
    }
    return found;
}
