import { chmodSync } from 'node:fs';
import path from 'node:path';
import { afterEach, beforeAll, describe, expect, it } from 'vitest';
import { ModelDir, parseTextLines, requireBuiltCli, runCli, runCliInProcess } from './helpers.js';

// The cases run maa-gen in a warm worker thread (runCliInProcess); those that hold the bin to its
// exit codes 0, 1 and 2, its streams, help and version, and a pathologically deep model run it as a
// process (runCli).

// Real models (the codes are those of docs/diagnostics.md).
const COMP1 = 'component Comp1 { port in int i; port out int o; i -> o; }\n';
const COMP1_CONNECTOR_COLUMN = COMP1.indexOf('i -> o') + 1;
const BROKEN = 'component Foo {\n';
const CLEAN = 'component Clean {\n  port in int i;\n  port out int o;\n}\n';
const SUB = 'component Sub {\n  port in int x;\n  port out int y;\n}\n';
const SYS = 'component Sys {\n  port in int a;\n  port out int b;\n  Sub s;\n  a -> s.x;\n  s.y -> b;\n}\n';

const SUMMARY = /^(\d+) errors?, (\d+) warnings?(?:, \d+ infos?)? in (\d+) files? \((\d+) roots?\)$/m;

interface JsonDiagnostic {
    root: string;
    file: string;
    line: number;
    column: number;
    endLine: number;
    endColumn: number;
    severity: string;
    code: string;
    message: string;
}
interface JsonReport {
    diagnostics: JsonDiagnostic[];
    summary: { errors: number; warnings: number; infos: number; files: number; roots: number };
}

function parseJson(stdout: string): JsonReport {
    const report = JSON.parse(stdout) as JsonReport;
    expect(Object.keys(report).sort()).toEqual(['diagnostics', 'summary']);
    expect(Object.keys(report.summary).sort()).toEqual(['errors', 'files', 'infos', 'roots', 'warnings']);
    for (const d of report.diagnostics) {
        expect(Object.keys(d).sort()).toEqual(
            ['code', 'column', 'endColumn', 'endLine', 'file', 'line', 'message', 'root', 'severity'].sort(),
        );
        expect(path.isAbsolute(d.root)).toBe(true);
        expect(path.isAbsolute(d.file)).toBe(true);
        expect(d.file.startsWith(d.root + path.sep)).toBe(true);
        for (const n of [d.line, d.column, d.endLine, d.endColumn]) {
            expect(Number.isInteger(n) && n >= 1).toBe(true);
        }
        expect(d.endLine > d.line || (d.endLine === d.line && d.endColumn >= d.column)).toBe(true);
        expect(['error', 'warning', 'info', 'hint']).toContain(d.severity);
        expect(d.code).toMatch(/^[a-z]+\/[a-z0-9-]+$/);
        expect(d.message.length).toBeGreaterThan(0);
    }
    return report;
}

function expectNoStackTrace(text: string): void {
    expect(text).not.toMatch(/^\s+at .+:\d+:\d+\)?$/m);
}

beforeAll(() => requireBuiltCli());

let dirs: ModelDir[] = [];
function models(): ModelDir {
    const d = new ModelDir();
    dirs.push(d);
    return d;
}
afterEach(() => {
    for (const d of dirs) d.dispose();
    dirs = [];
});

