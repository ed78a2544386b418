// The stream tests' logic without an editor: the outline of real `.stream` files (cases and the
// statements that can fail), which application runs a file (maa-gen test's rule), the CLI runner
// on a copy of the toast example with one wrong expected stream (a real `maa-gen test` run), and
// the report mapped to passed / failed (a diff at the port's statement) / errored outcomes.
import { cpSync, mkdtempSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import path from 'node:path';
import { fileURLToPath, pathToFileURL } from 'node:url';
import { LANGUAGE_FACTS } from '@maa/language-server/language-facts';
import { afterAll, describe, expect, it } from 'vitest';
import { contributions } from '../src/contributions.js';
import { appOfStreamFile, walkedFrom } from '../src/testing/association.js';
import { CliStreamTestRunner, testArgs } from '../src/testing/cli-runner.js';
import { caseOutcome, fileOutcome, parseTestReport, problemMessage, resultOfCase } from '../src/testing/report.js';
import type { FileRef } from '../src/testing/runner.js';
import { outlineStreamFile } from '../src/testing/stream-file.js';

const repo = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..', '..', '..');
const maaGen = path.join(repo, 'packages', 'cli', 'bin', 'maa-gen.js');
const python = path.join(repo, 'packages', 'generators-python', '.venv', 'bin', 'python');
const toast = path.join(repo, 'examples', 'toast-service');
const tmp = mkdtempSync(path.join(tmpdir(), 'maa-vscode-streams-'));
afterAll(() => rmSync(tmp, { recursive: true, force: true }));

const fileRef = (fsPath: string): FileRef => ({ uri: pathToFileURL(fsPath).toString(), path: fsPath, fsPath });

describe('outline of a .stream file', () => {
    it('finds the cases of the toast controller with their ranges and failing statements', () => {
        const text = readFileSync(path.join(toast, 'toast', 'Controller.stream'), 'utf8');
        const outline = outlineStreamFile(text);
        expect(outline.component).toBe('toast.Controller');
        expect(outline.cases.map((c) => c.name)).toEqual([
            'nothing happens while no plate is in front of the robot',
            'a plate starts loading the bread',
            'a whole service: load, toast until golden, deliver',
            'a burnt toast is not served',
            'the states of a whole service, slice by slice',
        ]);
        const lines = text.split('\n');
        // 0-based: `test "a plate starts loading the bread" {` is line 15 of the file.
        const plate = outline.cases[1]!;
        expect(plate.range).toMatchObject({ line: 14, character: 0, endLine: 21 });
        expect(lines[plate.range.endLine]).toBe('}');
        expect(Object.keys(plate.expected)).toEqual(['toaster', 'arm']);
        expect(lines[plate.expected['arm']!.line]).toContain('arm      == NONE Tk Tk LOAD_BREAD Tk;');
        expect(plate.states.map((s) => lines[s.line]!.trim())).toEqual(['state    == Loading;']);
        const burnt = outline.cases[3]!;
        expect(lines[burnt.expected['toaster']!.line]).toContain('toaster  ~= STOP START;');
        const steps = outline.cases[4]!;
        expect(steps.states).toHaveLength(7);
        expect(steps.empties).toHaveLength(1);
        // Inputs (`distance = …`) are not expected streams.
        expect(Object.keys(steps.expected)).toEqual(['toaster', 'arm']);
    });

    it('skips tests inside comments and strings and survives broken text', () => {
        const text = [
            'component lib.Delay<Long>; // test "in a comment" {',
            'test "a \\"quoted\\" name" {',
            '  i = "test \\"fake\\" {" Tk;',
            "  c == 'x' Tk; // o == 1;",
            '}',
            'test "unclosed" {',
            '  o == 1',
        ].join('\n');
        const outline = outlineStreamFile(text);
        expect(outline.component).toBe('lib.Delay');
        expect(outline.cases.map((c) => c.name)).toEqual(['a "quoted" name', 'unclosed']);
        expect(Object.keys(outline.cases[0]!.expected)).toEqual(['c']);
        expect(outline.cases[1]!.range).toMatchObject({ line: 5, endLine: 6 });
        expect(Object.keys(outline.cases[1]!.expected)).toEqual(['o']);
        expect(outlineStreamFile('')).toEqual({ cases: [] });
        expect(outlineStreamFile('test "x" {').cases.map((c) => c.name)).toEqual(['x']);
    });
});

describe('which application runs a stream file', () => {
    const app = (p: string, platform = 'timesync') => ({
        path: p,
        text: `application A for a.B {\n  platform ${platform} { timesync.Components; }\n}\n`,
    });
    const markers = new Set(['/w/toast', '/w/toast/nested']);
    const hasMarker = (dir: string): boolean => markers.has(dir);

    it('is an application whose model root holds the file, the nearest root first', () => {
        const apps = [app('/w/toast/TR.arcapp'), app('/w/toast/nested/N.arcapp')];
        expect(appOfStreamFile('/w/toast/t/C.stream', apps, hasMarker, '/w')).toBe('/w/toast/TR.arcapp');
        expect(appOfStreamFile('/w/toast/nested/x/D.stream', apps, hasMarker, '/w')).toBe('/w/toast/nested/N.arcapp');
        // Without maa.json the root is the application's folder.
        expect(appOfStreamFile('/w/other/E.stream', [app('/w/other/O.arcapp')], hasMarker, '/w')).toBe('/w/other/O.arcapp');
    });

    it('is none outside every root, in a folder maa-gen test skips, or without a timesync platform', () => {
        expect(appOfStreamFile('/w/else/C.stream', [app('/w/toast/TR.arcapp')], hasMarker, '/w')).toBeUndefined();
        expect(appOfStreamFile('/w/toast/generated/C.stream', [app('/w/toast/TR.arcapp')], hasMarker, '/w')).toBeUndefined();
        expect(appOfStreamFile('/w/toast/C.stream', [app('/w/toast/TR.arcapp', 'rospython')], hasMarker, '/w')).toBeUndefined();
        expect(walkedFrom('/w/toast', '/w/toast/.hidden/C.stream')).toBe(false);
        expect(walkedFrom('/w/toast', '/w/toast/a/node_modules/C.stream')).toBe(false);
        expect(walkedFrom('/w/toast', '/w/toastie/C.stream')).toBe(false);
    });

    it('matches the example: toast-service/TR.arcapp runs its three stream files', () => {
        const tr = { path: path.join(toast, 'TR.arcapp'), text: readFileSync(path.join(toast, 'TR.arcapp'), 'utf8') };
        const hasExampleMarker = (dir: string): boolean => dir === toast;
        for (const f of ['Controller', 'ToasterController', 'ArmController']) {
            expect(appOfStreamFile(path.join(toast, 'toast', `${f}.stream`), [tr], hasExampleMarker, repo)).toBe(tr.path);
        }
    });
});

describe('report mapping', () => {
    const outline = outlineStreamFile(readFileSync(path.join(toast, 'toast', 'Controller.stream'), 'utf8'));
    const plate = outline.cases[1]!;

    it('a port comparison is a diff at the port statement; a state comparison at its line', () => {
        const port = problemMessage('arm: expected NONE Tk; got NONE Tk Tk', plate);
        expect(port.comparison).toBe(true);
        expect(port.message).toMatchObject({ expected: 'NONE Tk', actual: 'NONE Tk Tk', span: plate.expected['arm'] });
        const state = problemMessage('state (line 21): expected Loading; got Idle', plate);
        expect(state.message).toMatchObject({ expected: 'Loading', actual: 'Idle', span: { line: 20 } });
        expect(problemMessage('empty distance: 1 item(s) left buffered: 20', outline.cases[4]).message.span).toEqual(
            outline.cases[4]!.empties[0],
        );
    });

    it('a crash or a port the component lacks is an error, not a failure', () => {
        const result = { file: 'f', test: plate.name, line: 15, passed: false, problems: ["toast.Controller has no in port 'x'"] };
        expect(caseOutcome(result, plate).state).toBe('errored');
        expect(caseOutcome({ ...result, problems: ['TypeError: boom'] }, plate).state).toBe('errored');
        expect(caseOutcome({ ...result, problems: ['arm: expected 1; got 2'] }, plate).state).toBe('failed');
        expect(caseOutcome({ ...result, passed: true, problems: [] }, plate)).toEqual({ state: 'passed', messages: [] });
        const broken = fileOutcome({ file: 'f', test: null, line: 0, passed: false, problems: ['/x/C.stream:7: expected ;, found }'] });
        expect(broken).toMatchObject({ state: 'errored', messages: [{ span: { line: 6 } }] });
    });

    it('a run without a JSON report is an error with what the CLI said', () => {
        expect(() => parseTestReport('x.arc:3:1 error …', 'maa-gen test: generation failed; no stream test was run')).toThrow(
            /generation failed/,
        );
        expect(() => parseTestReport('{"results":[{"file":1}],"summary":{"passed":0,"failed":0}}', '')).toThrow();
        expect(parseTestReport('{"results":[],"summary":{"passed":0,"failed":0}}', '').results).toEqual([]);
        const failed = {
            diagnostics: [
                { file: 'toast/Robot.arc', line: 7, column: 3, severity: 'error', code: 'arc/unknown-port', message: "no port 'x'" },
                { file: 'toast/Robot.arc', line: 2, column: 1, severity: 'warning', code: 'arc/unused', message: 'unused' },
            ],
            results: [],
            summary: { generated: false, passed: 0, failed: 0 },
        };
        expect(() => parseTestReport(JSON.stringify(failed), 'maa-gen test: generation failed; no stream test was run')).toThrow(
            "generation failed; no stream test was run\ntoast/Robot.arc:7:3: no port 'x'",
        );
    });

    it('the CLI arguments name the files, the cases and the Python', () => {
        const req = { app: fileRef('/w/A.arcapp'), files: [fileRef('/w/t/C.stream')], cases: ['one', 'two words'] };
        expect(testArgs(req, '/py')).toEqual([
            'test',
            '/w/A.arcapp',
            '/w/t/C.stream',
            '--case',
            'one',
            '--case',
            'two words',
            '--python',
            '/py',
            '--format',
            'json',
        ]);
        expect(testArgs({ ...req, cases: [] })).toEqual(['test', '/w/A.arcapp', '/w/t/C.stream', '--format', 'json']);
    });

    it('the manifest contributes the Python setting (restricted in untrusted workspaces)', () => {
        const c = contributions(LANGUAGE_FACTS);
        const config = c.contributes['configuration'] as { properties: Record<string, unknown> };
        expect(config.properties['maa.test.python']).toBeDefined();
        expect(config.properties['maa.generate.command']).toBeDefined();
        expect(c.activationEvents).toContain('workspaceContains:**/*.stream');
    });
});

describe('the CLI runner on a copy of the toast example (real maa-gen test)', () => {
    const project = path.join(tmp, 'toast-service');
    const controller = path.join(project, 'toast', 'Controller.stream');
    const runner = new CliStreamTestRunner(
        () => maaGen,
        () => python,
    );
    const request = (cases: string[] = []) => ({
        app: fileRef(path.join(project, 'TR.arcapp')),
        files: [fileRef(controller)],
        cases,
    });

    it('passes the example and fails a copy with a wrong expected stream, with a diff at its port', async () => {
        cpSync(toast, project, { recursive: true });
        const passing = await runner.run(request(), new AbortController().signal);
        expect(passing.summary).toEqual({ generated: true, passed: 5, failed: 0 });
        expect(passing.results.every((r) => r.file === fileRef(controller).uri)).toBe(true);

        // The second case expects LOAD_BREAD one slice late.
        const text = readFileSync(controller, 'utf8');
        const wrong = text.replace('arm      == NONE Tk Tk LOAD_BREAD Tk;', 'arm      == NONE Tk Tk Tk LOAD_BREAD Tk;');
        expect(wrong).not.toBe(text);
        writeFileSync(controller, wrong);
        const report = await runner.run(request(), new AbortController().signal);
        expect(report.summary).toEqual({ generated: true, passed: 4, failed: 1 });
        const outline = outlineStreamFile(wrong);
        const plate = outline.cases[1]!;
        const result = resultOfCase(report.results, plate)!;
        const outcome = caseOutcome(result, plate);
        expect(outcome.state).toBe('failed');
        expect(outcome.messages).toEqual([
            {
                text: 'arm: expected NONE Tk Tk Tk LOAD_BREAD Tk; got NONE Tk Tk LOAD_BREAD Tk',
                expected: 'NONE Tk Tk Tk LOAD_BREAD Tk',
                actual: 'NONE Tk Tk LOAD_BREAD Tk',
                span: plate.expected['arm'],
            },
        ]);
        for (const other of outline.cases.filter((c) => c !== plate)) {
            expect(caseOutcome(resultOfCase(report.results, other)!, other).state).toBe('passed');
        }

        // One case alone.
        const one = await runner.run(request([plate.name]), new AbortController().signal);
        expect(one.results.map((r) => [r.test, r.passed])).toEqual([[plate.name, false]]);
    }, 300_000);

    it('a file that does not parse is an error at its line', async () => {
        const broken = path.join(project, 'toast', 'Broken.stream');
        writeFileSync(broken, 'component toast.Controller(threshold = 25);\n\ntest "x" {\n  arm == NONE\n}\n');
        const report = await runner.run({ ...request(), files: [fileRef(broken)] }, new AbortController().signal);
        expect(report.results).toHaveLength(1);
        const outcome = fileOutcome(report.results[0]!);
        expect(outcome.state).toBe('errored');
        expect(outcome.messages[0]!.span?.line).toBe(4);
    }, 300_000);

    it('a run that cannot generate rejects with what maa-gen said', async () => {
        const app = path.join(project, 'TR.arcapp');
        const text = readFileSync(app, 'utf8');
        writeFileSync(app, text.replace('for toast.ToastServiceRobot', 'for toast.NoSuchRobot'));
        await expect(runner.run(request(), new AbortController().signal)).rejects.toThrow(/generation failed/);
        writeFileSync(app, text);
    }, 300_000);

    it('aborting kills the run', async () => {
        const abort = new AbortController();
        const pending = runner.run(request(), abort.signal);
        abort.abort();
        await expect(pending).rejects.toThrow('cancelled');
    }, 60_000);
});
