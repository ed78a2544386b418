/** The status line: the message item and the language server's state. */
import { byId } from './dom.js';

const statusMessage = byId('status-message');
const statusServer = byId('status-server');

export function notify(severity: 'info' | 'warning' | 'error', message: string): void {
    statusMessage.textContent = message;
    statusMessage.className = `status-item status-${severity}`;
    if (severity !== 'info') console.warn(`[maa-ide] ${message}`);
}

export function setServerStatus(text: string, state: 'starting' | 'ready' | 'error'): void {
    statusServer.textContent = text;
    statusServer.dataset.state = state;
}

/** An error's message for the status line. */
export function messageOf(error: unknown): string {
    return error instanceof Error ? error.message : String(error);
}
