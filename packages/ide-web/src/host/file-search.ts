/**
 * File search over the workspace listing, so that quick open (Ctrl+P) and the extension's
 * `workspace.findFiles` (Generate's platform pick) work on the backend's files: VS Code's search
 * service asks a file search provider for the `file` scheme, and a workbench without a disk has
 * none. The provider is registered through a small built-in extension of the host's own (the
 * `fileSearchProvider` API is a proposal, open to built-in extensions). VS Code scores and
 * filters quick open's results and applies findFiles' globs itself; the provider narrows by the
 * typed pattern only.
 */
import { ExtensionHostKind, registerExtension } from '@codingame/monaco-vscode-api/extensions';
import type * as vscode from 'vscode';
import { matchesPattern } from './workspace-tree.js';

/** The proposal's provider, as far as the host implements it. */
interface FileSearchProvider {
    provideFileSearchResults(query: { pattern: string }, options: { folder: vscode.Uri; maxResults?: number }): vscode.Uri[];
}
type SearchApi = typeof vscode & {
    workspace: { registerFileSearchProvider(scheme: string, provider: FileSearchProvider): vscode.Disposable };
};

/** Registers the provider; `files` lists the workspace's files (paths below `root`) at the time of each search. */
export async function registerFileSearch(root: string, files: () => string[]): Promise<void> {
    const extension = registerExtension(
        {
            name: 'maa-host-file-search',
            publisher: 'maa-web',
            version: '0.1.0',
            engines: { vscode: '*' },
            enabledApiProposals: ['fileSearchProvider'],
        },
        ExtensionHostKind.LocalProcess,
        { system: true },
    );
    const api = (await extension.getApi()) as SearchApi;
    api.workspace.registerFileSearchProvider('file', {
        provideFileSearchResults(query, options) {
            if (options.folder.path !== root) return [];
            const hits = files()
                .filter((p) => matchesPattern(p, query.pattern))
                .map((p) => api.Uri.file(`${root}/${p}`));
            return options.maxResults ? hits.slice(0, options.maxResults) : hits;
        },
    });
}
