/**
 * The Web Worker entry of the family's language server (`@maa/language-server/browser`): starts
 * it on the worker's own message port. The IDE builds its worker from this module; options such
 * as the backend's base URL come with the client's initialize request (see ./server.ts).
 */
import { startBrowserLanguageServer, type ServerPort } from './server.js';

/** The worker's global scope (typed loosely: this package compiles without the DOM library). */
declare const self: ServerPort;

/** The worker's global scope as far as errors are concerned (typed loosely without the DOM library). */
interface ErrorEventTarget {
    addEventListener(
        type: 'error' | 'unhandledrejection',
        listener: (event: { preventDefault(): void; error?: unknown; reason?: unknown }) => void,
    ): void;
}

// A feature that throws outside a request (an unawaited promise, an event handler) is logged and
// the worker goes on serving; requests answer or refuse on their own (createMaaLspServices).
const scope = globalThis as unknown as Partial<ErrorEventTarget>;
scope.addEventListener?.('error', (event) => {
    console.error('language server: uncaught exception (the server goes on):', event.error);
    event.preventDefault();
});
scope.addEventListener?.('unhandledrejection', (event) => {
    console.error('language server: unhandled rejection (the server goes on):', event.reason);
    event.preventDefault();
});

startBrowserLanguageServer(self);
