import path from 'node:path';
import { describe, expect, it } from 'vitest';
import { displayPath, formatDiagnosticText, formatSummaryText } from '../src/format/text.js';
import { modelRootOfFile } from '../src/roots.js';
import { sortDiagnostics } from '../src/summary.js';

const diag = (over: Partial<Parameters<typeof formatDiagnosticText>[0]> = {}) => ({
    root: '/w/models',
    file: '/w/models/a/B.arc',
    line: 3,
    column: 7,
    endLine: 3,
    endColumn: 9,
    severity: 'error' as const,
    code: 'arc/missing-port',
    message: "Port 'x' does not exist.",
    ...over,
});

describe('text format', () => {
    it('prints file:line:col: severity code message relative to cwd', () => {
        expect(formatDiagnosticText(diag(), { cwd: '/w', color: false })).toBe(
            "models/a/B.arc:3:7: error arc/missing-port Port 'x' does not exist.",
        );
    });

    it('keeps every diagnostic on one line and escapes control characters', () => {
        const line = formatDiagnosticText(diag({ message: 'first\r\n  second\u2028third \u0007\u001b[31m' }), { cwd: '/w', color: false });
        expect(line).toBe('models/a/B.arc:3:7: error arc/missing-port first second third \\x07\\x1b[31m');
    });

    it('colours only the severity', () => {
        expect(formatDiagnosticText(diag({ severity: 'warning' }), { cwd: '/w', color: true })).toContain(' \x1b[33mwarning\x1b[0m arc/');
    });

    it('prints files outside cwd with absolute paths', () => {
        expect(displayPath('/elsewhere/X.arc', '/w')).toBe('/elsewhere/X.arc');
        expect(displayPath('/w/..x/X.arc', '/w')).toBe('..x/X.arc');
    });

    it('summarizes with singular and plural forms', () => {
        expect(formatSummaryText({ errors: 1, warnings: 0, infos: 0, files: 1, roots: 1 })).toBe('1 error, 0 warnings in 1 file (1 root)');
        expect(formatSummaryText({ errors: 2, warnings: 3, infos: 4, files: 5, roots: 2 })).toBe(
            '2 errors, 3 warnings, 4 infos in 5 files (2 roots)',
        );
    });
});

describe('model root of a file argument', () => {
    const f = (...p: string[]) => path.join('/w', ...p);
    it('is the folder holding the package folders', () => {
        expect(modelRootOfFile(f('models', 'toast', 'ctrl', 'C.arc'), 'package toast.ctrl;\ncomponent C {}')).toBe(f('models'));
        expect(modelRootOfFile(f('models', 'toast', 'C.arc'), '// header\n/* more */\npackage  toast ;')).toBe(f('models'));
    });
    it('is the file folder without a package or when the folders do not match', () => {
        expect(modelRootOfFile(f('models', 'C.arc'), 'component C {}')).toBe(f('models'));
        expect(modelRootOfFile(f('models', 'other', 'C.arc'), 'package toast;')).toBe(f('models', 'other'));
        expect(modelRootOfFile(f('C.arc'), 'package a.b.c.d;')).toBe(f());
    });
});

describe('diagnostic order', () => {
    it('is by root in argument order, then file and position', () => {
        const roots = [{ root: '/w/z' }, { root: '/w/a' }];
        const sorted = sortDiagnostics(
            [
                diag({ root: '/w/a', file: '/w/a/A.arc', line: 1 }),
                diag({ root: '/w/z', file: '/w/z/B.arc', line: 9 }),
                diag({ root: '/w/z', file: '/w/z/B.arc', line: 2, column: 5 }),
                diag({ root: '/w/z', file: '/w/z/A.arc', line: 4 }),
            ],
            roots,
        );
        expect(sorted.map((d) => `${d.file}:${d.line}`)).toEqual(['/w/z/A.arc:4', '/w/z/B.arc:2', '/w/z/B.arc:9', '/w/a/A.arc:1']);
    });
});
