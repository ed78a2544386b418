// The exercises under examples/lab/ are solvable: their starter (as the loader gives it: with an
// exercise's base) has the expected diagnostics and failing stream tests, the starter with the
// reference solution (solution/, never released) over it passes `maa-gen check` and `maa-gen test`
// (the real CLI's main(), in a worker thread, on the generators-python venv).
import { cpSync, existsSync, mkdirSync, mkdtempSync, readdirSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { afterAll, describe, expect, it } from 'vitest';
// The CLI's own test helper: maa-gen's main() in one warm worker thread of this file instead of a
// cold process per command (about a second of CPU each, most of it loading; docs/testing.md).
import { requireBuiltCli, runCliInProcess } from '../../cli/test/helpers.js';
import { loadExercise } from '../src/exercises/index.js';

const repo = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '../../..');
const python = path.join(repo, 'packages/generators-python/.venv/bin/python');
const work = mkdtempSync(path.join(tmpdir(), 'maa-lab-examples-'));
afterAll(() => rmSync(work, { recursive: true, force: true }));
requireBuiltCli();

interface Run {
    code: number;
    stdout: string;
}

async function maaGen(args: string[], cwd: string): Promise<Run> {
    const r = await runCliInProcess(args, cwd, { MAA_PYTHON: python });
    return { code: r.code ?? -1, stdout: r.stdout };
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

/** The exercise's starter as released (written out), and one with its solution over it. */
function copies(name: string, files: Record<string, string>): { starter: string; solved: string } {
    const starter = path.join(work, name, 'starter');
    const solved = path.join(work, name, 'solved');
    for (const dir of [starter, solved])
        for (const [rel, content] of Object.entries(files)) {
            const file = path.join(dir, ...rel.split('/'));
            mkdirSync(path.dirname(file), { recursive: true });
            writeFileSync(file, content);
        }
    cpSync(path.join(repo, 'examples/lab', name, 'solution'), solved, { recursive: true });
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
        const { manifest, files } = await loadExercise(path.join(repo, 'examples/lab', name));
        const { starter, solved } = copies(name, files);

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
    it('takes the rest of examples/toast-service from its base (read-only), so there is no copy to drift', async () => {
        const folder = path.join(repo, 'examples/lab/toast-controller');
        const { files, manifest } = await loadExercise(folder);
        expect(manifest.base).toBe('../../toast-service');
        // starter/ holds only what differs: the stub Controller.
        expect(readdirSync(path.join(folder, 'starter'), { recursive: true, encoding: 'utf8' }).sort()).toEqual([
            'toast',
            'toast/Controller.arc',
        ]);
        const given = Object.keys(files).filter((f) => f !== 'toast/Controller.arc');
        expect(given.length).toBeGreaterThan(10);
        for (const rel of given) {
            expect(existsSync(path.join(folder, 'starter', rel)), rel).toBe(false);
            expect(files[rel], rel).toBe(readFileSync(path.join(repo, 'examples/toast-service', rel), 'utf8'));
            expect(
                manifest.readOnly.some((e) => rel === e || (e.endsWith('/') && rel.startsWith(e))),
                rel,
            ).toBe(true);
        }
        // The example's own tests of other components, its README and its RobotArm program are not handed out.
        for (const omitted of manifest.omit ?? []) expect(files[omitted], omitted).toBeUndefined();
        expect(Object.keys(files).filter((f) => f.endsWith('.stream'))).toEqual(manifest.tests);
        // The stub replaces the example's Controller, which is the reference solution.
        expect(files['toast/Controller.arc']).not.toBe(
            readFileSync(path.join(repo, 'examples/toast-service/toast/Controller.arc'), 'utf8'),
        );
        const solution = readFileSync(path.join(folder, 'solution/toast/Controller.arc'), 'utf8');
        expect(solution).toBe(readFileSync(path.join(repo, 'examples/toast-service/toast/Controller.arc'), 'utf8'));
    });
});
