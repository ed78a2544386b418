import { existsSync, mkdtempSync, readFileSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import path from 'node:path';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { ensureVenv, packageDir, pythonFiles, repoDir, ruffConfig, run, venvPython } from './python-env.js';

// The montiarc-io conformance suites (MontiArc's Java simulator's stream tests as data), read
// from ../shared at test time: every case's component is generated with the timesync family (one
// build per component and feature configuration), its steps run through the stream-test entry
// point, and the outputs, state traces and extra assertions are checked
// (test/python/io_cases.py). Skipped when a suite is absent.
//
// - montiarc-io: every case, every test class at 100 %;
// - montiarc-io-extended (variable architectures, mode automata): the pass rate is printed, and
//   the cases whose constructs the generators support (EXTENDED_SUPPORTED, growing as they land)
//   must pass;
// - test/fixtures/io-harness: a suite of our own in the same format that uses every field of the
//   format the MontiArc suites do not (yet) use, so the harness itself is tested end to end.
const conformance = path.resolve(repoDir, '..', 'shared', 'conformance');
const harnessSuite = path.join(packageDir, 'test', 'fixtures', 'io-harness');

/**
 * Test classes (or single case ids) of montiarc-io-extended whose constructs are supported by the
 * generators: they must pass. Modes (helper 12-B) and feature configurations (helper 12-A) are
 * added here when their generation lands.
 */
const EXTENDED_SUPPORTED: readonly string[] = [
    // mode automata (12-B)
    'montiarc.modes.sync.SimpleTransitionTest',
    'montiarc.modes.sync.composition.InitiallyUnusedOutPortsTest',
    // feature configurations (12-A): one build per component and `features` of the case
    'montiarc.sync.variability.FieldSourceTest',
    'montiarc.sync.variability.OptionalDelayTest',
];

interface Case {
    id: string;
}
interface Result {
    id: string;
    passed: boolean;
    reason: string | null;
}
interface Generation {
    builds: Record<string, { ok: boolean; dir: string; errors: string[] }>;
    cases: Record<string, string>;
}

function testClass(id: string): string {
    const i = id.indexOf('Test.');
    return i < 0 ? id.replace(/\.[^.]*$/, '') : id.slice(0, i + 4);
}

function casesOf(suite: string): Case[] {
    return existsSync(path.join(suite, 'io_cases.json'))
        ? (JSON.parse(readFileSync(path.join(suite, 'io_cases.json'), 'utf8')).cases as Case[])
        : [];
}

/** The suites of this file that are present (a suite of ../shared may be absent). */
function presentSuites(): string[] {
    return [path.join(conformance, 'montiarc-io'), path.join(conformance, 'montiarc-io-extended'), harnessSuite].filter(
        (s) => casesOf(s).length > 0,
    );
}

// A fresh folder per run (concurrent test runs must not share it), a subfolder per suite.
const work = mkdtempSync(path.join(tmpdir(), 'maa-montiarc-io-'));
afterAll(() => rmSync(work, { recursive: true, force: true }));
const cacheOf = (suite: string): string => path.join(work, path.basename(suite));

let generated: Promise<void> | undefined;
/**
 * Generates every present suite's builds, once for the file and in one process: loading the
 * language services costs more than a second of CPU per process, and the builds of a suite share
 * them (scripts/generate-io-cases.mjs).
 */
function generateAll(): Promise<void> {
    generated ??= (async () => {
        await ensureVenv();
        const args = presentSuites().flatMap((s) => [s, cacheOf(s)]);
        const gen = await run(process.execPath, [path.join(packageDir, 'scripts', 'generate-io-cases.mjs'), ...args], packageDir);
        if (gen.status !== 0) throw new Error(`generate-io-cases failed:\n${gen.stdout}\n${gen.stderr}`);
    })();
    return generated;
}

/** Runs one suite's cases on its builds: the results and the generation report. */
function runSuite(suite: string): { results: () => Result[]; generation: () => Generation } {
    let results: Result[] = [];
    let generation: Generation = { builds: {}, cases: {} };
    beforeAll(async () => {
        await generateAll();
        const cache = cacheOf(suite);
        generation = JSON.parse(readFileSync(path.join(cache, 'generation.json'), 'utf8')) as Generation;
        const report = path.join(cache, 'report.json');
        const py = await run(venvPython, [path.join(packageDir, 'test', 'python', 'io_cases.py'), suite, cache, report], packageDir);
        if (py.status !== 0) throw new Error(`io_cases.py failed:\n${py.stdout}\n${py.stderr}`);
        results = JSON.parse(readFileSync(report, 'utf8')) as Result[];
        const classes = [...new Set(results.map((r) => testClass(r.id)))].sort();
        const rows = classes.map((k) => {
            const mine = results.filter((r) => testClass(r.id) === k);
            return `${String(mine.filter((r) => r.passed).length).padStart(3)}/${String(mine.length).padEnd(3)} ${k}`;
        });
        const passed = results.filter((r) => r.passed).length;
        console.log(
            `${path.basename(suite)} pass rate per test class:\n${rows.join('\n')}\ntotal: ${passed}/${results.length} (${((100 * passed) / Math.max(1, results.length)).toFixed(1)}%)`,
        );
    }, 900_000);
    return { results: () => results, generation: () => generation };
}

/**
 * `ruff check` (the package's settings) and `py_compile` of every build that generated: one run
 * of each over all builds (a Python process costs more than checking a build). ruff runs once
 * with every build folder as a source root, so each build's own packages count as first-party
 * in its import sorting, as when ruff runs inside the folder (python-env.ts, lintPython).
 */
async function lintBuilds(generation: Generation): Promise<string[]> {
    const dirs = Object.values(generation.builds)
        .filter((x) => x.ok)
        .map((x) => x.dir)
        .sort();
    if (dirs.length === 0) return [];
    const problems: string[] = [];
    const settings = ['--config', ruffConfig, '--config', `src = ${JSON.stringify(dirs)}`, '--no-cache'];
    const ruff = await run(venvPython, ['-m', 'ruff', 'check', ...settings, '--output-format', 'concise', ...dirs], packageDir);
    if (ruff.status !== 0) problems.push(`ruff check:\n${ruff.stdout}${ruff.stderr}`);
    // Compiled into a temporary folder, so the generated folders stay free of __pycache__; a text
    // compiled once is not compiled again (the run-time environment every build holds a copy of).
    const compile = await run(
        venvPython,
        [
            '-c',
            [
                'import os, sys, py_compile, tempfile',
                'seen = set()',
                'with tempfile.TemporaryDirectory() as d:',
                '    for i, f in enumerate(sys.stdin.read().splitlines()):',
                '        with open(f, "rb") as h:',
                '            text = h.read()',
                '        if text not in seen:',
                '            seen.add(text)',
                '            py_compile.compile(f, cfile=os.path.join(d, f"{i}.pyc"), doraise=True)',
            ].join('\n'),
        ],
        packageDir,
        dirs.flatMap((d) => pythonFiles(d)).join('\n'),
    );
    if (compile.status !== 0) problems.push(`py_compile:\n${compile.stderr}`);
    return problems;
}

const ioSuite = path.join(conformance, 'montiarc-io');
const ioClasses = [...new Set(casesOf(ioSuite).map((c) => testClass(c.id)))].sort();

describe.skipIf(ioClasses.length === 0)('montiarc-io conformance (python-timesync)', () => {
    const s = runSuite(ioSuite);

    it('runs every case', () => {
        expect(s.results().length).toBe(casesOf(ioSuite).length);
    });

    it.each(ioClasses)('%s', (k) => {
        const failed = s
            .results()
            .filter((r) => testClass(r.id) === k && !r.passed)
            .map((r) => `${r.id}: ${r.reason}`);
        expect(failed).toEqual([]);
    });

    it('the generated code passes ruff check and py_compile', async () => {
        expect(await lintBuilds(s.generation())).toEqual([]);
    }, 300_000);
});

const extendedSuite = path.join(conformance, 'montiarc-io-extended');
const extendedCases = casesOf(extendedSuite);

describe.skipIf(extendedCases.length === 0)('montiarc-io-extended conformance (python-timesync)', () => {
    const s = runSuite(extendedSuite);
    const supported = (id: string): boolean => EXTENDED_SUPPORTED.includes(id) || EXTENDED_SUPPORTED.includes(testClass(id));

    it('runs every case, one build per component and feature configuration', () => {
        expect(
            s
                .results()
                .map((r) => r.id)
                .sort(),
        ).toEqual(extendedCases.map((c) => c.id).sort());
        const variants = new Set(Object.values(s.generation().cases));
        const configurations = new Set(
            extendedCases.map((c) =>
                JSON.stringify([
                    (c as Case & { component: string }).component,
                    Object.entries((c as Case & { features?: Record<string, boolean> }).features ?? {}).sort(),
                ]),
            ),
        );
        expect(variants.size).toBe(configurations.size);
    });

    it('every supported case passes', () => {
        const failed = s
            .results()
            .filter((r) => supported(r.id) && !r.passed)
            .map((r) => `${r.id}: ${r.reason}`);
        expect(failed).toEqual([]);
        const unlisted = s
            .results()
            .filter((r) => r.passed && !supported(r.id))
            .map((r) => r.id);
        if (unlisted.length > 0)
            console.log(`montiarc-io-extended: passing but not yet in EXTENDED_SUPPORTED:\n  ${unlisted.join('\n  ')}`);
    });

    it('the generated code passes ruff check and py_compile', async () => {
        expect(await lintBuilds(s.generation())).toEqual([]);
    }, 300_000);
});

describe('the io-case harness on a suite of its own (every field of the format)', () => {
    const s = runSuite(harnessSuite);
    const expectations = JSON.parse(readFileSync(path.join(harnessSuite, 'expectations.json'), 'utf8')) as Record<string, string | null>;

    it.each(Object.keys(expectations).sort())('%s', (id) => {
        const r = s.results().find((x) => x.id === id);
        expect(r, `no result for ${id}`).toBeDefined();
        const want = expectations[id];
        if (want === null) expect(r!.reason).toBeNull();
        else expect(r!.reason ?? '').toContain(want);
        expect(r!.passed).toBe(want === null);
    });

    it('scores every case of the suite', () => {
        expect(
            s
                .results()
                .map((r) => r.id)
                .sort(),
        ).toEqual(Object.keys(expectations).sort());
    });
});
