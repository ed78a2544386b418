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
import { type ExerciseItem, exerciseItems } from './exercise-items.js';
import type { ExerciseInfo } from './lab.js';

/** Opens the exercise's description (Markdown) as a read-only document. */
const DESCRIPTION_COMMAND = 'maa.exercise.showDescription';
const DESCRIPTION_SCHEME = 'maa-exercise';

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
    const provider: vscode.TreeDataProvider<ExerciseItem> = {
        getChildren: (item) => [...(item ? (item.children ?? []) : exerciseItems(info))],
        getTreeItem: (item) => {
            const row = new api.TreeItem(
                item.label,
                item.children?.length ? api.TreeItemCollapsibleState.Collapsed : api.TreeItemCollapsibleState.None,
            );
            row.description = item.description;
            row.tooltip = item.markdown !== undefined ? new api.MarkdownString(item.markdown) : item.tooltip;
            row.iconPath = new api.ThemeIcon(item.icon);
            if (item.file) row.command = { command: 'vscode.open', title: 'Open', arguments: [api.Uri.file(`${root}/${item.file}`)] };
            else if (item.markdown !== undefined) row.command = { command: DESCRIPTION_COMMAND, title: 'Show the description' };
            return row;
        },
    };
    // The description as a read-only document of its own scheme (an untitled one would ask to be saved).
    api.workspace.registerTextDocumentContentProvider(DESCRIPTION_SCHEME, { provideTextDocumentContent: () => info.description });
    api.commands.registerCommand(DESCRIPTION_COMMAND, async () => {
        const document = await api.workspace.openTextDocument(api.Uri.from({ scheme: DESCRIPTION_SCHEME, path: '/description.md' }));
        // Plain text: this workbench has no Markdown language (Markdown reads well as it is).
        await api.window.showTextDocument(document, { preview: true });
    });
    api.window.createTreeView('maa.exercise', { treeDataProvider: provider });
    // What the student is asked to do, in a tab of its own from the start.
    await api.commands.executeCommand(DESCRIPTION_COMMAND).then(undefined, (e: unknown) => {
        // The view works without it; say why the tab is missing.
        console.warn('the exercise description did not open:', e);
    });
}
