// `maa-gen test --case`: only the named stream tests are reported (the run the VS Code test
// explorer makes for one case), on the toast example with the generators-python venv's Python.
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { describe, expect, it } from 'vitest';
import { selectCases, type StreamTestResult } from '../src/commands/test.js';
import { ModelDir, requireBuiltCli, runCliInProcess } from './helpers.js';

const repo = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..', '..', '..');
const python = path.join(repo, 'packages', 'generators-python', '.venv', 'bin', 'python');
const APP = 'examples/toast-service/TR.arcapp';
const CONTROLLER = 'examples/toast-service/toast/Controller.stream';

const result = (file: string, test: string | null, passed = true): StreamTestResult => ({
    file,
    test,
    line: test ? 3 : 0,
    passed,
    problems: passed ? [] : ['x: expected 1; got 2'],
});

describe('selectCases', () => {
    const results = [result('a.stream', 'one'), result('a.stream', 'two', false), result('b.stream', 'one')];

    it('keeps every result without --case', async () => {
        expect(await selectCases(results, undefined)).toEqual(results);
        expect(await selectCases(results, [])).toEqual(results);
    });

    it('keeps the results of the named tests, in every file', async () => {
        expect((await selectCases(results, ['one'])).map((r) => `${r.file}:${r.test}`)).toEqual(['a.stream:one', 'b.stream:one']);
        expect(await selectCases(results, ['two', 'one'])).toHaveLength(3);
    });

    it('refuses a name no file has a test of', async () => {
        await expect(selectCases(results, ['one', 'three'])).rejects.toThrow('no stream test named "three"');
    });

    it('keeps the error of a file that did not run (its cases may be the named ones)', async () => {
        const broken = [result('c.stream', null, false), ...results];
        expect(await selectCases(broken, ['three'])).toEqual([broken[0]]);
    });
});

describe('maa-gen test --case (toast example)', () => {
    it('reports only the named tests', async () => {
        requireBuiltCli();
        const names = ['a plate starts loading the bread', 'a burnt toast is not served'];
        const r = await runCliInProcess(
            ['test', APP, CONTROLLER, '--format', 'json', '--python', python, '--case', names[0]!, '-c', names[1]!],
            repo,
        );
        expect(r.code, r.stderr).toBe(0);
        const report = JSON.parse(r.stdout) as { results: StreamTestResult[]; summary: { passed: number; failed: number } };
        expect(report.results.map((x) => x.test)).toEqual(names);
        expect(report.results.every((x) => x.passed && x.file === CONTROLLER)).toBe(true);
        expect(report.results.map((x) => x.line)).toEqual([15, 33]);
        expect(report.summary).toEqual({ generated: true, passed: 2, failed: 0 });
    }, 180_000);

    it('exits 2 for a name no test has', async () => {
        requireBuiltCli();
        const r = await runCliInProcess(['test', APP, CONTROLLER, '--python', python, '--case', 'no such test'], repo);
        expect(r.code).toBe(2);
        expect(r.stderr).toContain('no stream test named "no such test"');
    }, 180_000);
});

describe('maa-gen test --format json when the models do not generate', () => {
    it('prints one JSON object: the diagnostics, no results, summary.generated false; exit 1', async () => {
        requireBuiltCli();
        const models = new ModelDir();
        try {
            models.write('maa.json', '{}\n');
            models.write('a/Broken.arc', 'package a;\ncomponent Broken {\n  port in int i;\n  port out int o;\n  i -> nowhere;\n}\n');
            models.write('a/Broken.stream', 'stream test for a.Broken;\n');
            models.write(
                'App.arcapp',
                'application App for a.Broken {\n  platform timesync {\n    timesync.Components;\n    timesync.DataTypes;\n  }\n}\n',
            );
            const r = await runCliInProcess(['test', 'App.arcapp', '--format', 'json', '--python', python], models.dir);
            expect(r.code, r.stderr).toBe(1);
            const report = JSON.parse(r.stdout) as {
                diagnostics: Array<{ file: string; line: number; severity: string; code: string }>;
                results: unknown[];
                summary: { generated: boolean; passed: number; failed: number };
            };
            expect(report.summary).toEqual({ generated: false, passed: 0, failed: 0 });
            expect(report.results).toEqual([]);
            expect(report.diagnostics.some((d) => d.severity === 'error' && d.file.endsWith('Broken.arc') && d.line === 5)).toBe(true);
            expect(r.stderr).toContain('generation failed');
        } finally {
            models.dispose();
        }
    }, 180_000);
});
