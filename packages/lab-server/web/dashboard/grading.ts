// The dashboard's grading section of one exercise (docs/lab.md "Grading"): the Grade button, a
// progress bar while a run goes on, the table of students × criteria with the total, each row
// opening to its feedback and recordings, and the CSV link. Text only, never HTML.
import type { ResultView, RunView } from '../../src/grading/views.js';
import { el } from './dom.js';
import { criterionCell, type ExerciseGrading, feedbackLine, points, runText, running } from './grading-text.js';

/** How often a running run's progress is asked for. */
const RUN_POLL_MS = 1000;

export class GradingSection {
    readonly element: HTMLElement;
    private readonly body = el('div');
    private readonly runLine = el('p', { className: 'run', role: 'status' });
    private readonly progress = el('progress', { max: 1, value: 0, hidden: true });
    private readonly button = el('button', { type: 'button', className: 'grade' }, 'Grade all submissions');
    private readonly base: string;

    constructor(
        course: string,
        private readonly exercise: string,
        title: string,
        private readonly csrf: () => string,
    ) {
        this.base = `/api/courses/${encodeURIComponent(course)}/exercises/${encodeURIComponent(exercise)}/grading`;
        this.button.addEventListener('click', () => void this.gradeAll());
        this.element = el(
            'section',
            { className: 'grading', id: `grading-${exercise}` },
            el('h3', {}, title),
            el('p', {}, this.button, ' ', this.progress, ' ', this.runLine),
            this.body,
        );
    }

    /** Reads the results (and follows a run that goes on). */
    async load(): Promise<void> {
        const answer = await fetch(this.base, { cache: 'no-store', headers: { Accept: 'application/json' } });
        const json = (await answer.json().catch(() => ({}))) as ExerciseGrading & { error?: string };
        if (!answer.ok) {
            this.body.replaceChildren(el('p', {}, `Could not load the grading: ${json.error ?? answer.statusText}`));
            return;
        }
        this.render(json);
        const [latest] = json.runs;
        if (latest) this.showRun(latest);
        if (running(latest)) await this.follow(latest as RunView);
    }

    private async gradeAll(): Promise<void> {
        this.button.disabled = true;
        const answer = await fetch(`${this.base}/runs`, {
            method: 'POST',
            headers: { 'Content-Type': 'application/json', 'X-CSRF-Token': this.csrf() },
            body: '{}',
        });
        const json = (await answer.json().catch(() => ({}))) as { run?: RunView; error?: string };
        if (!answer.ok || !json.run) {
            this.runLine.textContent = `Grading did not start: ${json.error ?? answer.statusText}`;
            this.button.disabled = false;
            return;
        }
        await this.follow(json.run);
    }

    /** Polls the run until it ends, then reads the results again. */
    private async follow(run: RunView): Promise<void> {
        this.button.disabled = true;
        let current = run;
        this.showRun(current);
        while (running(current)) {
            await new Promise((resolve) => setTimeout(resolve, RUN_POLL_MS));
            const answer = await fetch(run.url, { cache: 'no-store' });
            if (!answer.ok) break;
            current = ((await answer.json()) as { run: RunView }).run;
            this.showRun(current);
        }
        this.button.disabled = false;
        await this.load();
    }

    private showRun(run: RunView): void {
        this.runLine.textContent = runText(run);
        this.progress.hidden = !running(run);
        this.progress.max = Math.max(run.total, 1);
        this.progress.value = run.done;
    }

    private render(grading: ExerciseGrading): void {
        const criteria = grading.criteria;
        if (!criteria) {
            this.button.hidden = true;
            this.body.replaceChildren(
                el('p', {}, `${this.exercise} has no grading: add a grading/ folder with grading.json and update the exercise.`),
            );
            return;
        }
        const head = el(
            'tr',
            {},
            el('th', { scope: 'col' }, 'Student'),
            ...criteria.map((c) => el('th', { scope: 'col', title: c.id }, `${c.title} (${points(c.weight)})`)),
            el('th', { scope: 'col' }, 'Total'),
        );
        const rows = grading.results.flatMap((r) =>
            this.rows(
                r,
                criteria.map((c) => c.id),
                criteria.length + 2,
            ),
        );
        const table = el(
            'table',
            { className: 'grades' },
            el('caption', {}, `${grading.results.length} graded students (each one's newest grade)`),
            // The header row without a thead: the course table's `thead th` stays the page's only one (e2e/lab-dashboard.mjs).
            head,
            el('tbody', {}, ...rows),
        );
        const csv = grading.csv ? el('a', { href: grading.csv }, 'Download grades (CSV)') : '';
        this.body.replaceChildren(table, el('p', {}, csv));
    }

    /** A result's row and its hidden feedback row (the student's button opens it). */
    private rows(result: ResultView, ids: string[], columns: number): HTMLTableRowElement[] {
        const details = el('tr', { className: 'feedback', hidden: true }, el('td', { colSpan: columns }, ...this.feedback(result)));
        const toggle = el('button', { type: 'button', ariaExpanded: 'false' }, `${result.student.name} (${result.student.login})`);
        toggle.addEventListener('click', () => {
            details.hidden = !details.hidden;
            toggle.ariaExpanded = String(!details.hidden);
        });
        const row = el(
            'tr',
            {},
            el('th', { scope: 'row' }, toggle),
            ...ids.map((id) => el('td', {}, criterionCell(result, id))),
            el('td', {}, `${points(result.score)}/${points(result.maxScore)}`),
        );
        return [row, details];
    }

    private feedback(result: ResultView): (Node | string)[] {
        const sections = result.criteria.map((c) =>
            el(
                'div',
                {},
                el('strong', {}, `${c.title}: ${points(c.score)}/${points(c.max)}`),
                c.feedback.length > 0 ? el('ul', {}, ...c.feedback.map((f) => el('li', {}, feedbackLine(f)))) : el('p', {}, 'No remarks.'),
            ),
        );
        const recordings = result.recordings.map((r) => el('li', {}, el('a', { href: r.url }, `Recording of ${r.scenario} (.mcap)`)));
        return [
            el('p', {}, `Submission ${result.submission}, graded ${new Date(result.gradedAt).toLocaleString()}`),
            ...sections,
            ...(recordings.length > 0 ? [el('ul', { className: 'recordings' }, ...recordings)] : []),
        ];
    }
}
