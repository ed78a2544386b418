// The exercises under examples/lab/ are solvable: their starter has the expected diagnostics and
// failing stream tests, the starter with the reference solution (solution/, never released) over
// it passes `maa-gen check` and `maa-gen test` (the real CLI, on the generators-python venv).
import { execFile } from 'node:child_process';
import { cpSync, mkdtempSync, readFileSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { afterAll, describe, expect, it } from 'vitest';
import { loadExercise } from '../src/exercises/index.js';

const repo = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '../../..');
const MAA_GEN = path.join(repo, 'packages/cli/bin/maa-gen.js');
const python = path.join(repo, 'packages/generators-python/.venv/bin/python');
const work = mkdtempSync(path.join(tmpdir(), 'maa-lab-examples-'));
afterAll(() => rmSync(work, { recursive: true, force: true }));

interface Run {
    code: number;
    stdout: string;
}

function maaGen(args: string[], cwd: string): Promise<Run> {
    return new Promise((resolve, reject) => {
        execFile(
            process.execPath,
            [MAA_GEN, ...args],
            { cwd, env: { ...process.env, NO_COLOR: '1', MAA_PYTHON: python } },
            (error, stdout) => {
                if (error && typeof error.code !== 'number') reject(error);
                else resolve({ code: error ? (error.code as number) : 0, stdout });
            },
        );
    });
}

interface Diagnostic {
    severity: string;
    code: string;
}
interface TestResult {
    test: string | null;
    passed: boolean;
}

async function check(dir: string): Promise<{ code: number; diagnostics: Diagnostic[] }> {
    const r = await maaGen(['check', '.', '--format', 'json'], dir);
    return { code: r.code, diagnostics: (JSON.parse(r.stdout) as { diagnostics: Diagnostic[] }).diagnostics };
}

/** The stream tests' results and the generation's diagnostics (no results when the models do not generate). */
async function streamTests(dir: string, app: string): Promise<{ code: number; results: TestResult[]; errors: string[] }> {
    const r = await maaGen(['test', app, '--format', 'json'], dir);
    const report = JSON.parse(r.stdout) as { results: TestResult[]; diagnostics: Diagnostic[] };
    const errors = report.diagnostics.filter((d) => d.severity === 'error').map((d) => d.code);
    return { code: r.code, results: report.results, errors };
}

/** A copy of the exercise's starter, and one with its solution over it. */
function copies(name: string): { starter: string; solved: string } {
    const exercise = path.join(repo, 'examples/lab', name);
    const starter = path.join(work, name, 'starter');
    const solved = path.join(work, name, 'solved');
    cpSync(path.join(exercise, 'starter'), starter, { recursive: true });
    cpSync(path.join(exercise, 'starter'), solved, { recursive: true });
    cpSync(path.join(exercise, 'solution'), solved, { recursive: true });
    return { starter, solved };
}

const EXERCISES = [
    { name: 'toast-controller', starterErrors: [] as string[], failingTests: 4 },
    {
        name: 'pick-and-place',
        starterErrors: ['robotarm/command-without-program', 'robotarm/command-without-program'],
        failingTests: undefined,
    },
    { name: 'line-follower', starterErrors: [] as string[], failingTests: 4 },
];

describe.each(EXERCISES)('examples/lab/$name', ({ name, starterErrors, failingTests }) => {
    it('the starter has the expected diagnostics and failing stream tests; the solution passes check and test', async () => {
        const { manifest } = await loadExercise(path.join(repo, 'examples/lab', name));
        const { starter, solved } = copies(name);

        const before = await check(starter);
        expect(before.diagnostics.filter((d) => d.severity === 'error').map((d) => d.code)).toEqual(starterErrors);
        expect(before.code).toBe(starterErrors.length > 0 ? 1 : 0);
        const failing = await streamTests(starter, manifest.app);
        expect(failing.code).toBe(1);
        if (failingTests !== undefined) expect(failing.results.filter((r) => !r.passed)).toHaveLength(failingTests);
        // A starter with errors does not generate: its tests fail on those errors.
        expect(failing.errors).toEqual(starterErrors);

        const after = await check(solved);
        expect(after.diagnostics).toEqual([]);
        expect(after.code).toBe(0);
        const passing = await streamTests(solved, manifest.app);
        expect(passing.results.length).toBeGreaterThan(3);
        expect(passing.results.filter((r) => !r.passed)).toEqual([]);
        expect(passing.code).toBe(0);
    });
});

describe('examples/lab/toast-controller', () => {
    it('gives the rest of examples/toast-service unchanged (read-only), so the two never drift', async () => {
        const { files, manifest } = await loadExercise(path.join(repo, 'examples/lab/toast-controller'));
        const given = Object.keys(files).filter((f) => f !== 'toast/Controller.arc');
        expect(given.length).toBeGreaterThan(10);
        for (const rel of given) {
            expect(files[rel], rel).toBe(readFileSync(path.join(repo, 'examples/toast-service', rel), 'utf8'));
            expect(
                manifest.readOnly.some((e) => rel === e || (e.endsWith('/') && rel.startsWith(e))),
                rel,
            ).toBe(true);
        }
        const solution = readFileSync(path.join(repo, 'examples/lab/toast-controller/solution/toast/Controller.arc'), 'utf8');
        expect(solution).toBe(readFileSync(path.join(repo, 'examples/toast-service/toast/Controller.arc'), 'utf8'));
    });
});
