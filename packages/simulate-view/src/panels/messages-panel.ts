/**
 * The raw message view: the topics of the session with their message counts, and the chosen
 * topic's messages around the shown time (the cursor, else the newest) as JSON; the message in
 * effect at that time is marked, a click on another moves the cursor to it.
 */
import { el } from '../dom.js';
import { formatTime } from '../timeline/window.js';
import type { Panel, PanelContext } from './context.js';

/** Messages shown before and after the one in effect. */
const AROUND = 3;
/** Longest JSON shown per message (a large array stays readable). */
const MAX_JSON = 4000;

export function messageJson(message: unknown): string {
    let text: string;
    try {
        text = JSON.stringify(message, null, 2) ?? String(message);
    } catch {
        text = String(message);
    }
    return text.length > MAX_JSON ? `${text.slice(0, MAX_JSON)}\n… (${text.length - MAX_JSON} more characters)` : text;
}

export class MessagesPanel implements Panel {
    readonly id = 'messages';
    readonly title = 'Messages';
    readonly element: HTMLElement;
    private readonly topicList = el('div', { class: 'maa-messages-topics', 'data-testid': 'messages-topics' });
    private readonly view = el('div', { class: 'maa-messages-view', 'data-testid': 'messages-view' });
    private chosen: string | undefined;

    constructor(private readonly ctx: PanelContext) {
        this.element = el('div', { class: 'maa-panel maa-messages-panel', 'data-testid': 'messages-panel' }, this.topicList, this.view);
    }

    render(): void {
        const { store } = this.ctx;
        const topics = store.topics();
        if (this.chosen === undefined || !topics.includes(this.chosen)) this.chosen = topics[0];
        this.topicList.replaceChildren(
            ...topics.map((topic) => {
                const b = el(
                    'button',
                    {
                        type: 'button',
                        class: `maa-messages-topic${topic === this.chosen ? ' maa-selected' : ''}`,
                        'data-testid': 'messages-topic',
                        title: topic,
                    },
                    el('span', {}, topic),
                    el('span', { class: 'maa-messages-count' }, String(store.count(topic))),
                );
                b.dataset['topic'] = topic;
                b.addEventListener('click', () => {
                    this.chosen = topic;
                    this.ctx.redraw();
                });
                return b;
            }),
        );
        this.renderMessages();
    }

    private renderMessages(): void {
        const { store } = this.ctx;
        const topic = this.chosen;
        const t = store.shownTime;
        if (topic === undefined || t === undefined) {
            this.view.replaceChildren(el('div', { class: 'maa-panel-empty' }, 'Messages appear here during a run.'));
            return;
        }
        const current = store.latestAt(topic, t);
        // a window around the time, not the topic's whole history (a long run has many thousands)
        const shown = store.around(topic, t, AROUND, AROUND);
        this.view.replaceChildren(
            el('div', { class: 'maa-messages-head' }, `${topic} at ${formatTime(t)}${current ? '' : ' (no message yet)'}`),
            ...shown.map((m) => {
                const isCurrent = m === current;
                const entry = el(
                    'div',
                    {
                        class: `maa-messages-entry${isCurrent ? ' maa-selected' : ''}`,
                        'data-testid': isCurrent ? 'message-current' : 'message',
                    },
                    el('div', { class: 'maa-messages-time' }, formatTime(m.t)),
                    el('pre', { class: 'maa-messages-json' }, messageJson(m.message)),
                );
                entry.addEventListener('click', () => {
                    store.cursor = m.t;
                });
                return entry;
            }),
        );
    }
}
