/**
 * Lab mode's **Exercise** view in the explorer: the exercise's title (its description as the
 * tooltip and, on a click, in a tab of its own, opened at the start), whose workspace this is (and
 * that an instructor sees it read-only), the application to generate and simulate, the tests
 * the exercise checks, the latest test result and the files the exercise keeps read-only. It is
 * the host's, not the extension's (VS Code desktop has no lab), registered through a small
 * built-in extension as the file search is.
 */
import { ExtensionHostKind, registerExtension } from '@codingame/monaco-vscode-api/extensions';
import type * as vscode from 'vscode';
import { type GradingState, gradingItems, parseGradingState, runGoesOn, SUBMIT_COMMAND } from './exercise-grading.js';
import { type ExerciseItem, exerciseItems } from './exercise-items.js';
import type { ExerciseInfo } from './lab.js';

/** Opens the exercise's description (Markdown) as a read-only document. */
const DESCRIPTION_COMMAND = 'maa.exercise.showDescription';
const DESCRIPTION_SCHEME = 'maa-exercise';
/** Starts a download (a recording) from the lab. */
const DOWNLOAD_COMMAND = 'maa.exercise.download';
/** How often a grading run's progress is asked for while it goes on. */
const RUN_POLL_MS = 1500;

/** Registers the view with the rows of `info` and shows the description; `root` is the workspace folder's path. */
export async function registerExercisePanel(info: ExerciseInfo, root: string): Promise<void> {
    const extension = registerExtension(
        {
            name: 'maa-host-exercise',
            publisher: 'maa-web',
            version: '0.1.0',
            engines: { vscode: '*' },
            contributes: { views: { explorer: [{ id: 'maa.exercise', name: 'Exercise' }] } },
        },
        ExtensionHostKind.LocalProcess,
        { system: true },
    );
    const api = (await extension.getApi()) as typeof vscode;
    let grading: GradingState | undefined;
    const changed = new api.EventEmitter<undefined>();
    const provider: vscode.TreeDataProvider<ExerciseItem> = {
        onDidChangeTreeData: changed.event,
        getChildren: (item) => (item ? [...(item.children ?? [])] : rootItems(info, grading)),
        getTreeItem: (item) => treeItem(api, item, root),
    };
    const refreshGrading = async (): Promise<GradingState | undefined> => {
        grading = await readGrading().catch((e: unknown) => {
            console.warn('the grading state did not load:', e);
            return grading;
        });
        changed.fire(undefined);
        return grading;
    };
    api.commands.registerCommand(SUBMIT_COMMAND, () => submitForGrading(api, refreshGrading));
    api.commands.registerCommand(DOWNLOAD_COMMAND, (url: string) => download(url));
    // The description as a read-only document of its own scheme (an untitled one would ask to be saved).
    api.workspace.registerTextDocumentContentProvider(DESCRIPTION_SCHEME, { provideTextDocumentContent: () => info.description });
    api.commands.registerCommand(DESCRIPTION_COMMAND, async () => {
        const document = await api.workspace.openTextDocument(api.Uri.from({ scheme: DESCRIPTION_SCHEME, path: '/description.md' }));
        // Plain text: this workbench has no Markdown language (Markdown reads well as it is).
        await api.window.showTextDocument(document, { preview: true });
    });
    api.window.createTreeView('maa.exercise', { treeDataProvider: provider });
    void refreshGrading().then((state) => (runGoesOn(state?.run) ? followRun(refreshGrading) : undefined));
    // What the student is asked to do, in a tab of its own from the start.
    await api.commands.executeCommand(DESCRIPTION_COMMAND).then(undefined, (e: unknown) => {
        // The view works without it; say why the tab is missing.
        console.warn('the exercise description did not open:', e);
    });
}

type Api = typeof vscode;

/** The view's rows: the exercise and whose workspace, then its grading (near the top: the pane is small), then the rest. */
function rootItems(info: ExerciseInfo, grading: GradingState | undefined): ExerciseItem[] {
    const items = exerciseItems(info);
    return [...items.slice(0, 2), ...gradingItems(grading, info.writable), ...items.slice(2)];
}

/** One row of the view as VS Code shows it: a file row opens the file (at its line), a command row runs it. */
function treeItem(api: Api, item: ExerciseItem, root: string): vscode.TreeItem {
    const state = item.children?.length
        ? item.expanded
            ? api.TreeItemCollapsibleState.Expanded
            : api.TreeItemCollapsibleState.Collapsed
        : api.TreeItemCollapsibleState.None;
    const row = new api.TreeItem(item.label, state);
    row.description = item.description;
    row.tooltip = item.markdown !== undefined ? new api.MarkdownString(item.markdown) : item.tooltip;
    row.iconPath = new api.ThemeIcon(item.icon);
    if (item.file) {
        const uri = api.Uri.file(`${root}/${item.file}`);
        const at = item.line !== undefined ? [{ selection: new api.Range(item.line - 1, 0, item.line - 1, 0) }] : [];
        row.command = { command: 'vscode.open', title: 'Open', arguments: [uri, ...at] };
    } else if (item.command) row.command = { command: item.command, title: item.label };
    else if (item.url) row.command = { command: DOWNLOAD_COMMAND, title: 'Download', arguments: [item.url] };
    else if (item.markdown !== undefined) row.command = { command: DESCRIPTION_COMMAND, title: 'Show the description' };
    return row;
}

/** The lab's grading state of this workspace (`api/grading` below the page: the workspace's route). */
async function readGrading(): Promise<GradingState> {
    const response = await fetch('api/grading', { cache: 'no-store' });
    if (!response.ok) throw new Error(`reading the grading: ${response.status} ${response.statusText}`);
    return parseGradingState(await response.json());
}

/** Saves the open editors, submits the workspace, follows the run, and says the grade. */
async function submitForGrading(api: Api, refresh: () => Promise<GradingState | undefined>): Promise<void> {
    await api.workspace.saveAll(false);
    const response = await fetch('api/grading/submit', { method: 'POST', headers: { 'Content-Type': 'application/json' }, body: '{}' });
    const answer = (await response.json().catch(() => ({}))) as { error?: string };
    if (!response.ok) {
        await api.window.showErrorMessage(`Submitting failed: ${answer.error ?? response.statusText}`);
        return;
    }
    const state = await followRun(refresh);
    if (state?.run?.status === 'failed') await api.window.showErrorMessage(`Grading failed: ${state.run.error ?? 'no reason given'}`);
    else if (state?.latest)
        await api.window.showInformationMessage(`Graded: ${state.latest.score} of ${state.latest.maxScore} points (see the Exercise view)`);
}

/** Refreshes the view until the newest run has ended. */
async function followRun(refresh: () => Promise<GradingState | undefined>): Promise<GradingState | undefined> {
    let state = await refresh();
    while (runGoesOn(state?.run)) {
        await new Promise((resolve) => setTimeout(resolve, RUN_POLL_MS));
        state = await refresh();
    }
    return state;
}

/** A download of the lab's (a recording with Content-Disposition: attachment). */
function download(url: string): void {
    const link = document.createElement('a');
    link.href = url;
    link.download = '';
    link.rel = 'noopener';
    document.body.append(link);
    link.click();
    link.remove();
}
