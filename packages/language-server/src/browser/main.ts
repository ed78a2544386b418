/**
 * The Web Worker entry of the family's language server (`@maa/language-server/browser`): starts
 * it on the worker's own message port. The IDE builds its worker from this module; options such
 * as the backend's base URL come with the client's initialize request (see ./server.ts).
 */
import { startBrowserLanguageServer, type ServerPort } from './server.js';

/** The worker's global scope (typed loosely: this package compiles without the DOM library). */
declare const self: ServerPort;

startBrowserLanguageServer(self);
