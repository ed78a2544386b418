// The grading section's texts (no DOM here, so the tests run it in Node).
import type { ResultView, RunView } from '../../src/grading/views.js';

/** A criterion of the exercise's grading as the results route lists it. */
export interface GradingCriterion {
    id: string;
    title: string;
    kind: string;
    weight: number;
}

/** What `GET /api/courses/<c>/exercises/<e>/grading` answers. */
export interface ExerciseGrading {
    course: string;
    exercise: string;
    /** null: the exercise has no grading */
    criteria: GradingCriterion[] | null;
    results: ResultView[];
    runs: RunView[];
    csv: string | null;
}

/** Points without float noise: 12.5, 30. */
export function points(n: number): string {
    return String(Math.round(n * 100) / 100);
}

/** The cell of one criterion of a result: `score/max`, or a dash when the result lacks it. */
export function criterionCell(result: ResultView, id: string): string {
    const c = result.criteria.find((x) => x.id === id);
    return c ? `${points(c.score)}/${points(c.max)}` : '—';
}

/** A run in words: `Grading… 3 of 8 tasks`, `Graded at …`, `Failed: why`. */
export function runText(run: RunView): string {
    if (run.status === 'queued') return `Run ${run.id} waits for the run before it`;
    if (run.status === 'running') return `Run ${run.id} grading… ${run.done} of ${run.total} tasks done`;
    if (run.status === 'failed') return `Run ${run.id} failed: ${run.error ?? 'no reason given'}`;
    const at = run.finishedAt ? new Date(run.finishedAt).toLocaleString() : '';
    return `Run ${run.id} finished ${at} (${run.kind === 'course' ? 'every student' : 'one submission'})`;
}

/** Whether a run still goes on (the page polls it). */
export function running(run: RunView | undefined): boolean {
    return run !== undefined && (run.status === 'queued' || run.status === 'running');
}

/** One feedback item's line: severity, text, where (file:line, scenario, simulated time, state). */
export function feedbackLine(item: unknown): string {
    const f = item as {
        severity?: string;
        text?: string;
        element?: { file: string; line: number; qualifiedName: string };
        scenario?: string;
        simTime?: number;
        state?: string;
    };
    const where = [
        f.element ? `${f.element.file}:${f.element.line} (${f.element.qualifiedName})` : '',
        f.scenario ? `scenario ${f.scenario}` : '',
        f.simTime !== undefined ? `at ${points(f.simTime)} s` : '',
        f.state ? `state ${f.state}` : '',
    ].filter(Boolean);
    return `${f.severity ?? 'info'}: ${f.text ?? ''}${where.length ? ` [${where.join(', ')}]` : ''}`;
}
