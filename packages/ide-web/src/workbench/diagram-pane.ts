/**
 * The diagram pane: the Sprotty diagram (a chunk of its own, mounted once the language client
 * runs) showing the architecture of the active component file, and the way back from a diagram
 * element to its source.
 */
import type { MonacoLanguageClient } from 'monaco-languageclient';
import type { ActionMessage } from 'sprotty-protocol';
import { uriOf, WORKSPACE_URI } from '../api.js';
import type { DiagramHost, DiagramView, Disposable, TextPosition, TextRange } from '../contracts.js';
import { parseTrace } from '@maa/diagram-view/trace';
import { byId } from './dom.js';
import type { EditorArea } from './editors.js';
import { hooks } from './hooks.js';
import { messageOf, notify } from './status.js';

/** The diagram until the real one is mounted (it is loaded as a chunk of its own), or when it failed. */
class NoDiagram implements DiagramView {
    show(): void {
        /* nothing */
    }
    revealPosition(): void {
        /* nothing */
    }
    exportSvg(): Promise<string> {
        return Promise.resolve('<svg xmlns="http://www.w3.org/2000/svg"/>');
    }
    setLiveValues(): void {
        /* nothing */
    }
    setActiveStates(): void {
        /* nothing */
    }
    onSelect(): Disposable {
        return { dispose: () => undefined };
    }
    dispose(): void {
        /* nothing */
    }
}

/** The workspace file and range a langium-sprotty trace points to (see diagram/trace.ts for the format). */
function traceTarget(trace: string): { path: string; range: TextRange } | undefined {
    const parsed = parseTrace(trace);
    // parseTrace decodes the URI already: take the path as it is, without a second decoding.
    if (!parsed?.uri.startsWith(WORKSPACE_URI)) return undefined;
    return { path: parsed.uri.slice(WORKSPACE_URI.length), range: parsed.range };
}

async function mountDiagramView(client: MonacoLanguageClient, area: EditorArea): Promise<DiagramView> {
    const container = byId('diagram-container');
    const { mountDiagram } = await import('@maa/diagram-view');
    const host: DiagramHost = {
        sendDiagramMessage: (message: ActionMessage) => void client.sendNotification('diagram/accept', message),
        onDiagramMessage: (handler) => {
            const disposable = client.onNotification('diagram/accept', (message: ActionMessage) => {
                hooks.diagramUpdates++;
                handler(message);
            });
            return { dispose: () => disposable.dispose() };
        },
        revealTrace: (trace) => {
            const target = traceTarget(trace);
            if (target) void area.open(target.path, target.range, false);
        },
    };
    return mountDiagram(container, host);
}

export class DiagramPane {
    /** The diagram view: a NoDiagram until mounted, and when mounting failed. */
    view: DiagramView = new NoDiagram();
    private shown: string | undefined;

    /** Shows the architecture of the active component file (the diagram's own switch shows its automaton). */
    showComponent(path: string | undefined, force = false): void {
        if (!path?.endsWith('.arc')) return;
        if (path === this.shown && !force) return;
        this.shown = path;
        this.view.show({ uri: uriOf(path), diagramType: 'maa-cc' });
    }

    /** Selects what is at a position of a component file (other files have no diagram). */
    revealPosition(path: string, position: TextPosition): void {
        if (path.endsWith('.arc')) this.view.revealPosition(uriOf(path), position);
    }

    /** Mounts the real diagram; a selection in it opens its source. A failure is reported and leaves the NoDiagram. */
    async mount(client: MonacoLanguageClient, area: EditorArea): Promise<void> {
        try {
            this.view = await mountDiagramView(client, area);
            this.view.onSelect((traces) => {
                const target = traces.map(traceTarget).find((t) => t !== undefined);
                if (target) void area.open(target.path, target.range, false);
            });
        } catch (error) {
            notify('error', `The diagram failed: ${messageOf(error)}`);
        }
    }
}
