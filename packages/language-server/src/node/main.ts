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

/** Starts the server on the transport the command line names. */
export function startNodeLanguageServer(): void {
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
