import { existsSync, mkdtempSync, readFileSync, readdirSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import path from 'node:path';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { ensureVenv, lintPython, packageDir, repoDir, run, venvPython } from './python-env.js';

// The montiarc-io conformance suite (MontiArc's Java simulator's stream tests as data), read from
// ../shared at test time: every case's component is generated with the timesync family, its
// steps run through the stream-test entry point, and the outputs are compared item by item
// with types (test/python/io_cases.py). Skipped when the suite is absent.
const suite = path.resolve(repoDir, '..', 'shared', 'conformance', 'montiarc-io');
const present = existsSync(path.join(suite, 'io_cases.json'));

interface Case { id: string }
interface Result { id: string; passed: boolean; reason: string | null }

function testClass(id: string): string {
    const i = id.indexOf('Test.');
    return i < 0 ? id.replace(/\.[^.]*$/, '') : id.slice(0, i + 4);
}

const classes: string[] = present
    ? [...new Set((JSON.parse(readFileSync(path.join(suite, 'io_cases.json'), 'utf8')).cases as Case[]).map((c) => testClass(c.id)))].sort()
    : [];

describe.skipIf(!present)('montiarc-io conformance (python-timesync)', () => {
    let results: Result[] = [];
    // A fresh folder per run: concurrent test runs must not share it.
    const cache = mkdtempSync(path.join(tmpdir(), 'maa-montiarc-io-'));
    afterAll(() => rmSync(cache, { recursive: true, force: true }));
    beforeAll(async () => {
        await ensureVenv();
        const gen = await run(process.execPath, [path.join(packageDir, 'scripts', 'generate-io-cases.mjs'), suite, cache], packageDir);
        if (gen.status !== 0) throw new Error(`generate-io-cases failed:\n${gen.stdout}\n${gen.stderr}`);
        const report = path.join(cache, 'report.json');
        const py = await run(venvPython, [path.join(packageDir, 'test', 'python', 'io_cases.py'), suite, cache, report], packageDir);
        if (py.status !== 0) throw new Error(`io_cases.py failed:\n${py.stdout}\n${py.stderr}`);
        results = JSON.parse(readFileSync(report, 'utf8')) as Result[];
        const rows = classes.map((k) => {
            const mine = results.filter((r) => testClass(r.id) === k);
            return `${String(mine.filter((r) => r.passed).length).padStart(3)}/${String(mine.length).padEnd(3)} ${k}`;
        });
        const passed = results.filter((r) => r.passed).length;
        console.log(`montiarc-io pass rate per test class:\n${rows.join('\n')}\ntotal: ${passed}/${results.length} (${((100 * passed) / Math.max(1, results.length)).toFixed(1)}%)`);
    }, 900_000);

    it('runs every case', () => {
        expect(results.length).toBeGreaterThan(0);
    });

    it.each(classes)('%s', (k) => {
        const failed = results.filter((r) => testClass(r.id) === k && !r.passed).map((r) => `${r.id}: ${r.reason}`);
        expect(failed).toEqual([]);
    });

    it('the generated code passes ruff check and py_compile', async () => {
        const builds = path.join(cache, 'builds');
        const problems: string[] = [];
        for (const b of readdirSync(builds).sort()) problems.push(...(await lintPython(path.join(builds, b, 'timesync'))));
        expect(problems).toEqual([]);
    }, 300_000);
});
