/**
 * The log: the transitions taken (all components) and the RobotArm program steps, by simulated
 * time. Clicking an entry moves the cursor there and shows it in the model (the transition's
 * line and diagram highlight; a program step's line when its event names the file).
 */
import { el } from '../dom.js';
import type { ProgramStep, TakenTransition } from '../timeline/transitions.js';
import { formatTime } from '../timeline/window.js';
import { nodeLabel, type Panel, type PanelContext } from './context.js';

/** The newest entries listed (a long run's log stays light). */
export const MAX_ENTRIES = 500;

type Entry = { kind: 'transition'; t: number; item: TakenTransition } | { kind: 'step'; t: number; item: ProgramStep };

/** Transitions and program steps merged by time (transitions first at the same time), the newest `max`. */
export function logEntries(transitions: readonly TakenTransition[], steps: readonly ProgramStep[], max = MAX_ENTRIES): Entry[] {
    const all: Entry[] = [
        ...transitions.map((item): Entry => ({ kind: 'transition', t: item.t, item })),
        ...steps.map((item): Entry => ({ kind: 'step', t: item.t, item })),
    ];
    all.sort((a, b) => a.t - b.t || (a.kind === b.kind ? 0 : a.kind === 'transition' ? -1 : 1));
    return all.slice(-max);
}

/** The note over a log that lists only its newest entries: "showing the newest 500 of 1234 entries". */
export function droppedNote(shown: number, total: number): string {
    return total > shown ? `showing the newest ${shown} of ${total} entries` : '';
}

export class LogPanel implements Panel {
    readonly id = 'log';
    readonly title = 'Log';
    readonly element: HTMLElement;
    private readonly body = el('tbody');
    private readonly empty = el('div', { class: 'maa-panel-empty' }, 'Transitions taken and program steps appear here during a run.');
    /** Says that older entries are not listed ("showing the newest 500 of 1234"). */
    private readonly dropped = el('div', { class: 'maa-log-dropped', 'data-testid': 'log-dropped', hidden: '' });
    /** What the table shows now (redrawn only when it changed). */
    private shownKey = '';

    constructor(private readonly ctx: PanelContext) {
        this.element = el(
            'div',
            { class: 'maa-panel maa-log-panel', 'data-testid': 'log-panel' },
            this.empty,
            this.dropped,
            el(
                'table',
                { class: 'maa-log-table' },
                el('thead', {}, el('tr', {}, el('th', {}, 'Time'), el('th', {}, 'Component'), el('th', {}, 'What'))),
                this.body,
            ),
        );
    }

    render(): void {
        const { ctx } = this;
        const transitions = ctx.index.allTransitions();
        const steps = ctx.index.programSteps();
        const entries = logEntries(transitions, steps);
        const total = transitions.length + steps.length;
        this.empty.hidden = entries.length > 0;
        this.dropped.hidden = total <= entries.length;
        this.dropped.textContent = droppedNote(entries.length, total);
        const sel = ctx.selected;
        const key = `${entries.length}:${entries[entries.length - 1]?.t}:${sel?.t}:${sel?.node}:${sel?.to}:${ctx.store.cursor}`;
        if (key === this.shownKey) return;
        this.shownKey = key;
        this.body.replaceChildren(...entries.map((e) => this.row(e)));
    }

    private row(e: Entry): HTMLElement {
        const { ctx } = this;
        const what =
            e.kind === 'transition'
                ? `${e.item.from} → ${e.item.to}`
                : `${e.item.program} step ${e.item.step + 1}: ${e.item.text} (line ${e.item.line})`;
        const selected = e.kind === 'transition' && e.item === ctx.selected;
        const tr = el(
            'tr',
            { class: `maa-log-${e.kind}${selected ? ' maa-selected' : ''}`, 'data-testid': 'log-entry' },
            el('td', {}, formatTime(e.t)),
            el('td', {}, nodeLabel(ctx, e.item.node)),
            el('td', {}, what),
        );
        tr.dataset['kind'] = e.kind;
        tr.addEventListener('click', () => {
            if (e.kind === 'transition') ctx.select(e.item);
            else ctx.selectStep(e.item);
        });
        return tr;
    }
}
