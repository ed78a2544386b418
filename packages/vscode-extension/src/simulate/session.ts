/**
 * What the simulate commands do in both entries (docs/vscode.md "Simulate"): **MontiArc: Start
 * Simulation**, **Stop Simulation**, **Reset Simulation** and the simulate view (panel.ts), with
 * the live port values and automaton states of a run going to the open diagram (src/diagram's
 * showLiveValues and showActiveStates) and to listeners of `onDidChangeLive`. Where the backend
 * is comes from the entry: desktop starts maa-ide behind a relay (index.ts), the web entry uses
 * the page's own origin (web.ts). Uses only `vscode` (no Node built-ins), so both entries share it.
 */
import type { FromWebview } from '@maa/simulate-view/host-messages';
import * as vscode from 'vscode';
import { showActiveStates, showLiveValues } from '../diagram/index.js';
import { pickPlatform } from '../platform-pick.js';
import type { PlatformItem } from '../platforms.js';
import { SimulateView } from './panel.js';
import { revealTrace } from './reveal.js';

/** The live state of a run as the simulate view reports it (port path → value, instance path → state). */
export interface LiveSnapshot {
    readonly values: ReadonlyMap<string, string>;
    readonly states: ReadonlyMap<string, string>;
}

const live = new vscode.EventEmitter<LiveSnapshot>();
/** Fires whenever a run's port values or active states change (empty maps: cleared). */
export const onDidChangeLive: vscode.Event<LiveSnapshot> = live.event;

/** Where a simulation of a picked platform runs: the application as the backend names it, and the backend's base URL as the view reaches it. */
export interface SimulationTarget {
    readonly app: string;
    readonly base: string;
}

/** The entry's part: finding the backend for an application (desktop: start maa-ide and the relay; web: the page's origin). */
export interface SimulationBackend extends vscode.Disposable {
    /** The target of `item`; throws with a message for the user when there is none. */
    target(item: PlatformItem): Promise<SimulationTarget>;
    /** Called after `target` failed (desktop: shows the backend's output). */
    failed?(): void;
}

/** The simulate commands and view over an entry's backend; disposing disposes the backend too. */
export class SimulateSession implements vscode.Disposable {
    private readonly view: SimulateView;
    private readonly disposables: vscode.Disposable[];
    private snapshot: LiveSnapshot = { values: new Map(), states: new Map() };

    constructor(
        extensionUri: vscode.Uri,
        private readonly backend: SimulationBackend,
    ) {
        this.view = new SimulateView(extensionUri, (m) => this.fromView(m));
        this.disposables = [
            vscode.commands.registerCommand('maa.simulate.start', () => this.start()),
            vscode.commands.registerCommand('maa.simulate.stop', () => this.command('stop')),
            vscode.commands.registerCommand('maa.simulate.reset', () => this.command('reset')),
        ];
    }

    dispose(): void {
        for (const d of this.disposables) d.dispose();
        this.view.dispose();
        this.backend.dispose();
    }

    private async start(): Promise<void> {
        if (!vscode.workspace.isTrusted) {
            void vscode.window.showWarningMessage('MontiArc: simulations run generated code and are available in trusted workspaces only.');
            return;
        }
        const item = await pickPlatform('Simulate');
        if (!item) return;
        try {
            const { app, base } = await this.backend.target(item);
            await this.view.show(base);
            if (!(await this.view.command({ type: 'start', app, platform: item.platform }))) {
                void vscode.window.showErrorMessage(`MontiArc: the simulate view does not know ${app} with platform ${item.platform}.`);
            }
        } catch (e) {
            this.backend.failed?.();
            void vscode.window.showErrorMessage(`MontiArc: ${e instanceof Error ? e.message : String(e)}`);
        }
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
            case 'reveal':
                revealTrace(message).catch((e: unknown) =>
                    vscode.window.showErrorMessage(
                        `MontiArc: could not reveal ${message.file}:${message.line}: ${e instanceof Error ? e.message : String(e)}`,
                    ),
                );
                break;
            default:
                break;
        }
    }
}