describe('maa-gen check, text format', () => {
    it('reports nothing and exits 0 for a clean model root', async () => {
        const m = models();
        m.write('Clean.arc', CLEAN);
        const r = await runCli(['check', '.'], m.dir);
        expect(r.stdout).toBe('');
        expect(r.stderr.trim()).toBe('0 errors, 0 warnings in 1 file (1 root)');
        expect(r.code).toBe(0);
    });

    it('prints a warning as file:line:col: severity code message and exits 0', async () => {
        const m = models();
        m.write('Comp1.arc', COMP1);
        const r = await runCliInProcess(['check', m.dir], m.dir);
        expect(r.code).toBe(0);
        expect(r.stdout).toBe(
            `Comp1.arc:1:${COMP1_CONNECTOR_COLUMN}: warning arc/connector-in-atomic ${parseTextLines(r.stdout)[0]?.['message']}\n`,
        );
        expect(r.stderr.trim()).toBe('0 errors, 1 warning in 1 file (1 root)');
    });

    it('reports a syntax error with a syntax/ code and exits 1', async () => {
        const m = models();
        m.write('Foo.arc', BROKEN);
        const r = await runCli(['check', '.'], m.dir);
        expect(r.code).toBe(1);
        const lines = parseTextLines(r.stdout);
        expect(lines.length).toBeGreaterThan(0);
        for (const l of lines) expect(l['file']).toBe('Foo.arc');
        expect(lines.some((l) => l['severity'] === 'error' && l['code']?.startsWith('syntax/'))).toBe(true);
        const summary = SUMMARY.exec(r.stderr);
        expect(summary?.[1]).toBe(String(lines.filter((l) => l['severity'] === 'error').length));
    });

    it('prints paths relative to the current folder, with packages in folders', async () => {
        const m = models();
        m.write('models/p/Comp1.arc', `package p;\n${COMP1}`);
        const r = await runCliInProcess(['check', 'models'], m.dir);
        expect(r.code).toBe(0);
        const lines = parseTextLines(r.stdout);
        expect(lines.map((l) => [l['file'], l['line'], l['code']])).toEqual([['models/p/Comp1.arc', '2', 'arc/connector-in-atomic']]);
    });

    it('prints files outside the current folder with absolute paths', async () => {
        const m = models();
        const file = m.write('models/Comp1.arc', COMP1);
        m.write('work/.keep', '');
        const r = await runCliInProcess(['check', '../models'], m.path('work'));
        expect(r.code).toBe(0);
        expect(parseTextLines(r.stdout).map((l) => l['file'])).toEqual([file]);
    });

    it('checks several independent roots in one run', async () => {
        const m = models();
        m.write('a/Comp1.arc', COMP1);
        m.write('b/Foo.arc', BROKEN);
        m.write('c/Clean.arc', CLEAN);
        // The same component name in two roots is no clash: each root has its own scope.
        m.write('c/Comp1.arc', 'component Comp1 { port in int i; }\n');
        const r = await runCliInProcess(['check', 'a', 'b', 'c'], m.dir);
        expect(r.code).toBe(1);
        const files = new Set(parseTextLines(r.stdout).map((l) => l['file']));
        expect(files).toEqual(new Set(['a/Comp1.arc', 'b/Foo.arc']));
        const summary = SUMMARY.exec(r.stderr);
        expect(summary?.slice(2, 5)).toEqual(['1', '4', '3']);
    });

    it('a broken file does not stop the other files of its root from being checked', async () => {
        const m = models();
        m.write('Comp1.arc', COMP1);
        m.write('Foo.arc', BROKEN);
        m.write('Truncated.arc', 'package ; component Truncated { port in int');
        m.write('Garbage.arc', Buffer.from(Array.from({ length: 512 }, (_, i) => (i * 7919 + 13) % 256)));
        m.write('Unbalanced.arc', 'component Unbalanced { port in int i; } } }\n');
        const r = await runCliInProcess(['check', '.'], m.dir);
        expect(r.code).toBe(1);
        expectNoStackTrace(r.stderr);
        const lines = parseTextLines(r.stdout);
        const codesByFile = (file: string) => lines.filter((l) => l['file'] === file).map((l) => l['code'] ?? '');
        expect(codesByFile('Comp1.arc')).toContain('arc/connector-in-atomic');
        for (const broken of ['Foo.arc', 'Truncated.arc', 'Garbage.arc', 'Unbalanced.arc']) {
            expect(
                codesByFile(broken).some((c) => c.startsWith('syntax/')),
                broken,
            ).toBe(true);
        }
    });

    it('a pathologically nested file is reported with syntax/too-deep; the other files and roots are checked', async () => {
        const m = models();
        const states = Array.from({ length: 5_000 }, (_, k) => `state S${k} {`).join(' ') + ' }'.repeat(5_000);
        m.write(
            'a/Deep.arc',
            `component Deep {\n  port in int i;\n  port out int o;\n  automaton {\n    initial ${states}\n    S0 -> S0 [${'('.repeat(10_000)}i > 0${')'.repeat(10_000)}] / o = ${'-'.repeat(10_000)}1;\n  }\n}\n`,
        );
        m.write('a/Comp1.arc', COMP1);
        m.write('b/Comp1.arc', COMP1);
        const r = await runCli(['check', 'a', 'b'], m.dir);
        expect(r.code).toBe(1);
        expectNoStackTrace(r.stderr);
        const lines = parseTextLines(r.stdout);
        const codesByFile = (file: string) => lines.filter((l) => l['file'] === file).map((l) => l['code'] ?? '');
        expect(codesByFile('a/Deep.arc').filter((c) => c.startsWith('syntax/'))).toEqual(['syntax/too-deep']);
        expect(codesByFile('a/Comp1.arc')).toContain('arc/connector-in-atomic');
        expect(codesByFile('b/Comp1.arc')).toContain('arc/connector-in-atomic');
        expect(SUMMARY.exec(r.stderr)?.slice(3, 5)).toEqual(['3', '2']);
    });
});

