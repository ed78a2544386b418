/**
 * The grading part of lab mode's Exercise view (docs/lab.md "Grading"): what the lab's
 * `GET <workspace>/grading` says (whether the exercise is graded, the student's newest grade, their
 * newest grading run) parsed, and the view's rows for it: "Submit for grading" (the owner only),
 * the run while it goes on, the score, each criterion with its score and its feedback (a feedback
 * item about a model element opens the file at its line). Pure: the tests read the rows.
 */
import type { ExerciseItem } from './exercise-items.js';

/** The command the "Submit for grading" row runs (exercise-panel.ts registers it). */
export const SUBMIT_COMMAND = 'maa.exercise.submitForGrading';

export interface GradingFeedback {
    readonly severity: 'error' | 'warning' | 'info';
    readonly text: string;
    readonly element?: { readonly qualifiedName: string; readonly file: string; readonly line: number };
    readonly scenario?: string;
    readonly simTime?: number;
    readonly state?: string;
}

export interface GradedCriterion {
    readonly id: string;
    readonly title: string;
    readonly score: number;
    readonly max: number;
    readonly feedback: readonly GradingFeedback[];
}

export interface GradingRunState {
    readonly id: number;
    readonly status: 'queued' | 'running' | 'done' | 'failed';
    readonly done: number;
    readonly total: number;
    readonly error: string | null;
    /** the run's status route (absolute path on the lab) */
    readonly url: string;
}

export interface LatestGrade {
    readonly score: number;
    readonly maxScore: number;
    readonly gradedAt: string;
    readonly criteria: readonly GradedCriterion[];
    readonly recordings: ReadonlyArray<{ readonly scenario: string; readonly url: string }>;
}

/** The lab's `GET <workspace>/grading`. */
export interface GradingState {
    readonly graded: boolean;
    readonly latest: LatestGrade | null;
    readonly run: GradingRunState | null;
}

/** The lab's answer, checked for what the view uses (an error names what is missing). */
export function parseGradingState(value: unknown): GradingState {
    const v = value as Partial<GradingState> | null;
    if (
        !v ||
        typeof v.graded !== 'boolean' ||
        (v.latest !== null && typeof v.latest !== 'object') ||
        (v.run !== null && typeof v.run !== 'object')
    )
        throw new Error("the lab's answer about grading lacks graded, latest or run");
    const latest = v.latest;
    if (latest && (typeof latest.score !== 'number' || !Array.isArray(latest.criteria)))
        throw new Error("the lab's latest grade lacks its score or criteria");
    return v as GradingState;
}

/** Whether the run still goes on. */
export function runGoesOn(run: GradingRunState | null | undefined): boolean {
    return run?.status === 'queued' || run?.status === 'running';
}

function points(n: number): string {
    return String(Math.round(n * 100) / 100);
}

const ICONS = { error: 'error', warning: 'warning', info: 'info' } as const;

function feedbackItem(f: GradingFeedback): ExerciseItem {
    const where = [
        f.scenario ? `scenario ${f.scenario}` : '',
        f.simTime !== undefined ? `at ${points(f.simTime)} s` : '',
        f.state ? `in state ${f.state}` : '',
        f.element ? `${f.element.file}:${f.element.line}` : '',
    ].filter(Boolean);
    return {
        label: f.text,
        ...(where.length ? { description: where.join(', ') } : {}),
        tooltip: f.text,
        icon: ICONS[f.severity] ?? 'info',
        ...(f.element ? { file: f.element.file, line: f.element.line } : {}),
    };
}

function criterionItem(c: GradedCriterion): ExerciseItem {
    const full = c.score >= c.max;
    return {
        label: c.title,
        description: `${points(c.score)} / ${points(c.max)}`,
        icon: full ? 'pass' : c.score > 0 ? 'warning' : 'error',
        ...(c.feedback.length ? { children: c.feedback.map(feedbackItem) } : {}),
    };
}

/** The run's row while it goes on or when it failed (nothing for a finished one: the grade says it). */
function runItem(run: GradingRunState | null): ExerciseItem[] {
    if (!run) return [];
    if (run.status === 'queued') return [{ label: 'Grading', description: 'waiting for its turn…', icon: 'watch' }];
    if (run.status === 'running') return [{ label: 'Grading', description: `${run.done} of ${run.total} tasks done…`, icon: 'sync' }];
    if (run.status === 'failed')
        return [{ label: 'The last grading failed', description: run.error ?? '', tooltip: run.error ?? '', icon: 'error' }];
    return [];
}

/** The Grading row of the view (none when the exercise is not graded). */
export function gradingItems(state: GradingState | undefined, writable: boolean): ExerciseItem[] {
    if (!state?.graded) return [];
    const latest = state.latest;
    const children: ExerciseItem[] = [
        ...(writable && !runGoesOn(state.run)
            ? [
                  {
                      label: 'Submit for grading',
                      tooltip: 'Grade your files as they are saved now',
                      icon: 'cloud-upload',
                      command: SUBMIT_COMMAND,
                  },
              ]
            : []),
        ...runItem(state.run),
        ...(latest?.criteria.map(criterionItem) ?? []),
        ...(latest?.recordings.map((r) => ({
            label: `Recording of ${r.scenario}`,
            description: '.mcap (Foxglove, Lichtblick)',
            icon: 'device-camera-video',
            url: r.url,
        })) ?? []),
    ];
    return [
        {
            label: 'Grading',
            description: latest
                ? `${points(latest.score)} / ${points(latest.maxScore)} (graded ${new Date(latest.gradedAt).toLocaleString()})`
                : 'not graded yet',
            icon: 'checklist',
            children,
            expanded: true,
        },
    ];
}
