/**
 * The problems panel: every marker of every workspace file (the language server's diagnostics
 * and the generator's), grouped by file; a click opens the file at the problem.
 */
import * as monaco from '@codingame/monaco-vscode-editor-api';
import { pathOf } from '../api.js';
import type { TextRange } from '../contracts.js';
import { basename, h } from './dom.js';

export interface ProblemCounts {
    errors: number;
    warnings: number;
    infos: number;
}

export class ProblemsPanel {
    private scheduled = false;
    private readonly listeners: ((counts: ProblemCounts) => void)[] = [];
    counts: ProblemCounts = { errors: 0, warnings: 0, infos: 0 };

    constructor(
        private readonly container: HTMLElement,
        private readonly open: (path: string, range: TextRange) => void,
    ) {
        monaco.editor.onDidChangeMarkers(() => this.schedule());
        this.render();
    }

    onCounts(listener: (counts: ProblemCounts) => void): void {
        this.listeners.push(listener);
        listener(this.counts);
    }

    private schedule(): void {
        if (this.scheduled) return;
        this.scheduled = true;
        requestAnimationFrame(() => {
            this.scheduled = false;
            this.render();
        });
    }

    private render(): void {
        const markers = monaco.editor
            .getModelMarkers({})
            .filter((m) => pathOf(m.resource.toString()) !== undefined && m.severity >= monaco.MarkerSeverity.Info);
        const byFile = new Map<string, monaco.editor.IMarker[]>();
        for (const marker of markers) {
            const path = pathOf(marker.resource.toString())!;
            const list = byFile.get(path) ?? [];
            list.push(marker);
            byFile.set(path, list);
        }
        const counts: ProblemCounts = { errors: 0, warnings: 0, infos: 0 };
        const content = h('div', { class: 'problems-list' });
        for (const path of [...byFile.keys()].sort()) {
            const list = byFile
                .get(path)!
                .sort((a, b) => b.severity - a.severity || a.startLineNumber - b.startLineNumber || a.startColumn - b.startColumn);
            content.append(
                h(
                    'div',
                    { class: 'problem-file', title: path },
                    h('span', { class: 'problem-file-name' }, basename(path)),
                    h('span', { class: 'problem-file-path' }, path),
                    h('span', { class: 'badge' }, String(list.length)),
                ),
            );
            for (const marker of list) {
                const severity =
                    marker.severity === monaco.MarkerSeverity.Error
                        ? 'error'
                        : marker.severity === monaco.MarkerSeverity.Warning
                          ? 'warning'
                          : 'info';
                if (severity === 'error') counts.errors++;
                else if (severity === 'warning') counts.warnings++;
                else counts.infos++;
                const code = typeof marker.code === 'string' ? marker.code : marker.code?.value;
                const row = h(
                    'div',
                    {
                        class: `problem ${severity}`,
                        'data-severity': severity,
                        'data-path': path,
                        'data-line': String(marker.startLineNumber),
                    },
                    h('span', { class: `severity-icon ${severity}` }),
                    h('span', { class: 'problem-message' }, marker.message),
                    h('span', { class: 'problem-source' }, [marker.source, code].filter(Boolean).join(' ')),
                    h('span', { class: 'problem-position' }, `[Ln ${marker.startLineNumber}, Col ${marker.startColumn}]`),
                );
                row.addEventListener('click', () =>
                    this.open(path, {
                        start: { line: marker.startLineNumber - 1, character: marker.startColumn - 1 },
                        end: { line: marker.endLineNumber - 1, character: marker.endColumn - 1 },
                    }),
                );
                content.append(row);
            }
        }
        if (markers.length === 0) content.append(h('div', { class: 'empty' }, 'No problems have been detected in the workspace.'));
        this.container.replaceChildren(content);
        this.counts = counts;
        for (const listener of this.listeners) listener(counts);
    }
}
