/**
 * The diagram webview's script (bundled by bin/build.mjs for the browser into out/webview/):
 * mounts the shared diagram (@maa/diagram-view) and connects it to the extension through
 * `postMessage` (protocol.ts). The extension relays the action messages to the language
 * server's diagram server and back (relay.ts); selections go to the editor, Export SVG to a save
 * dialog, and the extension pushes what to show, the cursor, live values and active states.
 */
import { type DiagramHost, type Disposable, mountDiagram } from '@maa/diagram-view';
import type { ActionMessage } from 'sprotty-protocol';
import { type FromWebview, type ToWebview, unpackServerAction } from '../protocol.js';
import './webview.css';

interface VsCodeApi {
    postMessage(message: FromWebview): void;
}
declare function acquireVsCodeApi(): VsCodeApi;

const vscode = acquireVsCodeApi();
const actionHandlers = new Set<(message: ActionMessage) => void>();

const host: DiagramHost = {
    sendDiagramMessage: (message) => vscode.postMessage({ type: 'action', message }),
    onDiagramMessage: (handler): Disposable => {
        actionHandlers.add(handler);
        return { dispose: () => actionHandlers.delete(handler) };
    },
    revealTrace: (trace) => vscode.postMessage({ type: 'select', traces: [trace] }),
    saveSvg: (svg, fileName) => vscode.postMessage({ type: 'saveSvg', svg, fileName }),
};

const root = document.getElementById('maa-diagram-root');
if (!root) throw new Error('the diagram webview has no #maa-diagram-root');
const view = mountDiagram(root, host);
view.onSelect((traces) => vscode.postMessage({ type: 'select', traces }));

/** The command's Export SVG: the same file name the tool bar's button suggests. */
async function exportSvg(): Promise<void> {
    try {
        vscode.postMessage({ type: 'saveSvg', svg: await view.exportSvg(), fileName: view.exportFileName() });
    } catch (e) {
        console.warn('diagram export:', e);
    }
}

window.addEventListener('message', (event: MessageEvent<ToWebview>) => {
    const message = event.data;
    switch (message.type) {
        case 'show':
            view.show(message.target);
            break;
        case 'action': {
            const action = unpackServerAction(message);
            for (const handler of [...actionHandlers]) handler(action);
            break;
        }
        case 'revealPosition':
            view.revealPosition(message.uri, message.position);
            break;
        case 'liveValues':
            view.setLiveValues(new Map(message.values));
            break;
        case 'activeStates':
            view.setActiveStates(new Map(message.states));
            break;
        case 'exportSvg':
            void exportSvg();
            break;
        case 'highlight':
            view.highlight(message.highlight);
            break;
    }
});
vscode.postMessage({ type: 'ready' });
