/**
 * Simulation in VS Code desktop (docs/vscode.md "Simulate"): the commands and the simulate view of
 * session.ts, with the backend the extension starts itself: maa-ide (backend-process.ts) for the
 * application's workspace folder, reached through the relay (relay.ts). The web entry's backend is
 * web.ts.
 */
import { existsSync, realpathSync } from 'node:fs';
import path from 'node:path';
import * as vscode from 'vscode';
import type { PlatformItem } from '../platforms.js';
import { IdeBackend } from './backend-process.js';
import { backendAppPath, backendScript, readSimulateSettings } from './launch.js';
import { SimRelay } from './relay.js';
import { SimulateSession, type SimulationBackend, type SimulationTarget } from './session.js';

export { type LiveSnapshot, onDidChangeLive } from './session.js';

/** Registers the simulate commands and view; disposing stops the backend and the relay. */
export function registerSimulate(context: vscode.ExtensionContext): vscode.Disposable {
    return new SimulateSession(context.extensionUri, new DesktopBackend(context));
}

/** maa-ide started by the extension, one per workspace folder, behind the relay. */
class DesktopBackend implements SimulationBackend {
    private readonly output = vscode.window.createOutputChannel('MontiArc Simulation');
    private readonly backend: IdeBackend;
    private relay: SimRelay | undefined;
    /** The last start failed while starting or reaching maa-ide (its output tells why). */
    private backendFailed = false;

    constructor(context: vscode.ExtensionContext) {
        this.backend = new IdeBackend(context.asAbsolutePath(path.join('out', 'simulate', 'backend-launcher.mjs')), (line) =>
            this.output.appendLine(line),
        );
    }

    async target(item: PlatformItem): Promise<SimulationTarget> {
        const folder = vscode.workspace.getWorkspaceFolder(vscode.Uri.file(item.appFile))?.uri.fsPath;
        const app = folder ? backendAppPath(folder, item.appFile) : undefined;
        this.backendFailed = false;
        if (!folder || !app) throw new Error(`${item.appFile} is not inside a workspace folder.`);
        this.backendFailed = true;
        const base = await vscode.window.withProgress(
            { location: vscode.ProgressLocation.Notification, title: 'MontiArc: starting the IDE backend' },
            () => this.connect(folder),
        );
        this.backendFailed = false;
        return { app, base };
    }

    failed(): void {
        if (this.backendFailed) this.output.show(true);
    }

    dispose(): void {
        void this.relay?.close();
        void this.backend.stop();
        this.output.dispose();
    }

    /** The backend of `folder` (started or reused) behind the relay; the relay's base as the webview reaches it. */
    private async connect(folder: string): Promise<string> {
        const settings = readSimulateSettings((key) => vscode.workspace.getConfiguration().get(key));
        const folders = (vscode.workspace.workspaceFolders ?? []).map((f) => f.uri.fsPath);
        const bin = backendScript(
            settings,
            [folder, ...folders],
            (process.env['PATH'] ?? '').split(path.delimiter),
            existsSync,
            realpathSync,
        );
        if (!bin) {
            throw new Error(
                'the IDE backend maa-ide was not found: install @maa/ide-server in the workspace (npm install @maa/ide-server) or name its script in maa.simulate.backend',
            );
        }
        const running = await this.backend.ensure(folder, { node: settings.node, bin });
        const target = { port: running.port, token: running.token };
        if (this.relay) this.relay.retarget(target);
        else this.relay = new SimRelay(target);
        const external = await vscode.env.asExternalUri(vscode.Uri.parse(await this.relay.base()));
        return external.toString(true).replace(/\/+$/, '');
    }
}
