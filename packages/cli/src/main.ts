import { Command, CommanderError } from 'commander';
import { checkCommand } from './commands/check.js';
import { diagramCommand } from './commands/diagram.js';
import { generateCommand } from './commands/generate.js';
import { generatorsCommand } from './commands/generators.js';
import { lspCommand } from './commands/lsp.js';
import { newCommand } from './commands/new.js';
import { simCommand } from './commands/sim.js';
import { testCommand } from './commands/test.js';
import { CliError, ExitCode } from './errors.js';
import { processIo, type CliIo } from './io.js';
import { cliVersion } from './version.js';

export { runCheck, type CheckOptions, type CheckFormat } from './commands/check.js';
export { runDiagram, type DiagramCommandOptions } from './commands/diagram.js';
export { runGenerate, type GenerateCommandOptions, type GenerateFormat } from './commands/generate.js';
export { runGenerators, type GeneratorsCommandOptions } from './commands/generators.js';
export { runTest, type TestCommandOptions } from './commands/test.js';
export { runNew, listTemplates, type NewCommandOptions, type ProjectTemplate } from './commands/new.js';
export { runLsp, type LspCommandOptions } from './commands/lsp.js';
export { runSim, type SimCommandOptions } from './commands/sim.js';
export { ExitCode, CliError } from './errors.js';
export type { CliIo } from './io.js';
export { CapturedIo } from './io.js';

export function createProgram(io: CliIo, setExitCode: (code: ExitCode) => void): Command {
    const program = new Command('maa-gen')
        .description(
            'MontiArcAutomaton for the web: create a project from a template (new), check models (check), generate code for a ' +
                "platform (generate), list the installed generators (generators), run stream tests (test), draw a component's " +
                'diagram as SVG or PNG (diagram), run the language server for an editor (lsp), run an application in the simulator (sim)',
        )
        .version(cliVersion(), '-V, --version', 'print the version')
        .helpOption('-h, --help', 'show help')
        .helpCommand('help [command]', 'show help for a command')
        .showHelpAfterError('(run "maa-gen --help" for usage)')
        .configureOutput({ writeOut: (s) => io.out(s), writeErr: (s) => io.err(s) })
        .exitOverride();
    program.addCommand(newCommand(io, setExitCode));
    program.addCommand(checkCommand(io, setExitCode));
    program.addCommand(generateCommand(io, setExitCode));
    program.addCommand(generatorsCommand(io, setExitCode));
    program.addCommand(testCommand(io, setExitCode));
    program.addCommand(diagramCommand(io, setExitCode));
    program.addCommand(lspCommand(io, setExitCode));
    program.addCommand(simCommand(io, setExitCode));
    // Subcommands added with addCommand do not inherit these settings.
    for (const sub of program.commands) {
        sub.helpOption('-h, --help', 'show help')
            .showHelpAfterError(`(run "maa-gen ${sub.name()} --help" for usage)`)
            .configureOutput({ writeOut: (s) => io.out(s), writeErr: (s) => io.err(s) })
            .exitOverride();
    }
    return program;
}

/** Runs maa-gen with a full argv (node, script, args...) and returns the exit code. */
export async function main(argv: readonly string[], io: CliIo = processIo()): Promise<ExitCode> {
    let exitCode: ExitCode = ExitCode.ok;
    const program = createProgram(io, (code) => {
        exitCode = code;
    });
    try {
        await program.parseAsync([...argv]);
        return exitCode;
    } catch (e) {
        if (e instanceof CommanderError) {
            // Commander has already printed its message (or the help / version text).
            return e.exitCode === 0 ? ExitCode.ok : ExitCode.usage;
        }
        if (e instanceof CliError) {
            io.err(
                e.message
                    .split('\n')
                    .map((line) => `maa-gen: error: ${line}\n`)
                    .join(''),
            );
            return e.exitCode;
        }
        const debug = Boolean(io.env['MAA_GEN_DEBUG']);
        const message = e instanceof Error ? e.message : String(e);
        io.err(`maa-gen: internal error: ${message}\n`);
        if (debug && e instanceof Error && e.stack) io.err(`${e.stack}\n`);
        else io.err('(this is a bug in maa-gen; run with MAA_GEN_DEBUG=1 for the stack trace)\n');
        return ExitCode.internal;
    }
}

/** Entry point of the `maa-gen` bin: runs, flushes stdout/stderr, then exits with the code. */
export function run(argv: readonly string[]): void {
    void main(argv).then((code) => {
        process.stdout.write('', () => process.stderr.write('', () => process.exit(code)));
    });
}
