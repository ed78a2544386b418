/**
 * A transition selected in the simulate view's panels, shown in the model (docs/vscode.md
 * "Simulate"): the source line opens in the editor beside the view, and the diagrams highlight
 * the state and transition (`maa.diagram.highlightTrace`, registered by the diagram side; called
 * only when it is there). The message was checked by parseFromWebview: the file is relative and
 * is opened only inside a workspace folder.
 */
import type { RevealMessage } from '@maa/simulate-view/host-messages';
import * as vscode from 'vscode';

export const HIGHLIGHT_COMMAND = 'maa.diagram.highlightTrace';

/** The file in the first workspace folder that has it, `undefined` when none has. */
async function findInWorkspace(file: string): Promise<vscode.Uri | undefined> {
    for (const folder of vscode.workspace.workspaceFolders ?? []) {
        const uri = vscode.Uri.joinPath(folder.uri, ...file.split('/'));
        try {
            await vscode.workspace.fs.stat(uri);
            return uri;
        } catch {
            /* not in this folder */
        }
    }
    return undefined;
}

/** Opens the line (its text from the column selected) and highlights the trace in the diagrams. */
export async function revealTrace(message: RevealMessage): Promise<void> {
    const uri = await findInWorkspace(message.file);
    if (!uri) {
        void vscode.window.showWarningMessage(`MontiArc: ${message.file} is not in the workspace.`);
        return;
    }
    const doc = await vscode.workspace.openTextDocument(uri);
    const line = Math.min(message.line, doc.lineCount) - 1;
    const text = doc.lineAt(line);
    const start = new vscode.Position(line, Math.min((message.column ?? 1) - 1, text.range.end.character));
    const selection = new vscode.Range(start, text.range.end);
    // the first editor group: the simulate view stays where it is (beside)
    const editor = await vscode.window.showTextDocument(doc, { selection, viewColumn: vscode.ViewColumn.One, preserveFocus: true });
    editor.revealRange(selection, vscode.TextEditorRevealType.InCenterIfOutsideViewport);
    if (message.highlight && (await vscode.commands.getCommands(true)).includes(HIGHLIGHT_COMMAND)) {
        await vscode.commands.executeCommand(HIGHLIGHT_COMMAND, message.highlight);
    }
}