describe('maa-gen check, file arguments', () => {
    it('checks a file within its folder and reports only that file', async () => {
        const m = models();
        m.write('Comp1.arc', COMP1);
        m.write('Foo.arc', BROKEN);
        const r = await runCliInProcess(['check', '--format', 'json', 'Comp1.arc'], m.dir);
        expect(r.code).toBe(0);
        const report = parseJson(r.stdout);
        expect(report.diagnostics.map((d) => [d.root, d.file, d.code])).toEqual([[m.dir, m.path('Comp1.arc'), 'arc/connector-in-atomic']]);
        expect(report.summary).toEqual({ errors: 0, warnings: 1, infos: 0, files: 1, roots: 1 });
    });

    it('resolves names against the other files of the folder', async () => {
        const m = models();
        m.write('Sub.arc', SUB);
        m.write('Sys.arc', SYS);
        m.write('Foo.arc', BROKEN);
        const r = await runCliInProcess(['check', 'Sys.arc'], m.dir);
        expect(r.stdout).toBe('');
        expect(r.code).toBe(0);
        expect(r.stderr.trim()).toBe('0 errors, 0 warnings in 1 file (1 root)');
    });

    it('checks a file in a package folder within the root that holds its package folders', async () => {
        const m = models();
        const file = m.write('models/robot/arm/Comp1.arc', `package robot.arm;\n${COMP1}`);
        m.write('models/robot/Sub.arc', `package robot;\n${SUB}`);
        m.write('models/robot/Sys.arc', `package robot;\nimport robot.arm.*;\n${SYS}`);
        const r = await runCliInProcess(['check', '-f', 'json', 'models/robot/arm/Comp1.arc', 'models/robot/Sys.arc'], m.dir);
        expect(r.code).toBe(0);
        const report = parseJson(r.stdout);
        expect(report.diagnostics.map((d) => [d.root, d.file, d.code])).toEqual([[m.path('models'), file, 'arc/connector-in-atomic']]);
        expect(report.summary).toMatchObject({ errors: 0, files: 2, roots: 1 });
    });

    it('a file whose folders do not match its package is checked in its own folder', async () => {
        const m = models();
        m.write('models/elsewhere/Comp1.arc', `package robot;\n${COMP1}`);
        const r = await runCliInProcess(['check', 'models/elsewhere/Comp1.arc'], m.dir);
        expect(r.code).toBe(1);
        expect(parseTextLines(r.stdout).map((l) => l['code'])).toContain('arc/package-mismatch');
    });

    it('a folder argument wins over a file argument in the same folder', async () => {
        const m = models();
        m.write('Comp1.arc', COMP1);
        m.write('Foo.arc', BROKEN);
        const r = await runCliInProcess(['check', 'Comp1.arc', '.'], m.dir);
        expect(r.code).toBe(1);
        expect(new Set(parseTextLines(r.stdout).map((l) => l['file']))).toEqual(new Set(['Comp1.arc', 'Foo.arc']));
    });
});

describe('maa-gen check --format json', () => {
    it('prints exactly one object with diagnostics and summary', async () => {
        const m = models();
        m.write('a/Comp1.arc', COMP1);
        m.write('b/Foo.arc', BROKEN);
        m.write('b/Clean.arc', CLEAN);
        const r = await runCliInProcess(['check', '--format', 'json', 'a', 'b'], m.dir);
        expect(r.code).toBe(1);
        expect(r.stderr).toBe('');
        const report = parseJson(r.stdout);
        const warning = report.diagnostics.find((d) => d.code === 'arc/connector-in-atomic');
        expect(warning).toMatchObject({
            root: m.path('a'),
            file: m.path('a/Comp1.arc'),
            line: 1,
            column: COMP1_CONNECTOR_COLUMN,
            severity: 'warning',
        });
        const syntax = report.diagnostics.filter((d) => d.code.startsWith('syntax/'));
        expect(syntax.length).toBeGreaterThan(0);
        for (const d of syntax) expect(d).toMatchObject({ root: m.path('b'), file: m.path('b/Foo.arc'), severity: 'error' });
        expect(report.summary).toEqual({
            errors: report.diagnostics.filter((d) => d.severity === 'error').length,
            warnings: 1,
            infos: 0,
            files: 3,
            roots: 2,
        });
    });

    it('prints an empty list for a clean root and exits 0', async () => {
        const m = models();
        m.write('Clean.arc', CLEAN);
        const r = await runCliInProcess(['check', '-f', 'json', '.'], m.dir);
        expect(r.code).toBe(0);
        expect(parseJson(r.stdout)).toEqual({
            diagnostics: [],
            summary: { errors: 0, warnings: 0, infos: 0, files: 1, roots: 1 },
        });
    });
});

