// Students' handwritten Python in a grading run (docs/lab.md "Sandbox"): one batch of a small
// exercise (test/fixtures/grading/malicious: a <<handwritten>> Doubler, the student writes
// calc/Doubler.timesync.py) with one submission per attack and two honest ones, graded by
// @maa/grading in one gradeSubmissions call (one local Ray run, every task in bubblewrap). Each
// attack is contained (the secrets never appear in any output, the outside file is not written, the
// "lab server" sees no connection, the machine stays usable) and reported in its submission's
// result; the honest submissions of the same batch are graded correctly. Skipped, with the
// reason, where the sim-server venv or bwrap is missing.
import { execFile } from 'node:child_process';
import { randomUUID } from 'node:crypto';
import { existsSync, mkdirSync, mkdtempSync, readdirSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { createServer, type Server } from 'node:net';
import { tmpdir } from 'node:os';
import path from 'node:path';
import { gradeSubmissions } from '@maa/grading';
import type { GradingSpec, SubmissionGrade } from '@maa/protocol/grading';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { feedbackText, gradingUnavailable, materialize, repo, simPython } from './grading-helpers.js';

const FIXTURE = path.join(repo, 'packages/lab-server/test/fixtures/grading/malicious');
const unavailable = gradingUnavailable();
if (unavailable !== undefined) console.warn(`grading-malicious.test.ts skipped: ${unavailable}`);

const work = mkdtempSync(path.join(tmpdir(), 'maa-grading-malicious-'));
const secret = `SECRET-of-honest-a-${randomUUID()}`;
const databaseSecret = `DATABASE-ROW-${randomUUID()}`;
const secretFile = path.join(work, 'submissions', 'honest-a', 'notes', 'secret.txt');
const databaseFile = path.join(work, 'lab-data', 'lab.db');
const outsideFile = path.join(work, 'outside', 'pwned.txt');
/** Unique, so the processes of this batch's fork bomb can be told from everything else on the machine. */
const bombId = `fork-bomb-${randomUUID().slice(0, 8)}`;

/** The "lab server": a TCP server on 127.0.0.1 that counts the connections it gets. */
let server: Server;
let connections = 0;
let port = 0;

afterAll(async () => {
    await new Promise<void>((resolve) => (server ? server.close(() => resolve()) : resolve()));
    rmSync(work, { recursive: true, force: true });
});

/** Submission id → its Doubler.timesync.py in the fixture's submissions/ folder. */
const SUBMISSIONS: Record<string, string> = {
    'honest-a': 'honest',
    'read-workspace': 'read-workspace',
    'read-database': 'read-database',
    'write-outside': 'write-outside',
    'connect-lab': 'connect-lab',
    [bombId]: 'fork-bomb',
    allocate: 'allocate',
    'run-forever': 'run-forever',
    'honest-b': 'honest',
};

function submission(id: string, source: string): { id: string; root: string; appFile: string } {
    const code = readFileSync(path.join(FIXTURE, 'submissions', `${source}.timesync.py`), 'utf8')
        .replace('__OTHER_WORKSPACE_FILE__', secretFile)
        .replace('__DATABASE_FILE__', databaseFile)
        .replace('__OUTSIDE_FILE__', outsideFile)
        .replace('__LAB_PORT__', String(port));
    const root = materialize(path.join(work, 'submissions', id), { 'calc/Doubler.timesync.py': code }, [path.join(FIXTURE, 'model')]);
    return { id, root, appFile: path.join(root, 'Calc.arcapp') };
}

/** Every file under `dir` (relative paths). */
function filesUnder(dir: string): string[] {
    if (!existsSync(dir)) return [];
    return (readdirSync(dir, { recursive: true, withFileTypes: true }) as import('node:fs').Dirent[])
        .filter((e) => e.isFile())
        .map((e) => path.join(e.parentPath, e.name));
}

/** The command lines of the machine's processes that mention `token`. */
function processesWith(token: string): string[] {
    const found: string[] = [];
    for (const pid of readdirSync('/proc').filter((p) => /^\d+$/.test(p))) {
        try {
            const cmdline = readFileSync(`/proc/${pid}/cmdline`, 'utf8').replaceAll('\0', ' ');
            if (cmdline.includes(token)) found.push(`${pid}: ${cmdline}`);
        } catch {
            // the process ended meanwhile
        }
    }
    return found;
}

describe.skipIf(unavailable !== undefined)('grading a batch with malicious handwritten components', () => {
    let grades: Map<string, SubmissionGrade>;
    let spec: GradingSpec;

    beforeAll(async () => {
        server = createServer((socket) => {
            connections++;
            socket.destroy();
        });
        await new Promise<void>((resolve) => server.listen(0, '127.0.0.1', resolve));
        port = (server.address() as import('node:net').AddressInfo).port;
        mkdirSync(path.dirname(databaseFile), { recursive: true });
        writeFileSync(databaseFile, `${databaseSecret}\n`);
        mkdirSync(path.dirname(outsideFile), { recursive: true });
        const submissions = Object.entries(SUBMISSIONS).map(([id, source]) => submission(id, source));
        mkdirSync(path.dirname(secretFile), { recursive: true });
        writeFileSync(secretFile, `${secret}\n`);

        const gradingDir = path.join(FIXTURE, 'grading');
        spec = JSON.parse(readFileSync(path.join(gradingDir, 'grading.json'), 'utf8')) as GradingSpec;
        const result = await gradeSubmissions({ spec, gradingDir, submissions, workDir: path.join(work, 'grading'), python: simPython });
        grades = new Map(result.map((g) => [g.submission, g]));
    }, 900_000);

    function grade(id: string): SubmissionGrade {
        const g = grades.get(id);
        if (g === undefined) throw new Error(`no grade for ${id} (got ${[...grades.keys()].join(', ')})`);
        return g;
    }
    function tests(id: string): SubmissionGrade['criteria'][number] {
        const c = grade(id).criteria.find((x) => x.id === 'hidden-tests');
        if (c === undefined) throw new Error(`${id}: no hidden-tests criterion`);
        return c;
    }
    /** The submission's result reports the attack: its test task failed or was stopped, with a message, and the tests lost their points. */
    function expectReported(id: string, why: RegExp): void {
        const g = grade(id);
        expect(g.criteria.find((c) => c.id === 'no-errors')?.score).toBe(1);
        expect(tests(id).score).toBe(0);
        const failed = g.tasks.filter((t) => t.status !== 'ok');
        expect(failed.length, `${id}: a task that did not end ok`).toBeGreaterThan(0);
        for (const t of failed) expect(t.message ?? '', `${id}: the task's message`).not.toBe('');
        const said = [...failed.map((t) => `${t.status}: ${t.message ?? ''}`), feedbackText(tests(id))].join('\n');
        expect(said, `${id}: the result says why`).toMatch(why);
    }

    it('grades the two honest submissions of the batch correctly', () => {
        for (const id of ['honest-a', 'honest-b']) {
            const g = grade(id);
            expect(g.score, id).toBe(g.maxScore);
            expect(g.maxScore).toBe(10);
            expect(g.tasks.map((t) => t.status)).toEqual(g.tasks.map(() => 'ok'));
        }
        expect(grades.size).toBe(Object.keys(SUBMISSIONS).length);
    });

    it("another student's workspace is out of reach, and its secret in no output", () => {
        expectReported('read-workspace', /No such file|Permission denied|not permitted/i);
        expect(JSON.stringify([...grades.values()])).not.toContain(secret);
        const leaked = filesUnder(work)
            .filter((f) => f !== secretFile)
            .filter((f) => readFileSync(f).includes(secret));
        expect(leaked).toEqual([]);
    });

    it("the lab's database file is out of reach, and its content in no output", () => {
        expectReported('read-database', /No such file|Permission denied|not permitted/i);
        expect(JSON.stringify([...grades.values()])).not.toContain(databaseSecret);
        const leaked = filesUnder(work)
            .filter((f) => f !== databaseFile)
            .filter((f) => readFileSync(f).includes(databaseSecret));
        expect(leaked).toEqual([]);
    });

    it('nothing is written outside the output directory', () => {
        expectReported('write-outside', /No such file|Read-only|Permission denied|not permitted/i);
        expect(existsSync(outsideFile)).toBe(false);
        expect(readdirSync(path.dirname(outsideFile))).toEqual([]);
        expect(filesUnder(work).filter((f) => path.basename(f) === 'planted.py')).toEqual([]);
    });

    it('the lab server gets no connection', () => {
        expectReported('connect-lab', /refused|unreachable|Network|not permitted|timed out/i);
        expect(connections).toBe(0);
    });

    it('a fork bomb is stopped by the process and time limits, and leaves no process behind', async () => {
        expectReported(bombId, /limit|killed|timeout|process/i);
        expect(processesWith(bombId)).toEqual([]);
        // The machine still starts processes.
        const out = await new Promise<string>((resolve, reject) =>
            execFile(process.execPath, ['-e', 'console.log("still fine")'], (e, stdout) => (e ? reject(e) : resolve(stdout))),
        );
        expect(out.trim()).toBe('still fine');
    });

    it('unbounded allocation is stopped by the memory limit', () => {
        expectReported('allocate', /memory/i);
    });

    it('a component that runs forever is stopped by the CPU or wall time limit', () => {
        expectReported('run-forever', /time limit|CPU|timeout|timed out/i);
        const t = grade('run-forever').tasks.find((x) => x.status !== 'ok');
        expect(['timeout', 'killed']).toContain(t?.status);
    });
});
