/** The status line, the error box (message and log tail) and the start's progress log. */
import { el } from './dom.js';

export class StatusView {
    readonly bar: HTMLElement;
    readonly errorBox = el('div', { class: 'maa-sim-error', 'data-testid': 'sim-error', hidden: '' });
    readonly progressBox: HTMLElement;
    private readonly text = el('span', { class: 'maa-sim-status', 'data-testid': 'sim-status' }, 'Not running');
    private readonly progressLog = el('pre', { class: 'maa-sim-log maa-sim-progress-log', 'data-testid': 'sim-progress-log' });

    constructor() {
        this.bar = el('div', { class: 'maa-sim-statusbar' }, this.text);
        this.progressBox = el('div', { class: 'maa-sim-progress', 'data-testid': 'sim-progress', hidden: '' }, this.progressLog);
    }

    /** The status line. */
    set(text: string): void {
        this.text.textContent = text;
    }

    /** Shows a message with the last 40 log lines; `undefined` hides the box. */
    showError(message: string | undefined, log: readonly string[] = []): void {
        if (!message) {
            this.errorBox.hidden = true;
            this.errorBox.replaceChildren();
            return;
        }
        this.errorBox.hidden = false;
        const children: Node[] = [el('div', { class: 'maa-sim-error-message' }, message)];
        if (log.length > 0) children.push(el('pre', { class: 'maa-sim-log', 'data-testid': 'sim-log' }, log.slice(-40).join('\n')));
        const close = el('button', { type: 'button', class: 'maa-sim-error-close', title: 'Dismiss' }, '×');
        close.addEventListener('click', () => this.showError(undefined));
        this.errorBox.replaceChildren(close, ...children);
    }

    /** Shows the last 12 lines of a start's log (none: nothing changes). */
    showProgress(log: readonly string[]): void {
        if (log.length === 0) return;
        this.progressLog.textContent = log.slice(-12).join('\n');
        this.progressBox.hidden = false;
        this.progressLog.scrollTop = this.progressLog.scrollHeight;
    }

    hideProgress(): void {
        this.progressBox.hidden = true;
        this.progressLog.textContent = '';
    }
}
