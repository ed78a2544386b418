// The dashboard table's text and order (no DOM here, so the tests run it in Node).
import type { Dashboard, DashboardCell, DashboardStudent } from '../../src/dashboard/data.js';

/** `student` (by name) or an exercise's name (by errors, then tests passed, then last activity). */
export interface SortKey {
    column: string;
    descending: boolean;
}

/** The cell's lines of text: every state is said in words, the colour only repeats it. */
export function cellSummary(cell: DashboardCell): string[] {
    if (!cell.diagnostics && !cell.checking && !cell.checkError) return ['not started'];
    const lines = [diagnosticsLine(cell)];
    lines.push(cell.tests ? `tests ${cell.tests.passed}/${cell.tests.total} passed` : 'tests not run');
    lines.push(cell.simulation ? (cell.simulation.goalReached ? 'goal reached' : 'goal not reached') : 'not simulated');
    lines.push(`last activity ${cell.lastActivity ? new Date(cell.lastActivity).toLocaleString() : 'none'}`);
    return lines;
}

/** The diagnostics' line: the counts, `checking…` while the current files are checked, or the failed check. */
function diagnosticsLine(cell: DashboardCell): string {
    if (cell.checkError) return `check failed: ${cell.checkError}`;
    if (!cell.diagnostics) return 'checking…';
    const { errors, warnings } = cell.diagnostics;
    const counts = errors === 0 && warnings === 0 ? 'no problems' : `${plural(errors, 'error')}, ${plural(warnings, 'warning')}`;
    return cell.checking ? `${counts} (checking…)` : counts;
}

/**
 * The cell's class: `none` (no workspace), `bad` (errors), `good` (tests all passed or goal
 * reached, no errors), `warn` (else, and while a first check runs or after a failed one).
 */
export function cellTone(cell: DashboardCell): 'none' | 'bad' | 'warn' | 'good' {
    if (!cell.diagnostics) return cell.checking || cell.checkError ? 'warn' : 'none';
    if (cell.diagnostics.errors > 0) return 'bad';
    const testsOk = cell.tests !== null && cell.tests.total > 0 && cell.tests.passed === cell.tests.total;
    return testsOk || cell.simulation?.goalReached ? 'good' : 'warn';
}

export function sortStudents(d: Dashboard, sort: SortKey): DashboardStudent[] {
    const cells = new Map(d.cells.filter((c) => c.exercise === sort.column).map((c) => [c.student, c]));
    const key = (s: DashboardStudent): (string | number)[] => {
        if (sort.column === 'student') return [s.name.toLowerCase(), s.login];
        const c = cells.get(s.login);
        if (!c?.diagnostics) return [Number.POSITIVE_INFINITY, 0, ''];
        return [c.diagnostics.errors, -(c.tests?.passed ?? -1), c.lastActivity ?? ''];
    };
    const sorted = [...d.students].sort((a, b) => compare(key(a), key(b)));
    return sort.descending ? sorted.reverse() : sorted;
}

function compare(a: (string | number)[], b: (string | number)[]): number {
    for (let i = 0; i < a.length; i++) {
        const x = a[i] as string | number;
        const y = b[i] as string | number;
        if (x < y) return -1;
        if (x > y) return 1;
    }
    return 0;
}

function plural(n: number, word: string): string {
    return `${n} ${word}${n === 1 ? '' : 's'}`;
}
