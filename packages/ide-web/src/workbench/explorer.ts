/** The file explorer: the workspace tree from GET /api/files; click opens a file. */
import type { FileEntry } from '../api.js';
import { basename, h } from './dom.js';

export class Explorer {
    private selected: string | undefined;
    private readonly collapsed = new Set<string>();
    private entries: FileEntry[] = [];

    constructor(
        private readonly container: HTMLElement,
        private readonly openFile: (path: string) => void,
    ) {}

    setEntries(root: string, entries: FileEntry[]): void {
        this.entries = entries;
        this.container.replaceChildren(h('div', { class: 'explorer-title' }, root.toUpperCase()), this.renderLevel(''));
        this.markSelected();
    }

    select(path: string | undefined): void {
        this.selected = path;
        // Unfold the folders above the file.
        if (path) {
            let changed = false;
            for (let i = path.indexOf('/'); i >= 0; i = path.indexOf('/', i + 1)) {
                changed = this.collapsed.delete(path.slice(0, i)) || changed;
            }
            if (changed) this.rerender();
        }
        this.markSelected();
    }

    private rerender(): void {
        const title = this.container.firstElementChild;
        this.container.replaceChildren(...(title ? [title] : []), this.renderLevel(''));
    }

    private markSelected(): void {
        for (const row of this.container.querySelectorAll<HTMLElement>('.tree-row')) {
            row.classList.toggle('selected', row.dataset.path === this.selected);
        }
    }

    private renderLevel(folder: string): HTMLElement {
        const list = h('ul', { class: 'tree' });
        const children = this.entries
            .filter((e) => {
                const slash = e.path.lastIndexOf('/');
                return (slash < 0 ? '' : e.path.slice(0, slash)) === folder;
            })
            .sort((a, b) => (a.type === b.type ? a.path.localeCompare(b.path) : a.type === 'directory' ? -1 : 1));
        const depth = folder === '' ? 0 : folder.split('/').length;
        for (const entry of children) {
            const isDir = entry.type === 'directory';
            const open = isDir && !this.collapsed.has(entry.path);
            const row = h(
                'div',
                {
                    class: `tree-row ${isDir ? 'folder' : 'file'}`,
                    'data-path': entry.path,
                    title: entry.path,
                    style: `padding-left:${8 + depth * 12}px`,
                },
                h('span', { class: 'twistie' }, isDir ? (open ? '▾' : '▸') : ''),
                h('span', { class: `file-icon ${iconClass(entry.path, isDir)}` }),
                h('span', { class: 'tree-label' }, basename(entry.path)),
            );
            row.addEventListener('click', () => {
                if (isDir) {
                    if (open) this.collapsed.add(entry.path);
                    else this.collapsed.delete(entry.path);
                    this.rerender();
                    this.markSelected();
                } else {
                    this.openFile(entry.path);
                }
            });
            const item = h('li', {}, row);
            if (open) item.append(this.renderLevel(entry.path));
            list.append(item);
        }
        return list;
    }
}

function iconClass(path: string, isDir: boolean): string {
    if (isDir) return 'icon-folder';
    const ext = path.slice(path.lastIndexOf('.') + 1);
    return `icon-${ext}`;
}
