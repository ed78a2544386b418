/**
 * Lab mode's **Exercise** view in the explorer: the exercise's title, whose workspace this is (and
 * that an instructor sees it read-only), the application to generate and simulate, the tests
 * the exercise checks, the latest test result and the files the exercise keeps read-only. It is
 * the host's, not the extension's (VS Code desktop has no lab), registered through a small
 * built-in extension as the file search is.
 */
import { ExtensionHostKind, registerExtension } from '@codingame/monaco-vscode-api/extensions';
import type * as vscode from 'vscode';
import { type ExerciseItem, exerciseItems } from './exercise-items.js';
import type { ExerciseInfo } from './lab.js';

/** Registers the view with the rows of `info`; `root` is the workspace folder's path. */
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
            row.tooltip = item.tooltip;
            row.iconPath = new api.ThemeIcon(item.icon);
            if (item.file) row.command = { command: 'vscode.open', title: 'Open', arguments: [api.Uri.file(`${root}/${item.file}`)] };
            return row;
        },
    };
    api.window.createTreeView('maa.exercise', { treeDataProvider: provider });
}
