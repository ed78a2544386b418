import { spawn, type ChildProcess } from 'node:child_process';
import { existsSync, readFileSync } from 'node:fs';
import { createRequire } from 'node:module';
import { createServer, type AddressInfo, type Server, type Socket } from 'node:net';
import path from 'node:path';
import { Command } from 'commander';
import { CliError, ExitCode } from '../errors.js';
import type { CliIo } from '../io.js';

export interface LspCommandOptions {
    stdio?: boolean;
    socket?: string;
}

/**
 * The node entry of the family's language server: the `maa-language-server` bin of
 * @maa/language-server (dist/node/main.js), the very module editors start directly.
 */
export function languageServerMain(): string {
    const require = createRequire(import.meta.url);
    const pkgFile = require.resolve('@maa/language-server/package.json');
    const pkg = JSON.parse(readFileSync(pkgFile, 'utf8')) as { bin?: Record<string, string> };
    const bin = pkg.bin?.['maa-language-server'];
    const main = bin === undefined ? undefined : path.resolve(path.dirname(pkgFile), bin);
    if (main === undefined || !existsSync(main)) {
        throw new CliError(`the language server is missing (${main ?? pkgFile}): rebuild @maa/language-server`, ExitCode.internal);
    }
    return main;
}

/** A language server process speaking LSP on its stdin/stdout. */
function startServer(main: string, stdio: 'inherit' | 'pipe'): ChildProcess {
    return spawn(process.execPath, [main, '--stdio'], { stdio: [stdio, stdio, 'inherit'] });
}

/** Passes Ctrl+C and termination on to `stop` while the server runs; returns the undo. */
function onStopSignals(stop: () => void): () => void {
    const signals = ['SIGINT', 'SIGTERM'] as const;
    for (const s of signals) process.on(s, stop);
    return () => {
        for (const s of signals) process.off(s, stop);
    };
}

/**
 * `--stdio`: the server process shares maa-gen's stdin, stdout and stderr, so the editor talks to
 * it directly. It ends when the editor closes the connection: exit 0 after LSP shutdown and
 * exit, 1 when the connection ended without them.
 */
function serveStdio(main: string): Promise<ExitCode> {
    return new Promise((resolve, reject) => {
        const child = startServer(main, 'inherit');
        const undo = onStopSignals(() => child.kill('SIGTERM'));
        child.on('error', (e) => {
            undo();
            reject(new CliError(`could not start the language server: ${e.message}`, ExitCode.internal));
        });
        child.on('exit', (code) => {
            undo();
            resolve(code === 0 ? ExitCode.ok : ExitCode.errors);
        });
    });
}

/** One language server per client connection, ended when either side ends. */
function serveConnection(main: string, socket: Socket, children: Set<ChildProcess>): void {
    const child = startServer(main, 'pipe');
    children.add(child);
    child.stdin?.on('error', () => undefined); // the server has gone: the socket is closed below
    socket.on('error', () => child.stdin?.end());
    socket.pipe(child.stdin!);
    child.stdout?.pipe(socket);
    child.on('exit', () => {
        children.delete(child);
        socket.end();
    });
}

export function parsePort(text: string): number {
    const port = /^\d+$/.test(text) ? Number(text) : Number.NaN;
    if (!Number.isInteger(port) || port < 0 || port > 65535) throw new CliError(`not a port number (0-65535): ${text}`);
    return port;
}

/**
 * `--socket PORT`: listens on 127.0.0.1 only (never another interface: the server reads and
 * writes the files of any folder a client names), one language server per connection, until
 * Ctrl+C or SIGTERM. PORT 0 picks a free port; the port is printed on stderr either way.
 */
function serveSocket(main: string, port: number, io: CliIo): Promise<ExitCode> {
    return new Promise((resolve, reject) => {
        const children = new Set<ChildProcess>();
        const server: Server = createServer((socket) => serveConnection(main, socket, children));
        const undo = onStopSignals(() => {
            undo();
            for (const child of children) child.kill('SIGTERM');
            server.close(() => resolve(ExitCode.ok));
        });
        server.on('error', (e: NodeJS.ErrnoException) => {
            undo();
            reject(new CliError(`cannot listen on 127.0.0.1:${port} (${e.code ?? e.message})`));
        });
        server.listen(port, '127.0.0.1', () => {
            const bound = (server.address() as AddressInfo).port;
            io.err(`maa-gen lsp: listening on 127.0.0.1:${bound} (a language server per connection; Ctrl+C stops)\n`);
        });
    });
}

/** `maa-gen lsp [--stdio | --socket PORT]`: runs the family's language server for an editor. */
export async function runLsp(options: LspCommandOptions, io: CliIo): Promise<ExitCode> {
    if (options.stdio && options.socket !== undefined) throw new CliError('--stdio and --socket exclude each other');
    const port = options.socket === undefined ? undefined : parsePort(options.socket);
    const main = languageServerMain();
    return port === undefined ? serveStdio(main) : serveSocket(main, port, io);
}

export function lspCommand(io: CliIo, setExitCode: (code: ExitCode) => void): Command {
    return new Command('lsp')
        .description('run the language server for an editor (LSP over stdio, or a socket on 127.0.0.1)')
        .option('--stdio', 'talk LSP over stdin and stdout (the default)')
        .option('--socket <port>', 'listen on 127.0.0.1:PORT; each connection gets its own server (0: a free port, printed on stderr)')
        .addHelpText(
            'after',
            `
The server is the family's language server (@maa/language-server, the maa-language-server
bin): diagnostics, completion, hover, definition, formatting, code actions and diagrams for
.arc, .cd, .ra and .arcapp files, in the workspace folders the editor names.

Exit codes:
  0  the editor shut the server down (stdio), or Ctrl+C / SIGTERM (socket)
  1  the connection ended without an LSP shutdown (stdio)
  2  usage problem (a bad port, a port in use)
  3  internal error

Examples:
  maa-gen lsp --stdio            # what an editor's LSP client starts
  maa-gen lsp --socket 5007      # for clients that connect to a TCP port`,
        )
        .action(async (options: LspCommandOptions) => {
            setExitCode(await runLsp(options, io));
        });
}
