/**
 * The simulate view: a webview panel beside the editor with @maa/simulate-view's panel
 * (`out/webview/simulate.js`, the same code as the browser IDE's simulate panel), reaching the
 * backend below the base it is shown with (desktop: the relay, web: the page's origin). One
 * panel; commands are messages to it (host-messages).
 */
import { type FromWebview, type PanelCommand, parseFromWebview, type ToWebview } from '@maa/simulate-view/host-messages';
import * as vscode from 'vscode';
import { simulateHtml } from './webview-html.js';

export class SimulateView implements vscode.Disposable {
    private panel: vscode.WebviewPanel | undefined;
    private base: string | undefined;
    private ready: Promise<void> | undefined;
    private markReady: (() => void) | undefined;
    private readonly waiting = new Map<PanelCommand, Array<(ok: boolean) => void>>();

    constructor(
        private readonly extensionUri: vscode.Uri,
        private readonly onMessage: (message: FromWebview) => void,
    ) {}

    get open(): boolean {
        return this.panel !== undefined;
    }

    /** Shows the view against the backend below `base` (desktop: an external URI of the relay; web: the page's backend). */
    async show(base: string): Promise<void> {
        if (this.panel && this.base === base) {
            this.panel.reveal(undefined, true);
            await this.ready;
            return;
        }
        const root = vscode.Uri.joinPath(this.extensionUri, 'out', 'webview');
        const panel =
            this.panel ??
            vscode.window.createWebviewPanel(
                'maa.simulate',
                'MontiArc Simulation',
                { viewColumn: vscode.ViewColumn.Beside, preserveFocus: true },
                { enableScripts: true, retainContextWhenHidden: true, localResourceRoots: [root] },
            );
        if (!this.panel) {
            this.panel = panel;
            panel.onDidDispose(() => this.closed());
            panel.webview.onDidReceiveMessage((raw: unknown) => this.receive(raw));
        }
        this.base = base;
        this.ready = new Promise<void>((resolve) => {
            this.markReady = resolve;
        });
        panel.webview.html = simulateHtml({
            cspSource: panel.webview.cspSource,
            script: panel.webview.asWebviewUri(vscode.Uri.joinPath(root, 'simulate.js')).toString(),
            style: panel.webview.asWebviewUri(vscode.Uri.joinPath(root, 'simulate.css')).toString(),
            relayOrigin: new URL(base).origin,
        });
        await this.ready;
        await this.panel?.webview.postMessage({ type: 'init', backendBase: base } satisfies ToWebview);
    }

    /** Sends a command; resolves with the panel's answer (false: no panel, or the panel refused). */
    async command(message: Exclude<ToWebview, { type: 'init' }>): Promise<boolean> {
        if (!this.panel) return false;
        await this.ready;
        const answer = new Promise<boolean>((resolve) => {
            const list = this.waiting.get(message.type) ?? [];
            list.push(resolve);
            this.waiting.set(message.type, list);
        });
        await this.panel.webview.postMessage(message);
        return answer;
    }

    dispose(): void {
        this.panel?.dispose();
    }

    private receive(raw: unknown): void {
        const message = parseFromWebview(raw);
        if (!message) return;
        if (message.type === 'ready') this.markReady?.();
        else if (message.type === 'done') this.waiting.get(message.command)?.shift()?.(message.ok);
        this.onMessage(message);
    }

    private closed(): void {
        this.panel = undefined;
        this.base = undefined;
        this.markReady?.();
        for (const list of this.waiting.values()) for (const resolve of list) resolve(false);
        this.waiting.clear();
    }
}