describe('maa-gen usage and I/O problems', () => {
    it('exits 2 and names a missing path', async () => {
        const m = models();
        m.write('Comp1.arc', COMP1);
        const r = await runCliInProcess(['check', '.', 'no-such-folder'], m.dir);
        expect(r.code).toBe(2);
        expect(r.stdout).toBe('');
        expect(r.stderr).toContain('no-such-folder');
        expect(r.stderr).toMatch(/not found/);
        expectNoStackTrace(r.stderr);
    });

    it('names every missing path at once', async () => {
        const m = models();
        const r = await runCliInProcess(['check', '--format', 'json', 'missing-a', 'missing/b.arc'], m.dir);
        expect(r.code).toBe(2);
        expect(r.stdout).toBe('');
        expect(r.stderr).toContain('missing-a');
        expect(r.stderr).toContain('missing/b.arc');
    });

    it('exits 2 for a file that is not a model file', async () => {
        const m = models();
        m.write('notes.txt', 'hello');
        const r = await runCliInProcess(['check', 'notes.txt'], m.dir);
        expect(r.code).toBe(2);
        expect(r.stderr).toContain('notes.txt');
        expectNoStackTrace(r.stderr);
    });

    it.skipIf(process.getuid?.() === 0)('exits 2 and names an unreadable file', async () => {
        const m = models();
        const file = m.write('Comp1.arc', COMP1);
        chmodSync(file, 0o000);
        try {
            const r = await runCliInProcess(['check', 'Comp1.arc'], m.dir);
            expect(r.code).toBe(2);
            expect(r.stderr).toContain('Comp1.arc');
            expectNoStackTrace(r.stderr);
        } finally {
            chmodSync(file, 0o644);
        }
    });

    it('exits 2 and names the file when checking meets an I/O problem', async () => {
        const m = models();
        m.write('Comp1.arc', COMP1);
        // The model root's configuration (docs/diagnostics.md, arc/reserved-name) is not valid JSON.
        m.write('maa.json', '{ "reservedNames": ');
        const r = await runCliInProcess(['check', '.'], m.dir);
        expect(r.code).toBe(2);
        expect(r.stdout).toBe('');
        expect(r.stderr).toContain('maa.json');
        expectNoStackTrace(r.stderr);
    });

    it('exits 2 without paths, with an unknown format, option or command', async () => {
        const m = models();
        for (const args of [['check'], ['check', '--format', 'xml', '.'], ['check', '--frobnicate', '.'], ['frobnicate'], []]) {
            const r = await runCli(args, m.dir);
            expect(r.code, args.join(' ')).toBe(2);
            expect(r.stdout, args.join(' ')).toBe('');
            expect(r.stderr.length, args.join(' ')).toBeGreaterThan(0);
            expectNoStackTrace(r.stderr);
        }
    });

    it('has --help everywhere and --version', async () => {
        const m = models();
        const top = await runCli(['--help'], m.dir);
        expect(top.code).toBe(0);
        expect(top.stdout).toContain('Usage: maa-gen');
        expect(top.stdout).toContain('check');
        const check = await runCli(['check', '--help'], m.dir);
        expect(check.code).toBe(0);
        expect(check.stdout).toContain('Usage: maa-gen check');
        expect(check.stdout).toContain('--format');
        expect(check.stdout).toMatch(/Exit codes/);
        const help = await runCli(['help', 'check'], m.dir);
        expect(help.code).toBe(0);
        expect(help.stdout).toContain('Usage: maa-gen check');
        const version = await runCli(['--version'], m.dir);
        expect(version.code).toBe(0);
        expect(version.stdout.trim()).toMatch(/^\d+\.\d+\.\d+/);
    });
});
