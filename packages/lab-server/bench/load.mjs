// The lab bench's load: simulated students, each with its own session, editing its Controller
// automaton in a loop with think time, and one instructor polling the dashboard.
import { readFileSync } from 'node:fs';
import { performance } from 'node:perf_hooks';
import path from 'node:path';
import { BenchClient } from './http.mjs';
import { COURSE, EXERCISE, EXERCISE_DIR, PASSWORD, studentLogin } from './setup.mjs';

const CONTROLLER = 'toast/Controller.arc';
const APP = 'TR.arcapp';
const SOLUTION = readFileSync(path.join(EXERCISE_DIR, 'solution', CONTROLLER), 'utf8');
const STARTER = readFileSync(path.join(EXERCISE_DIR, 'starter', CONTROLLER), 'utf8');

/**
 * The n-th edit of a student's Controller: the reference solution or the starter with a comment
 * that makes every save a new text; every `errorEvery`-th edit has an error (a transition to a
 * state that does not exist).
 */
export function editedController(n, errorEvery = 5) {
    const base = n % 2 === 0 ? SOLUTION : STARTER;
    const marked = `${base.trimEnd()}\n// edit ${n}\n`;
    if (n % errorEvery !== errorEvery - 1) return marked;
    return marked.replace(/state Idle;/, 'state Idle;\n    Idle -> NoSuchState;');
}

const sleep = (ms) => new Promise((r) => setTimeout(r, ms));
const between = (lo, hi) => lo + Math.random() * (hi - lo);

/**
 * Logs every student in, then runs for `seconds`: save, list the
 * files (the IDE's refresh), generate (timesync), and every `testEvery`-th round the stream
 * tests, with think time between the steps. An instructor polls the dashboard every 5 s (the
 * server-side diagnostics of every changed workspace, what the dashboard page does).
 * @returns the samples [{kind, ms, ok, status, detail}]
 */
export async function runLoad({ url, students, seconds, thinkMs, testEvery }) {
    const samples = [];
    const record = (kind, ms, ok, status, text) => samples.push({ kind, ms, ok, status, detail: ok ? undefined : text.slice(0, 300) });
    const clients = Array.from({ length: students }, () => new BenchClient(url, record));
    await Promise.all(clients.map((c, i) => c.login(studentLogin(i), PASSWORD)));
    const teacher = new BenchClient(url, record);
    await teacher.login('teacher', PASSWORD);
    const end = Date.now() + seconds * 1000;
    const think = () => sleep(Math.min(between(thinkMs / 2, (thinkMs * 3) / 2), Math.max(0, end - Date.now())));
    const student = async (c, i) => {
        const prefix = `/api/ws/${COURSE}/${EXERCISE}/${studentLogin(i)}`;
        await sleep(between(0, thinkMs)); // the class does not press save at the same instant
        for (let round = 0; Date.now() < end; round++) {
            const edit = i * 1000 + round;
            await c.send('save', 'PUT', `${prefix}/file?path=${encodeURIComponent(CONTROLLER)}`, editedController(edit));
            await c.send('files', 'GET', `${prefix}/files`);
            await think();
            if (Date.now() >= end) break;
            await c.send('generate', 'POST', `${prefix}/generate`, { app: APP, platform: 'timesync' });
            if (round % testEvery === testEvery - 1 && Date.now() < end)
                await c.send('test', 'POST', `${prefix}/test`, { app: APP, platform: 'timesync' });
            await think();
        }
    };
    const instructor = async () => {
        let etag;
        while (Date.now() < end) {
            // a conditional GET as the page sends it (304 while nothing changed)
            const a = await teacher.send(
                'dashboard',
                'GET',
                `/api/courses/${COURSE}/dashboard`,
                undefined,
                etag ? { 'If-None-Match': etag } : {},
            );
            if (typeof a.headers['etag'] === 'string') etag = a.headers['etag'];
            await sleep(Math.min(5000, Math.max(0, end - Date.now())));
        }
    };
    const started = performance.now();
    await Promise.all([...clients.map(student), instructor()]);
    const elapsed = (performance.now() - started) / 1000;
    for (const c of [...clients, teacher]) c.close();
    return { samples: samples.filter((s) => s.kind !== 'login'), elapsed };
}
