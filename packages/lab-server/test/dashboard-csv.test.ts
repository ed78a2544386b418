// The dashboard's CSV quoting (RFC 4180) and the table's texts and order (web/dashboard/table.ts).
import { describe, expect, it } from 'vitest';
import { csvField, type Dashboard, type DashboardCell, dashboardCsv } from '../src/dashboard/index.js';
import { cellSummary, cellTone, sortStudents } from '../web/dashboard/table.js';

const cell = (student: string, exercise: string, more: Partial<DashboardCell> = {}): DashboardCell => ({
    student,
    exercise,
    workspace: `/api/ws/c/${exercise}/${student}`,
    diagnostics: { errors: 0, warnings: 0 },
    checking: false,
    checkError: null,
    tests: null,
    simulation: null,
    lastActivity: '2026-01-02T03:04:05.000Z',
    simulating: false,
    ...more,
});

describe('csvField', () => {
    it('leaves plain text and numbers as they are', () => {
        expect(csvField('ada')).toBe('ada');
        expect(csvField(3)).toBe('3');
        expect(csvField(-1)).toBe('-1');
        expect(csvField(null)).toBe('');
    });
    it('quotes commas, quotes, CR and LF, doubling quotes', () => {
        expect(csvField('Lovelace, Ada')).toBe('"Lovelace, Ada"');
        expect(csvField('say "hi"')).toBe('"say ""hi"""');
        expect(csvField('two\nlines')).toBe('"two\nlines"');
        expect(csvField('cr\rhere')).toBe('"cr\rhere"');
    });
    it('keeps spreadsheets from running text as a formula', () => {
        expect(csvField('=HYPERLINK("x")')).toBe('"\'=HYPERLINK(""x"")"');
        expect(csvField('+1')).toBe("'+1");
        expect(csvField('@sum')).toBe("'@sum");
    });
});

describe('dashboardCsv', () => {
    it('writes a header and one row per cell, CRLF line ends', () => {
        const d: Dashboard = {
            course: { name: 'c', title: 'C' },
            exercises: [{ name: 'e', title: 'E', released: true }],
            students: [{ login: 'ada', name: 'Ada, "A"' }],
            cells: [
                cell('ada', 'e', {
                    tests: { passed: 1, total: 2, at: 'x' },
                    simulation: { goalReached: false, at: 'y' },
                    simulating: true,
                }),
            ],
        };
        expect(dashboardCsv(d)).toBe(
            'login,name,exercise,errors,warnings,tests_passed,tests_total,goal_reached,last_activity,simulating\r\n' +
                'ada,"Ada, ""A""",e,0,0,1,2,no,2026-01-02T03:04:05.000Z,yes\r\n',
        );
    });
});

describe('the table', () => {
    it('says every state in words (not by colour alone)', () => {
        expect(cellSummary(cell('a', 'e', { workspace: null, diagnostics: null, lastActivity: null }))).toEqual(['not started']);
        const lines = cellSummary(cell('a', 'e', { diagnostics: { errors: 2, warnings: 1 }, tests: { passed: 1, total: 3, at: '' } }));
        expect(lines.slice(0, 3)).toEqual(['2 errors, 1 warning', 'tests 1/3 passed', 'not simulated']);
        expect(cellSummary(cell('a', 'e', { simulation: { goalReached: true, at: '' } }))[2]).toBe('goal reached');
    });
    it('says "checking…" while the current files are checked, and a failed check', () => {
        expect(cellSummary(cell('a', 'e', { diagnostics: null, checking: true }))[0]).toBe('checking…');
        expect(cellSummary(cell('a', 'e', { diagnostics: { errors: 1, warnings: 0 }, checking: true }))[0]).toBe(
            '1 error, 0 warnings (checking…)',
        );
        expect(cellSummary(cell('a', 'e', { diagnostics: null, checkError: 'the checker crashed' }))[0]).toBe(
            'check failed: the checker crashed',
        );
        expect(cellTone(cell('a', 'e', { diagnostics: null, checking: true }))).toBe('warn');
        expect(cellTone(cell('a', 'e', { diagnostics: null, checkError: 'x' }))).toBe('warn');
    });
    it('colours errors, passed tests and the rest apart', () => {
        expect(cellTone(cell('a', 'e', { diagnostics: null }))).toBe('none');
        expect(cellTone(cell('a', 'e', { diagnostics: { errors: 1, warnings: 0 } }))).toBe('bad');
        expect(cellTone(cell('a', 'e', { tests: { passed: 2, total: 2, at: '' } }))).toBe('good');
        expect(cellTone(cell('a', 'e', { tests: { passed: 1, total: 2, at: '' } }))).toBe('warn');
    });
    it('sorts by name or by an exercise column, either way', () => {
        const d: Dashboard = {
            course: { name: 'c', title: 'C' },
            exercises: [{ name: 'e', title: 'E', released: true }],
            students: [
                { login: 'b', name: 'Bea' },
                { login: 'a', name: 'Zed' },
                { login: 'c', name: 'Cy' },
            ],
            cells: [
                cell('b', 'e', { diagnostics: { errors: 2, warnings: 0 } }),
                cell('a', 'e', { diagnostics: { errors: 0, warnings: 0 } }),
                cell('c', 'e', { diagnostics: null }),
            ],
        };
        expect(sortStudents(d, { column: 'student', descending: false }).map((s) => s.login)).toEqual(['b', 'c', 'a']);
        expect(sortStudents(d, { column: 'student', descending: true }).map((s) => s.login)).toEqual(['a', 'c', 'b']);
        expect(sortStudents(d, { column: 'e', descending: false }).map((s) => s.login)).toEqual(['a', 'b', 'c']);
    });
});
