/** The VS Code services (monaco-vscode-api, classic mode with Monarch) and the workspace file overlay. */
import * as monaco from '@codingame/monaco-vscode-editor-api';
import type { OpenEditor } from '@codingame/monaco-vscode-editor-service-override';
import { LogLevel } from '@codingame/monaco-vscode-api';
import { MonacoVscodeApiWrapper } from 'monaco-languageclient/vscodeApiWrapper';
import EditorWorker from '@codingame/monaco-vscode-editor-api/esm/vs/editor/editor.worker.js?worker';
import { registerFileSystemOverlay, RegisteredFileSystemProvider } from '@codingame/monaco-vscode-files-service-override';
import { pathOf } from '../api.js';
import { registerLanguages } from '../languages.js';
import type { EditorArea } from './editors.js';

/** VS Code's "open editor" (go to definition, peek, references) as a tab of the editor area, once it exists. */
export function openEditorIn(areaOf: () => EditorArea | undefined): OpenEditor {
    return async (modelRef, options) => {
        const uri = modelRef.object.textEditorModel.uri.toString();
        const path = pathOf(uri);
        const editors = areaOf();
        if (!path || !editors) return undefined;
        const selection =
            options && 'selection' in options
                ? (options as { selection?: { startLineNumber: number; startColumn: number; endLineNumber?: number; endColumn?: number } })
                      .selection
                : undefined;
        const range = selection
            ? {
                  start: { line: selection.startLineNumber - 1, character: selection.startColumn - 1 },
                  end: {
                      line: (selection.endLineNumber ?? selection.startLineNumber) - 1,
                      character: (selection.endColumn ?? selection.startColumn) - 1,
                  },
              }
            : undefined;
        return await editors.open(path, range);
    };
}

/**
 * Starts the services, registers the family's languages and returns the workspace files for
 * VS Code's file service (peek/references into files without a tab).
 */
export async function startServices(openEditor: OpenEditor): Promise<RegisteredFileSystemProvider> {
    const wrapper = new MonacoVscodeApiWrapper({
        $type: 'classic',
        viewsConfig: { $type: 'EditorService', openEditorFunc: openEditor },
        logLevel: LogLevel.Warning,
        advanced: { enforceSemanticHighlighting: true },
        userConfiguration: {
            json: JSON.stringify({
                'workbench.colorTheme': 'Default Dark Modern',
                'editor.semanticHighlighting.enabled': true,
                'editor.guides.bracketPairsHorizontal': 'active',
                'editor.lightbulb.enabled': 'onCode',
            }),
        },
        // Monaco's own worker (diff, links, word-based suggestions), bundled by Vite.
        monacoWorkerFactory: () => {
            const environment: monaco.Environment = { getWorker: () => new EditorWorker() };
            (globalThis as { MonacoEnvironment?: monaco.Environment }).MonacoEnvironment = environment;
        },
    });
    await wrapper.start();
    const workspaceFiles = new RegisteredFileSystemProvider(false);
    registerFileSystemOverlay(1, workspaceFiles);
    registerLanguages();
    monaco.editor.setTheme('vs-dark');
    return workspaceFiles;
}
