/**
 * Relays Sprotty action messages between diagram webviews and the one language server.
 *
 * Every webview runs its own Sprotty container whose client id is only unique inside that
 * webview (the diagram names it after its mount, `maa-diagram-1` in each of them), while the
 * language server keeps one diagram server per client id. So the relay gives each client of each
 * webview a server-side id of its own (`<panel>/<client id>`), rewrites the id on the way to the
 * server (`diagram/accept` from the client) and back (`diagram/accept` from the server), and
 * delivers a server message only to the webview whose client it is.
 */
import type { ActionMessage } from 'sprotty-protocol';

/** Delivers an action message into one webview. */
export type Deliver = (message: ActionMessage) => void;

interface Client {
    readonly panel: string;
    readonly localId: string;
}

export class DiagramRelay {
    private readonly panels = new Map<string, Deliver>();
    /** Server-side client id → its webview and the id the webview uses. */
    private readonly clients = new Map<string, Client>();

    /** Adds a webview (`panel`: an id unique among the open webviews). */
    addPanel(panel: string, deliver: Deliver): void {
        if (panel.includes('/')) throw new Error(`a panel id has no "/": ${panel}`);
        this.panels.set(panel, deliver);
    }

    /**
     * Removes a webview; returns the server-side client ids it used, for the server to drop their
     * diagram servers (`diagram/didClose`).
     */
    removePanel(panel: string): string[] {
        this.panels.delete(panel);
        const closed = [...this.clients].filter(([, c]) => c.panel === panel).map(([id]) => id);
        for (const id of closed) this.clients.delete(id);
        return closed;
    }

    /** A webview's message as the server gets it (its client id made unique among the webviews). */
    toServer(panel: string, message: ActionMessage): ActionMessage {
        if (!this.panels.has(panel)) throw new Error(`no diagram webview ${panel}`);
        const serverId = `${panel}/${message.clientId}`;
        this.clients.set(serverId, { panel, localId: message.clientId });
        return { ...message, clientId: serverId };
    }

    /**
     * Delivers a server message to the webview of its client, with the client id that webview
     * knows; returns whether some webview took it (false: a client of a closed webview, or of
     * another front end).
     */
    fromServer(message: ActionMessage): boolean {
        const client = this.clients.get(message.clientId);
        const deliver = client ? this.panels.get(client.panel) : undefined;
        if (!client || !deliver) return false;
        deliver({ ...message, clientId: client.localId });
        return true;
    }

    /** The open webviews. */
    panelIds(): string[] {
        return [...this.panels.keys()];
    }
}
