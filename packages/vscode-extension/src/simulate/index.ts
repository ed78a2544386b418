/**
 * Simulation in VS Code desktop (docs/vscode.md "Simulate"): **MontiArc: Start Simulation**,
 * **Stop Simulation**, **Reset Simulation** and the simulate view. The extension starts the IDE
 * backend (maa-ide, backend-process.ts) for the application's workspace folder, reaches it through
 * the relay (relay.ts), and shows the panel in a webview (panel.ts). Live port values and
 * automaton states of a run go to the open diagram (src/diagram's showLiveValues and
 * showActiveStates) and to listeners of `onDidChangeLive`.
 */
import { existsSync, realpathSync } from 'node:fs';
import path from 'node:path';
import type { FromWebview } from '@maa/simulate-view/host-messages';
import * as vscode from 'vscode';
import { showActiveStates, showLiveValues } from '../diagram/index.js';
import { pickPlatform } from '../platform-pick.js';
import { IdeBackend } from './backend-process.js';
import { backendAppPath, backendScript, readSimulateSettings } from './launch.js';
import { SimulateView } from './panel.js';
import { SimRelay } from './relay.js';

/** The live state of a run as the simulate view reports it (port path → value, instance path → state). */
export interface LiveSnapshot {
    readonly values: ReadonlyMap<string, string>;
    readonly states: ReadonlyMap<string, string>;
}

const live = new vscode.EventEmitter<LiveSnapshot>();
/** Fires whenever a run's port values or active states change (empty maps: cleared). */
export const onDidChangeLive: vscode.Event<LiveSnapshot> = live.event;

/** Registers the simulate commands and view; disposing stops the backend and the relay. */
export function registerSimulate(context: vscode.ExtensionContext): vscode.Disposable {
    return new Simulation(context);
}

class Simulation implements vscode.Disposable {
    private readonly output = vscode.window.createOutputChannel('MontiArc Simulation');
    private readonly backend: IdeBackend;
    private relay: SimRelay | undefined;
    private readonly view: SimulateView;
    private readonly disposables: vscode.Disposable[];
    private snapshot: LiveSnapshot = { values: new Map(), states: new Map() };

    constructor(context: vscode.ExtensionContext) {
        this.backend = new IdeBackend(context.asAbsolutePath(path.join('out', 'simulate', 'backend-launcher.mjs')), (line) =>
            this.output.appendLine(line),
        );
        this.view = new SimulateView(context.extensionUri, (m) => this.fromView(m));
        this.disposables = [
            vscode.commands.registerCommand('maa.simulate.start', () => this.start()),
            vscode.commands.registerCommand('maa.simulate.stop', () => this.command('stop')),
            vscode.commands.registerCommand('maa.simulate.reset', () => this.command('reset')),
        ];
    }

    dispose(): void {
        for (const d of this.disposables) d.dispose();
        this.view.dispose();
        void this.relay?.close();
        void this.backend.stop();
        this.output.dispose();
    }

    private async start(): Promise<void> {
        if (!vscode.workspace.isTrusted) {
            void vscode.window.showWarningMessage('MontiArc: simulations run generated code and are available in trusted workspaces only.');
            return;
        }
        const item = await pickPlatform('Simulate');
        if (!item) return;
        const folder = vscode.workspace.getWorkspaceFolder(vscode.Uri.file(item.appFile))?.uri.fsPath;
        const app = folder ? backendAppPath(folder, item.appFile) : undefined;
        if (!folder || !app) {
            void vscode.window.showErrorMessage(`MontiArc: ${item.appFile} is not inside a workspace folder.`);
            return;
        }
        try {
            const base = await vscode.window.withProgress(
                { location: vscode.ProgressLocation.Notification, title: 'MontiArc: starting the IDE backend' },
                () => this.connect(folder),
            );
            await this.view.show(base);
            if (!(await this.view.command({ type: 'start', app, platform: item.platform }))) {
                void vscode.window.showErrorMessage(`MontiArc: the simulate view does not know ${app} with platform ${item.platform}.`);
            }
        } catch (e) {
            this.output.show(true);
            void vscode.window.showErrorMessage(`MontiArc: ${e instanceof Error ? e.message : String(e)}`);
        }
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

    private async command(type: 'stop' | 'reset'): Promise<void> {
        if (!this.view.open) {
            void vscode.window.showInformationMessage('MontiArc: no simulation view is open (MontiArc: Start Simulation).');
            return;
        }
        const ok = await this.view.command({ type });
        if (!ok && type === 'reset') void vscode.window.showInformationMessage('MontiArc: no simulation is running.');
    }

    private fromView(message: FromWebview): void {
        switch (message.type) {
            case 'notify':
                if (message.severity === 'error') void vscode.window.showErrorMessage(`MontiArc: ${message.message}`);
                else if (message.severity === 'warning') void vscode.window.showWarningMessage(`MontiArc: ${message.message}`);
                else vscode.window.setStatusBarMessage(`MontiArc: ${message.message}`, 5000);
                break;
            case 'live-values':
                this.snapshot = { values: new Map(message.values), states: this.snapshot.states };
                showLiveValues(this.snapshot.values);
                live.fire(this.snapshot);
                break;
            case 'active-states':
                this.snapshot = { values: this.snapshot.values, states: new Map(message.states) };
                showActiveStates(this.snapshot.states);
                live.fire(this.snapshot);
                break;
            default:
                break;
        }
    }
}
