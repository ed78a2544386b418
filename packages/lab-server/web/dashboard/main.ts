// The instructor's dashboard page (docs/lab.md "The instructor's dashboard"): bundled by esbuild
// into dist/web/dashboard.js and served as /lab-assets/dashboard.js under a strict CSP (no inline
// script). Everything the server sends is put into the page as text (never as HTML).
import type { Dashboard, DashboardCell } from '../../src/dashboard/data.js';
import { el } from './dom.js';
import { GradingSection } from './grading.js';
import { cellSummary, cellTone, type SortKey, sortStudents } from './table.js';

/** How often the table asks for changes (an unchanged dashboard answers 304 without a body). */
const POLL_MS = 5000;

const app = document.getElementById('app') as HTMLElement;
const status = document.getElementById('status') as HTMLElement;

async function getJson<T>(path: string): Promise<T> {
    const answer = await fetch(path, { headers: { Accept: 'application/json' }, cache: 'no-store' });
    const json = await answer.json().catch(() => ({}));
    if (!answer.ok) throw new Error(json.error ?? answer.statusText);
    return json as T;
}

function coursePicker(): void {
    const input = el('input', { name: 'course', required: true, id: 'course-name' });
    const form = el('form', {}, el('label', { htmlFor: 'course-name' }, 'Course '), input, ' ', el('button', {}, 'Open'));
    form.addEventListener('submit', (event) => {
        event.preventDefault();
        location.assign(`/dashboard/${encodeURIComponent(input.value.trim())}`);
    });
    app.replaceChildren(el('h1', {}, 'maa-lab: dashboard'), form);
}

class CourseTable {
    private dashboard: Dashboard | undefined;
    private etag: string | undefined;
    private sort: SortKey = { column: 'student', descending: false };
    private filter = '';
    private csrf: string | undefined;
    private readonly tableHolder = el('div');
    /** one grading section per exercise (docs/lab.md "Grading") */
    private readonly gradingHolder = el('div', { id: 'grading' });
    private gradedExercises = '';

    constructor(private readonly course: string) {}

    async start(): Promise<void> {
        const filter = el('input', { type: 'search', id: 'filter' });
        filter.addEventListener('input', () => {
            this.filter = filter.value.trim().toLowerCase();
            this.render();
        });
        const csv = el('a', { href: `/api/courses/${encodeURIComponent(this.course)}/results.csv` }, 'Download results (CSV)');
        app.replaceChildren(
            el('h1', { id: 'title' }, `Dashboard: ${this.course}`),
            el('p', {}, el('label', { htmlFor: 'filter' }, 'Filter by name '), filter, ' ', csv),
            this.tableHolder,
            this.gradingHolder,
        );
        this.csrf = (await getJson<{ csrfToken: string }>('/api/me')).csrfToken;
        await this.poll();
    }

    private async poll(): Promise<void> {
        try {
            const path = `/api/courses/${encodeURIComponent(this.course)}/dashboard`;
            const answer = await fetch(path, { cache: 'no-store', headers: this.etag ? { 'If-None-Match': this.etag } : {} });
            if (answer.status === 200) {
                this.dashboard = (await answer.json()) as Dashboard;
                this.etag = answer.headers.get('ETag') ?? undefined;
                (document.getElementById('title') as HTMLElement).textContent = `Dashboard: ${this.dashboard.course.title}`;
                this.render();
                this.renderGrading();
                status.textContent = `Updated ${new Date().toLocaleTimeString()}`;
            } else if (answer.status !== 304) {
                const json = await answer.json().catch(() => ({}));
                status.textContent = `Could not load the dashboard: ${json.error ?? answer.statusText}`;
            }
        } catch (e) {
            status.textContent = `Could not load the dashboard: ${(e as Error).message}`;
        }
        setTimeout(() => void this.poll(), POLL_MS);
    }

    private render(): void {
        const d = this.dashboard;
        if (!d) return;
        const cells = new Map(d.cells.map((c) => [`${c.student}\n${c.exercise}`, c]));
        const students = sortStudents(d, this.sort).filter(
            (s) => !this.filter || s.login.toLowerCase().includes(this.filter) || s.name.toLowerCase().includes(this.filter),
        );
        const head = el('tr', {}, this.header('student', 'Student'), ...d.exercises.map((e) => this.header(e.name, e.title)));
        const rows = students.map((s) =>
            el(
                'tr',
                {},
                el('th', { scope: 'row' }, `${s.name} (${s.login})`),
                ...d.exercises.map((e) => this.cell(cells.get(`${s.login}\n${e.name}`))),
            ),
        );
        const table = el(
            'table',
            { id: 'dashboard' },
            el(
                'caption',
                {},
                `${students.length} of ${d.students.length} students × ${d.exercises.length} exercise${d.exercises.length === 1 ? '' : 's'}`,
            ),
            el('thead', {}, head),
            el('tbody', {}, ...rows),
        );
        this.tableHolder.replaceChildren(table);
    }

