/** Ctrl+P: a small quick-open list over the workspace files. */
import { h } from './dom.js';

export class QuickOpen {
    private readonly overlay: HTMLElement;
    private readonly input: HTMLInputElement;
    private readonly list: HTMLElement;
    private matches: string[] = [];
    private index = 0;

    constructor(
        private readonly files: () => string[],
        private readonly open: (path: string) => void,
    ) {
        this.input = h('input', { class: 'quick-open-input', placeholder: 'Search files by name', 'data-testid': 'quick-open' });
        this.list = h('div', { class: 'quick-open-list' });
        this.overlay = h('div', { class: 'quick-open', hidden: '' }, this.input, this.list);
        document.body.append(this.overlay);
        this.input.addEventListener('input', () => this.update());
        this.input.addEventListener('keydown', (e) => {
            if (e.key === 'Escape') this.hide();
            else if (e.key === 'ArrowDown') {
                this.index = Math.min(this.index + 1, this.matches.length - 1);
                this.render();
                e.preventDefault();
            } else if (e.key === 'ArrowUp') {
                this.index = Math.max(this.index - 1, 0);
                this.render();
                e.preventDefault();
            } else if (e.key === 'Enter') this.choose(this.matches[this.index]);
        });
        this.input.addEventListener('blur', () => setTimeout(() => this.hide(), 150));
    }

    show(): void {
        this.overlay.hidden = false;
        this.input.value = '';
        this.update();
        this.input.focus();
    }

    hide(): void {
        this.overlay.hidden = true;
    }

    private choose(path: string | undefined): void {
        this.hide();
        if (path) this.open(path);
    }

    private update(): void {
        const query = this.input.value.toLowerCase();
        this.matches = this.files()
            .filter((p) => fuzzy(p.toLowerCase(), query))
            .sort((a, b) => score(a, query) - score(b, query) || a.localeCompare(b))
            .slice(0, 50);
        this.index = 0;
        this.render();
    }

    private render(): void {
        this.list.replaceChildren(
            ...this.matches.map((path, i) => {
                const row = h(
                    'div',
                    { class: `quick-open-item${i === this.index ? ' selected' : ''}` },
                    h('span', {}, path.slice(path.lastIndexOf('/') + 1)),
                    h('span', { class: 'muted' }, path),
                );
                row.addEventListener('mousedown', (e) => {
                    e.preventDefault();
                    this.choose(path);
                });
                return row;
            }),
        );
    }
}

function fuzzy(text: string, query: string): boolean {
    let i = 0;
    for (const c of text) if (c === query[i]) i++;
    return i >= query.length;
}

function score(path: string, query: string): number {
    const name = path.slice(path.lastIndexOf('/') + 1).toLowerCase();
    return name.startsWith(query) ? 0 : name.includes(query) ? 1 : 2;
}
