/** The rows of lab mode's Exercise view (exercise-panel.ts), from the lab's answer about the workspace. Pure. */
import type { ExerciseInfo } from './lab.js';

/** One row of the view: a label, an optional description and file to open, and children. */
export interface ExerciseItem {
    readonly label: string;
    readonly description?: string;
    readonly tooltip?: string;
    /** a workspace path the row opens */
    readonly file?: string;
    /** the line (1-based) the file opens at */
    readonly line?: number;
    /** a command the row runs (when it opens no file) */
    readonly command?: string;
    /** a download the row starts (a path on the lab) */
    readonly url?: string;
    /** open from the start (a row with children) */
    readonly expanded?: boolean;
    readonly icon: string;
    readonly children?: readonly ExerciseItem[];
    /** Markdown the row shows in its tooltip and opens as a read-only document */
    readonly markdown?: string;
}

/** The rows of the view for an exercise (pure: the tests read them). */
export function exerciseItems(info: ExerciseInfo): ExerciseItem[] {
    const latest = info.latestTests;
    return [
        { label: info.title, description: `${info.course} / ${info.exercise}`, icon: 'mortar-board', markdown: info.description },
        info.writable
            ? { label: `Your workspace (${info.owner})`, icon: 'account' }
            : { label: `${info.owner}'s workspace`, description: 'read-only (instructor view)', icon: 'lock' },
        { label: 'Application', description: info.app, file: info.app, icon: 'rocket', tooltip: `Generate and simulate ${info.app}` },
        {
            label: 'Tests',
            description: latest ? `last run: ${latest.passed} passed, ${latest.failed} failed` : 'not run yet',
            icon: latest ? (latest.failed > 0 ? 'error' : 'pass') : 'beaker',
            children: info.tests.map((t) => ({ label: t, file: t, icon: 'beaker' })),
        },
        {
            label: 'Read-only files',
            description: String(info.readOnly.length),
            tooltip: 'Part of the exercise: you can read them, not change them',
            icon: 'lock',
            children: info.readOnly.map((p) => ({ label: p, ...(p.endsWith('/') ? {} : { file: p }), icon: 'lock' })),
        },
    ];
}
