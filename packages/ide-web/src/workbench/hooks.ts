/** `window.maaIde`: timings and hooks for the e2e tests and the benchmark. */
import * as monaco from '@codingame/monaco-vscode-editor-api';
import { pathOf, uriOf } from '../api.js';
import type { TextRange } from '../contracts.js';

export interface IdeHooks {
    timings: Record<string, number>;
    ready: boolean;
    diagramUpdates: number;
    editor?: monaco.editor.IStandaloneCodeEditor;
    open(path: string, range?: TextRange): Promise<void>;
    markers(): { path: string; severity: number; message: string; line: number }[];
    /** The current text of a workspace file's model (undefined when not loaded). */
    text(path: string): string | undefined;
    /** Selects the `occurrence`-th match of `needle` in the active editor (plus offset/length). */
    select(needle: string, options?: { occurrence?: number; offset?: number; length?: number }): boolean;
}
declare global {
    interface Window {
        maaIde: IdeHooks;
    }
}

/** The hooks: main.ts sets `timings.start` first thing, `editor` and `open` once the editor area exists. */
export const hooks: IdeHooks = {
    timings: {},
    ready: false,
    diagramUpdates: 0,
    open: async () => undefined,
    markers: () =>
        monaco.editor.getModelMarkers({}).map((m) => ({
            path: pathOf(m.resource.toString()) ?? m.resource.toString(),
            severity: m.severity,
            message: m.message,
            line: m.startLineNumber,
        })),
    text: (path) => monaco.editor.getModel(monaco.Uri.parse(uriOf(path)))?.getValue(),
    select: (needle, options = {}) => {
        const editor = hooks.editor;
        const model = editor?.getModel();
        if (!editor || !model) return false;
        const matches = model.findMatches(needle, false, false, true, null, false);
        const match = matches[options.occurrence ?? 0];
        if (!match) return false;
        const start = model.modifyPosition(match.range.getStartPosition(), options.offset ?? 0);
        const end = model.modifyPosition(start, options.length ?? (options.offset === undefined ? needle.length : 0));
        editor.setSelection(monaco.Selection.fromPositions(start, end));
        editor.revealPositionInCenterIfOutsideViewport(start);
        editor.focus();
        return true;
    },
};