    /** The grading sections, made again only when the course's exercises change. */
    private renderGrading(): void {
        const d = this.dashboard;
        const names = d ? d.exercises.map((e) => e.name).join('\n') : '';
        if (!d || names === this.gradedExercises) return;
        this.gradedExercises = names;
        const sections = d.exercises.map((e) => new GradingSection(this.course, e.name, e.title, () => this.csrf ?? ''));
        this.gradingHolder.replaceChildren(el('h2', {}, 'Grading'), ...sections.map((s) => s.element));
        for (const section of sections) void section.load();
    }

    private header(column: string, label: string): HTMLTableCellElement {
        const sorted = this.sort.column === column;
        const button = el('button', { type: 'button' }, label, sorted ? (this.sort.descending ? ' ▼' : ' ▲') : '');
        button.addEventListener('click', () => {
            this.sort = { column, descending: sorted ? !this.sort.descending : false };
            this.render();
        });
        const th = el('th', { scope: 'col' }, button);
        th.setAttribute('aria-sort', sorted ? (this.sort.descending ? 'descending' : 'ascending') : 'none');
        return th;
    }

    private cell(cell: DashboardCell | undefined): HTMLTableCellElement {
        if (!cell) return el('td', { className: 'none' }, '—');
        const td = el('td', { className: cellTone(cell) });
        td.append(el('div', {}, ...cellSummary(cell).flatMap((line, i) => (i ? [el('br'), line] : [line]))));
        if (cell.simulating) td.prepend(el('div', { className: 'live' }, '● simulating now'));
        if (cell.workspace) {
            const names = [this.course, cell.exercise, cell.student].map(encodeURIComponent).join('/');
            const view = el('a', { href: `/dashboard/${names}` }, 'open read-only');
            // The student's IDE, read-only for the instructor (docs/lab.md "The IDE in the lab").
            const ide = el('a', { href: `/ide/${names}/` }, 'in the IDE');
            const reset = el('button', { type: 'button' }, 'Reset');
            reset.addEventListener('click', () => void this.reset(cell));
            td.append(el('div', {}, view, ' (', ide, ') ', reset));
        }
        return td;
    }

    private async reset(cell: DashboardCell): Promise<void> {
        if (!cell.workspace) return;
        if (!confirm(`Reset ${cell.student}'s workspace of ${cell.exercise} to the exercise's starter? (The history keeps every file.)`))
            return;
        const answer = await fetch(`${cell.workspace}/reset`, {
            method: 'POST',
            headers: { 'Content-Type': 'application/json', 'X-CSRF-Token': this.csrf ?? '' },
            body: '{}',
        });
        const json = await answer.json().catch(() => ({}));
        status.textContent = answer.ok
            ? `Reset ${cell.student}'s ${cell.exercise}: ${json.saved?.length ?? 0} files restored, ${json.deleted?.length ?? 0} deleted`
            : `Reset failed: ${json.error ?? answer.statusText}`;
    }
}

interface WorkspaceView {
    course: string;
    exercise: string;
    student: { login: string; name: string };
    lastActivity: string | null;
    errors: number;
    warnings: number;
    files: {
        path: string;
        revision: number;
        content: string;
        diagnostics: { line: number; column: number; severity: string; code: string; message: string }[];
    }[];
}

async function workspacePage(course: string, exercise: string, student: string): Promise<void> {
    const [c, e, s] = [course, exercise, student].map(encodeURIComponent);
    const view = await getJson<WorkspaceView>(`/api/courses/${c}/dashboard/${e}/${s}`);
    const back = el('a', { href: `/dashboard/${encodeURIComponent(course)}` }, `← Dashboard of ${course}`);
    const summary = `${view.errors} errors, ${view.warnings} warnings; last activity ${view.lastActivity ? new Date(view.lastActivity).toLocaleString() : 'none'} (read-only)`;
    const files = view.files.map((f) =>
        el(
            'section',
            {},
            el('h2', {}, `${f.path} (revision ${f.revision})`),
            f.diagnostics.length
                ? el(
                      'ul',
                      {},
                      ...f.diagnostics.map((d) =>
                          el('li', { className: `diag-${d.severity}` }, `${d.line}:${d.column} ${d.severity} ${d.code}: ${d.message}`),
                      ),
                  )
                : el('p', {}, 'No diagnostics.'),
            el('pre', {}, f.content),
        ),
    );
    app.replaceChildren(
        back,
        el('h1', {}, `${view.student.name} (${view.student.login}): ${view.exercise}`),
        el('p', {}, summary),
        ...files,
    );
}

const parts = location.pathname
    .split('/')
    .filter(Boolean)
    .slice(1)
    .map((p) => decodeURIComponent(p));
const run =
    parts.length === 0
        ? Promise.resolve(coursePicker())
        : parts.length === 3
          ? workspacePage(parts[0] as string, parts[1] as string, parts[2] as string)
          : new CourseTable(parts[0] as string).start();
run.catch((e: Error) => {
    status.textContent = e.message;
});
