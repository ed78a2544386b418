// `npm test` tells the truth: every kind of failure is counted in the closing line, and the exit
// code agrees with it. The Vitest outcome reporter runs on a small project with one failure of
// each kind (scripts/test/fixtures/outcome) in a Vitest of its own; the tally and the pytest
// report parser are checked directly.
import { execFile } from 'node:child_process';
import { mkdtempSync, readFileSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { promisify } from 'node:util';
import { afterAll, describe, expect, it } from 'vitest';
// @ts-expect-error -- a plain .mjs script without type declarations
import { junitCounts, parseTimes, stageTable, Tally } from '../test-summary.mjs';

const scripts = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..');
const repo = path.resolve(scripts, '..');

interface Outcome {
  passed: number;
  skipped: number;
  failedTests: string[];
  brokenFiles: string[];
  suiteErrors: string[];
  unhandledErrors: string[];
  slowest: Array<{ test: string; ms: number }>;
  slowestFiles: Array<{ file: string; ms: number }>;
}

describe('the Vitest outcome reporter', () => {
  const dir = mkdtempSync(path.join(tmpdir(), 'maa-outcome-'));
  afterAll(() => rmSync(dir, { recursive: true, force: true }));

  it('counts failed tests, unhandled errors, files that did not run and failed hooks, each by name', async () => {
    const outcomeFile = path.join(dir, 'outcome.json');
    const vitest = path.join(repo, 'node_modules', 'vitest', 'vitest.mjs');
    const run = promisify(execFile)(process.execPath, [
      vitest, 'run', '--root', path.join(scripts, 'test', 'fixtures', 'outcome'),
      '--reporter=dot', `--reporter=${path.join(scripts, 'vitest-outcome-reporter.mjs')}`,
    ], { cwd: repo, env: { ...process.env, MAA_VITEST_OUTCOME: outcomeFile } });
    // The probe project fails on purpose: Vitest exits 1.
    await expect(run).rejects.toMatchObject({ code: 1 });
    const outcome = JSON.parse(readFileSync(outcomeFile, 'utf8')) as Outcome;
    expect(outcome.passed).toBe(2);
    expect(outcome.failedTests).toEqual([expect.stringMatching(/^tests\.probe\.mjs > fails: AssertionError/)]);
    expect(outcome.unhandledErrors).toEqual([expect.stringContaining('thrown after the test')]);
    expect(outcome.brokenFiles).toEqual([expect.stringMatching(/^broken-import\.probe\.mjs: .*no-such-module/)]);
    expect(outcome.suiteErrors).toEqual([expect.stringMatching(/^failing-hook\.probe\.mjs > a group whose hook fails: .*the hook failed/)]);
    // The explicitly skipped test and the one its failed hook kept from running.
    expect(outcome.skipped).toBe(2);
    expect(outcome.slowestFiles.map((f) => f.file).sort()).toEqual(['broken-import.probe.mjs', 'failing-hook.probe.mjs', 'tests.probe.mjs']);
  }, 120_000);
});

describe('the tally of npm test', () => {
  it('counts an unhandled error as a failure: the closing line and the exit code agree', () => {
    const tally = new Tally();
    tally.passed = 1061;
    tally.skipped = 2;
    tally.fail('unhandled errors', 'vitest: Error: [vitest-worker]: Timeout calling "onTaskUpdate"');
    const lines: string[] = tally.summary(8.5);
    expect(lines.at(-1)).toBe('tests: 1061 passed, 1 failed, 2 skipped');
    expect(lines).toContain('failures: 1 unhandled errors');
    expect(lines.join('\n')).toContain('Timeout calling "onTaskUpdate"');
    expect(tally.exitCode).toBe(1);
  });

  it('sums every kind into failed and names each kind', () => {
    const tally = new Tally();
    tally.passed = 10;
    tally.fail('failed tests', 'a > b');
    tally.fail('failed tests', 'c > d');
    tally.fail('linters that failed', 'sim-server mypy exited with 1');
    tally.fail('test files that did not run', 'x.test.ts: SyntaxError');
    const lines: string[] = tally.summary();
    expect(lines.at(-1)).toBe('tests: 10 passed, 4 failed, 0 skipped');
    expect(lines).toContain('failures: 2 failed tests, 1 linters that failed, 1 test files that did not run');
    expect(tally.exitCode).toBe(1);
  });

  it('exits 0 only when nothing failed and something passed', () => {
    const clean = new Tally();
    clean.passed = 3;
    expect(clean.exitCode).toBe(0);
    expect(clean.summary().at(-1)).toBe('tests: 3 passed, 0 failed, 0 skipped');
    const empty = new Tally();
    expect(empty.exitCode).toBe(1);
    expect(empty.summary()).toContain('test-all: no test was run');
  });
});

describe("pytest's JUnit report", () => {
  const report = (cases: string, attributes: string) => `<?xml version="1.0" encoding="utf-8"?><testsuites><testsuite name="pytest" ${attributes}>${cases}</testsuite></testsuites>`;

  it('names failures and errors (a fixture that failed outside the test body)', () => {
    const xml = report(
      '<testcase classname="tests.test_a" name="test_ok" time="0.1" />'
      + '<testcase classname="tests.test_a" name="test_bad" time="0.1"><failure message="assert 1 == 2&#10;more">trace</failure></testcase>'
      + '<testcase classname="tests.test_b" name="test_setup" time="0.1"><error message="failed on setup with &quot;OSError&quot;">trace</error></testcase>'
      + '<testcase classname="tests.test_b" name="test_skip" time="0"><skipped message="no ros" /></testcase>',
      'errors="1" failures="1" skipped="1" tests="4"',
    );
    expect(junitCounts(xml)).toEqual({
      passed: 1,
      skipped: 1,
      failed: ['tests.test_a::test_bad: assert 1 == 2'],
      errors: ['tests.test_b::test_setup: failed on setup with "OSError"'],
    });
  });

  it('counts what the attributes say even when no case names it, and refuses a text without a suite', () => {
    const counts = junitCounts(report('', 'errors="1" failures="0" skipped="0" tests="1"'));
    expect(counts).toEqual({ passed: 0, skipped: 0, failed: [], errors: ['an error (not named in the report)'] });
    expect(junitCounts('not xml')).toBeUndefined();
  });
});

describe('the time per stage', () => {
  it("reads the children's user + sys from bash's times, and nothing from other text", () => {
    expect(parseTimes('0m0.002s 0m0.000s\n1m2.500s 0m0.250s\n')).toBe(62_750);
    expect(parseTimes('0m0.002s 0m0.000s\n')).toBeUndefined();
    expect(parseTimes('')).toBeUndefined();
  });

  it('lists each stage with its start, wall and CPU time, a stage without a CPU time as ?, and the totals', () => {
    const lines: string[] = stageTable(
      [
        { title: 'build', startMs: 0, wallMs: 60_000, cpuMs: 90_000 },
        { title: 'vitest', startMs: 60_000, wallMs: 300_000, cpuMs: 400_500 },
        { title: 'e2e', startMs: 360_000, wallMs: 1_000, cpuMs: undefined },
      ],
      361_000,
    );
    expect(lines).toContain('  build      0.0 s    60.0 s    90.0 s');
    expect(lines).toContain('  vitest    60.0 s   300.0 s   400.5 s');
    expect(lines).toContain('  e2e      360.0 s     1.0 s         ?');
    expect(lines.at(-1)).toBe('  total      0.0 s   361.0 s   490.5 s');
  });
});
