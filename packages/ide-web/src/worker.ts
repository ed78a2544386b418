// The language server Web Worker: the family's language server and diagram server, started on
// this worker's message port by the module's import.
import '@maa/language-server/browser';
