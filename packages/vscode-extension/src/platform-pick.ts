/**
 * The platform quick pick of **MontiArc: Generate** and **MontiArc: Start Simulation**: every
 * platform of the workspace's `.arcapp` files (platforms.ts scans them). Uses only `vscode` (no
 * Node built-ins), so the desktop and the web entry share it.
 */
import * as vscode from 'vscode';
import { type PlatformItem, platformItems } from './platforms.js';

/** Asks for a platform of the workspace's application configurations (`verb`: "Generate", "Simulate"); undefined when there is none or the user cancels. */
export async function pickPlatform(verb: string): Promise<PlatformItem | undefined> {
    const uris = await vscode.workspace.findFiles('**/*.arcapp', '**/{node_modules,.git,out}/**');
    const files = await Promise.all(
        uris.map(async (uri) => ({
            file: uri.fsPath,
            displayPath: vscode.workspace.asRelativePath(uri),
            text: new TextDecoder().decode(await vscode.workspace.fs.readFile(uri)),
        })),
    );
    const items = platformItems(files);
    if (items.length === 0) {
        void vscode.window.showWarningMessage('MontiArc: no application configuration (.arcapp) with a platform in the workspace.');
        return undefined;
    }
    return vscode.window.showQuickPick(items, { placeHolder: `${verb} which platform?`, matchOnDescription: true });
}
