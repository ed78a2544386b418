/**
 * The diagram panel: a webview beside the editor running the shared diagram (webview/main.ts),
 * connected to the language server through the relay, the editor (selection both ways) and the
 * file system (Export SVG). One panel at a time; Open Diagram reveals it again.
 */
import type { DiagramTarget, TextPosition } from '@maa/diagram-view/contracts';
import * as vscode from 'vscode';
import { newNonce, webviewHtml } from './html.js';
import { diagramIcon } from './icons.js';
import { type FromWebview, packServerAction, parseFromWebview, type ToWebview } from './protocol.js';
import type { DiagramRelay } from './relay.js';
import { selectionSource } from './selection.js';

/** What the panel needs of the language client (vscode-languageclient's `LanguageClient` has it). */
export interface DiagramChannel {
    sendNotification(method: string, params: unknown): Promise<void>;
}

let panelCounter = 0;

export class DiagramPanel implements vscode.Disposable {
    readonly id = `maa-webview-${++panelCounter}`;
    private readonly panel: vscode.WebviewPanel;
    private readonly subscriptions: vscode.Disposable[] = [];
    /** Messages posted before the webview's script listens. */
    private readonly pending: ToWebview[] = [];
    private ready = false;
    private target: DiagramTarget | undefined;
    private disposed = false;

    constructor(
        extensionUri: vscode.Uri,
        private readonly relay: DiagramRelay,
        private readonly channel: DiagramChannel,
        private readonly onDisposed: () => void,
    ) {
        const webviewRoot = vscode.Uri.joinPath(extensionUri, 'out', 'webview');
        this.panel = vscode.window.createWebviewPanel(
            'maa.diagram',
            'MontiArc Diagram',
            { viewColumn: vscode.ViewColumn.Beside, preserveFocus: true },
            { enableScripts: true, retainContextWhenHidden: true, localResourceRoots: [webviewRoot] },
        );
        const icon = diagramIcon().icon;
        this.panel.iconPath = { light: vscode.Uri.joinPath(extensionUri, icon.light), dark: vscode.Uri.joinPath(extensionUri, icon.dark) };
        const webview = this.panel.webview;
        webview.html = webviewHtml({
            cspSource: webview.cspSource,
            nonce: newNonce(),
            scriptUri: webview.asWebviewUri(vscode.Uri.joinPath(webviewRoot, 'diagram.js')).toString(),
            styleUri: webview.asWebviewUri(vscode.Uri.joinPath(webviewRoot, 'diagram.css')).toString(),
        });
        relay.addPanel(this.id, (message) => this.post(packServerAction(message)));
        this.subscriptions.push(
            webview.onDidReceiveMessage((data: unknown) => {
                const message = parseFromWebview(data);
                if (message) void this.received(message);
            }),
            this.panel.onDidDispose(() => this.dispose()),
        );
    }

    /** The shown target. */
    current(): DiagramTarget | undefined {
        return this.target;
    }

    /** Shows a diagram and brings the panel forward (without taking the focus from the editor). */
    show(target: DiagramTarget): void {
        this.target = target;
        this.post({ type: 'show', target });
        if (!this.panel.visible) this.panel.reveal(undefined, true);
    }

    revealPosition(uri: string, position: TextPosition): void {
        this.post({ type: 'revealPosition', uri, position });
    }

    post(message: ToWebview): void {
        if (this.disposed) return;
        if (!this.ready) {
            this.pending.push(message);
            return;
        }
        void this.panel.webview.postMessage(message);
    }

    dispose(): void {
        if (this.disposed) return;
        this.disposed = true;
        for (const clientId of this.relay.removePanel(this.id)) void this.channel.sendNotification('diagram/didClose', clientId);
        for (const s of this.subscriptions.splice(0)) s.dispose();
        this.panel.dispose();
        this.onDisposed();
    }

    private async received(message: FromWebview): Promise<void> {
        switch (message.type) {
            case 'ready':
                this.ready = true;
                for (const m of this.pending.splice(0)) void this.panel.webview.postMessage(m);
                return;
            case 'action':
                await this.channel.sendNotification('diagram/accept', this.relay.toServer(this.id, message.message));
                return;
            case 'select':
                await revealSource(message.traces);
                return;
            case 'saveSvg':
                await saveSvg(message.svg, message.fileName, this.target);
                return;
        }
    }
}

/** Opens the source of the first selected element in its editor and selects it (the diagram keeps the focus). */
async function revealSource(traces: readonly string[]): Promise<void> {
    const source = selectionSource(traces);
    if (!source) return;
    const uri = vscode.Uri.parse(source.uri);
    const open = vscode.window.visibleTextEditors.find((e) => e.document.uri.toString() === uri.toString());
    const { start, end } = source.range;
    const range = new vscode.Range(start.line, start.character, end.line, end.character);
    const editor = await vscode.window.showTextDocument(uri, {
        viewColumn: open?.viewColumn ?? vscode.ViewColumn.One,
        preserveFocus: true,
        preview: true,
    });
    editor.selection = new vscode.Selection(range.start, range.end);
    editor.revealRange(range, vscode.TextEditorRevealType.InCenterIfOutsideViewport);
}

/** Export SVG: a save dialog next to the model file, then the file. */
async function saveSvg(svg: string, fileName: string, target: DiagramTarget | undefined): Promise<void> {
    const folder = target ? vscode.Uri.joinPath(vscode.Uri.parse(target.uri), '..') : vscode.workspace.workspaceFolders?.[0]?.uri;
    const defaultUri = folder ? vscode.Uri.joinPath(folder, fileName) : undefined;
    const chosen = await vscode.window.showSaveDialog({ defaultUri, filters: { SVG: ['svg'] }, title: 'Export the diagram as SVG' });
    if (!chosen) return;
    await vscode.workspace.fs.writeFile(chosen, new TextEncoder().encode(svg));
    void vscode.window.showInformationMessage(`MontiArc: diagram saved to ${vscode.workspace.asRelativePath(chosen)}`);
}
