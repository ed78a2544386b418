/** The workbench's commands and shortcuts, and the guard against leaving with unsaved changes. */
import * as monaco from '@codingame/monaco-vscode-editor-api';
import { showPanel } from './bottom-panel.js';
import type { EditorArea } from './editors.js';
import type { GeneratePanel } from './generate.js';
import { QuickOpen } from './quickOpen.js';
import { messageOf, notify } from './status.js';

export function registerCommands(area: EditorArea, generate: GeneratePanel, files: string[]): void {
    const save = (): void => {
        area.save().catch((error: unknown) => notify('error', messageOf(error)));
    };
    addEditorActions(area, generate, save);
    const quickOpen = new QuickOpen(
        () => files,
        (path) => void area.open(path),
    );
    bindShortcuts(area, quickOpen, save);
    window.addEventListener('beforeunload', (e) => {
        if (area.openPaths().some((p) => area.isDirty(p))) e.preventDefault();
    });
}

/** Show Generated Code (context menu, Ctrl+Alt+G) and Save, as editor actions. */
function addEditorActions(area: EditorArea, generate: GeneratePanel, save: () => void): void {
    area.editor.addAction({
        id: 'maa.showGeneratedCode',
        label: 'Show Generated Code',
        contextMenuGroupId: 'navigation',
        contextMenuOrder: 9,
        keybindings: [monaco.KeyMod.CtrlCmd | monaco.KeyMod.Alt | monaco.KeyCode.KeyG],
        run: (editor) => {
            const path = area.activePath;
            const position = editor.getPosition();
            if (path && position) void generate.showGeneratedFor(path, { line: position.lineNumber - 1, character: position.column - 1 });
        },
    });
    area.editor.addAction({
        id: 'maa.save',
        label: 'File: Save',
        keybindings: [monaco.KeyMod.CtrlCmd | monaco.KeyCode.KeyS],
        run: () => save(),
    });
}

/**
 * Ctrl+S, Ctrl+P, Ctrl+Shift+M and Alt+W. Capture phase on the window, and the event stops
 * here: VS Code's keybinding service binds the same keys (Ctrl+P opens its own quick input,
 * Ctrl+S its save) and must not see them too.
 */
function bindShortcuts(area: EditorArea, quickOpen: QuickOpen, save: () => void): void {
    window.addEventListener(
        'keydown',
        (e) => {
            const mod = e.ctrlKey || e.metaKey;
            const key = e.key.toLowerCase();
            let handled = true;
            if (mod && !e.shiftKey && key === 's') save();
            else if (mod && !e.shiftKey && key === 'p') quickOpen.show();
            else if (mod && e.shiftKey && key === 'm') showPanel('problems');
            else if (e.altKey && key === 'w' && area.activePath) area.close(area.activePath);
            else handled = false;
            if (handled) {
                e.preventDefault();
                e.stopImmediatePropagation();
            }
        },
        true,
    );
}
