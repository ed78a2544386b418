/** The bottom panel: its tabs (Problems / Generate / Simulate) and the problem counts in the status line. */
import type { EditorArea } from './editors.js';
import { byId, h } from './dom.js';
import { ProblemsPanel } from './problems.js';

export type PanelTab = 'problems' | 'generate' | 'simulate';

export function showPanel(tab: PanelTab): void {
    for (const button of document.querySelectorAll<HTMLElement>('.panel-tab'))
        button.classList.toggle('active', button.dataset.tab === tab);
    for (const view of document.querySelectorAll<HTMLElement>('.panel-view')) view.hidden = view.dataset.tab !== tab;
}

/** Each tab button shows its view. */
export function wirePanelTabs(): void {
    for (const button of document.querySelectorAll<HTMLElement>('.panel-tab')) {
        button.addEventListener('click', () => showPanel(button.dataset.tab as PanelTab));
    }
}

/** The Problems panel, its count on the tab and in the status line (a click there shows the panel). */
export function mountProblemsPanel(area: EditorArea): ProblemsPanel {
    const problems = new ProblemsPanel(byId('problems'), (path, range) => void area.open(path, range));
    const problemsCount = byId('problems-count');
    const statusProblems = byId('status-problems');
    problems.onCounts((c) => {
        problemsCount.textContent = String(c.errors + c.warnings);
        problemsCount.hidden = c.errors + c.warnings === 0;
        statusProblems.replaceChildren(
            h('span', { class: 'severity-icon error' }),
            ` ${c.errors} `,
            h('span', { class: 'severity-icon warning' }),
            ` ${c.warnings}`,
        );
    });
    statusProblems.addEventListener('click', () => showPanel('problems'));
    return problems;
}
