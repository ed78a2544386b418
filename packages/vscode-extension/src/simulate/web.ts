/**
 * Simulation in the browser IDE (the extension's web entry, docs/vscode.md "Simulate"): the
 * commands and the simulate view of session.ts against the backend that serves the page
 * (web-target.ts). The view's page connects to and frames only that origin (its CSP,
 * webview-html.ts).
 */
import * as vscode from 'vscode';
import type { PlatformItem } from '../platforms.js';
import { SimulateSession, type SimulationBackend, type SimulationTarget } from './session.js';
import { webAppPath, webBackendBase } from './web-target.js';

export { type LiveSnapshot, onDidChangeLive } from './session.js';

/** Registers the simulate commands and view against the backend at `apiBase` (web/backend.ts backendBase). */
export function registerWebSimulate(context: vscode.ExtensionContext, apiBase: string): vscode.Disposable {
    return new SimulateSession(context.extensionUri, new PageBackend(webBackendBase(apiBase)));
}

/** The page's own backend: nothing to start or stop. */
class PageBackend implements SimulationBackend {
    constructor(private readonly base: string) {}

    async target(item: PlatformItem): Promise<SimulationTarget> {
        const folder = vscode.workspace.workspaceFolders?.[0]?.uri.path ?? '/';
        const app = webAppPath(folder, item.appFile);
        if (!app) throw new Error(`${item.appFile} is not inside the workspace folder ${folder}.`);
        return { app, base: this.base };
    }

    dispose(): void {
        /* the backend belongs to the page */
    }
}
