// The dashboard as CSV (RFC 4180): one row per student × exercise with the dashboard's columns.
import type { Dashboard } from './data.js';

export const CSV_COLUMNS = [
    'login',
    'name',
    'exercise',
    'errors',
    'warnings',
    'tests_passed',
    'tests_total',
    'goal_reached',
    'last_activity',
    'simulating',
] as const;

/**
 * One field: quoted when it holds a comma, a quote, CR or LF (quotes doubled). Text that a
 * spreadsheet would run as a formula (starting with =, +, -, @, tab or CR) gets a leading `'`.
 */
export function csvField(value: string | number | boolean | null): string {
    if (value === null) return '';
    let text = String(value);
    if (typeof value === 'string' && /^[=+\-@\t\r]/.test(text)) text = `'${text}`;
    return /[",\r\n]/.test(text) ? `"${text.replaceAll('"', '""')}"` : text;
}

/** The CSV text: a header line, then the cells in the dashboard's order; lines end with CRLF. */
export function dashboardCsv(dashboard: Dashboard): string {
    const names = new Map(dashboard.students.map((s) => [s.login, s.name]));
    const rows = dashboard.cells.map((c) => [
        c.student,
        names.get(c.student) ?? '',
        c.exercise,
        c.diagnostics?.errors ?? null,
        c.diagnostics?.warnings ?? null,
        c.tests?.passed ?? null,
        c.tests?.total ?? null,
        c.simulation ? (c.simulation.goalReached ? 'yes' : 'no') : null,
        c.lastActivity,
        c.simulating ? 'yes' : 'no',
    ]);
    return [[...CSV_COLUMNS], ...rows].map((row) => `${row.map(csvField).join(',')}\r\n`).join('');
}
