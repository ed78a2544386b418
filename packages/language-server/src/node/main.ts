#!/usr/bin/env node
/**
 * `maa-language-server`: the language server of the family for editors that start it as a
 * process (VS Code, other LSP clients). Transport by the usual flags of vscode-languageserver:
 * `--stdio`, `--node-ipc` or `--socket=<port>`. Serves diagrams too (`diagram/accept`, docs/ide.md).
 */
import { readFileSync } from 'node:fs';
import { startLanguageServer } from 'langium/lsp';
import { NodeFileSystem } from 'langium/node';
import { createConnection, ProposedFeatures } from 'vscode-languageserver/node.js';
import { addMaaDiagramServer } from '../diagram/index.js';
import { createMaaLspServices, MAA_SERVICE_REQUIREMENTS } from '../family.js';

const USAGE = `Usage: maa-language-server (--stdio | --node-ipc | --socket=<port>)

The MontiArcAutomaton language server (.arc, .cd and every language of the family).
Options:
  --stdio          talk LSP over stdin/stdout
  --node-ipc       talk LSP over Node's IPC channel (when started with fork())
  --socket=<port>  talk LSP over a socket on localhost
  --version        print the version
  --help           print this help`;

/**
 * Keeps the server alive when a feature throws outside a request (a timer, an event handler, a
 * promise nobody awaits): the failure is logged (console goes to the client's log once the
 * connection exists) and the server goes on, instead of Node ending the process and the editor
 * losing the language support. Requests answer or refuse on their own (createMaaLspServices).
 */
function survive(): void {
    let reporting = false;
    const report =
        (what: string) =>
        (e: unknown): void => {
            // Never recurse: logging itself may fail (a closed pipe to the client).
            if (reporting) return;
            reporting = true;
            try {
                console.error(
                    `maa-language-server: ${what} (the server goes on): ${e instanceof Error ? (e.stack ?? e.message) : String(e)}`,
                );
            } catch {
                // nowhere left to report to
            } finally {
                reporting = false;
            }
        };
    process.on('uncaughtException', report('uncaught exception'));
    process.on('unhandledRejection', report('unhandled rejection'));
}

/** Starts the server on the transport the command line names. */
export function startNodeLanguageServer(): void {
    survive();
    const connection = createConnection(ProposedFeatures.all);
    const family = createMaaLspServices({ connection, ...NodeFileSystem });
    addMaaDiagramServer(family);
    // The outline waits for linked documents (see MAA_SERVICE_REQUIREMENTS).
    startLanguageServer(family.shared, MAA_SERVICE_REQUIREMENTS);
}

function main(args: readonly string[]): void {
    if (args.includes('--help') || args.includes('-h')) {
        process.stdout.write(`${USAGE}\n`);
        return;
    }
    if (args.includes('--version')) {
        const pkg = JSON.parse(readFileSync(new URL('../../package.json', import.meta.url), 'utf8')) as { version: string };
        process.stdout.write(`${pkg.version}\n`);
        return;
    }
    if (!args.some((a) => a === '--stdio' || a === '--node-ipc' || a.startsWith('--socket=') || a.startsWith('--pipe='))) {
        process.stderr.write(`maa-language-server: no transport given\n\n${USAGE}\n`);
        process.exitCode = 2;
        return;
    }
    startNodeLanguageServer();
}

main(process.argv.slice(2));
