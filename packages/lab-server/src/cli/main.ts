// The `maa-lab` command (docs/lab.md): serve, users, course, exercise (src/exercises), and the
// commands other parts of the lab register (registerLabCommand).
import { Command, CommanderError } from 'commander';
import { exerciseCommand } from '../exercises/command.js';
import { gradeCommand } from '../grading/command.js';
import { courseCommand } from './course.js';
import { type LabIo, processLabIo } from './io.js';
import { serveCommand } from './serve.js';
import { usersCommand } from './users.js';

export { LabCliError, type LabIo } from './io.js';

/** A command another part of the lab adds to `maa-lab` (e.g. `exercise`); it gets the same io. */
export type LabCommandFactory = (io: LabIo) => Command;

const registered: LabCommandFactory[] = [];

/** Adds a command to every program createLabProgram makes from now on. */
export function registerLabCommand(factory: LabCommandFactory): void {
    registered.push(factory);
}

export interface ProgramHooks {
    /** serve: called once the server listens, with a function that stops it (else SIGINT/SIGTERM stop it) */
    onServing?: (stop: () => Promise<void>, url: string) => void;
}

export function createLabProgram(io: LabIo, hooks: ProgramHooks = {}): Command {
    const program = new Command('maa-lab')
        .description('the classroom lab server of MontiArcAutomaton for the web: serve a lab, manage users, courses and exercises')
        .helpOption('-h, --help', 'show help')
        .helpCommand('help [command]', 'show help for a command')
        .showHelpAfterError('(run "maa-lab --help" for usage)')
        .configureOutput({ writeOut: (s) => io.out(s), writeErr: (s) => io.err(s) })
        .exitOverride();
    program.addCommand(serveCommand(io, hooks.onServing));
    program.addCommand(usersCommand(io));
    program.addCommand(courseCommand(io));
    program.addCommand(exerciseCommand(io));
    program.addCommand(gradeCommand(io));
    for (const factory of registered) program.addCommand(factory(io));
    const configure = (command: Command, name: string): void => {
        for (const sub of command.commands) {
            const full = name ? `${name} ${sub.name()}` : sub.name();
            sub.helpOption('-h, --help', 'show help')
                .showHelpAfterError(`(run "maa-lab ${full} --help" for usage)`)
                .configureOutput({ writeOut: (s) => io.out(s), writeErr: (s) => io.err(s) })
                .exitOverride();
            configure(sub, full);
        }
    };
    configure(program, '');
    return program;
}

/** Runs maa-lab with a full argv (node, script, args...); returns the exit code (0 ok, 1 error, 2 usage). */
export async function runLab(argv: readonly string[], io: LabIo = processLabIo(), hooks: ProgramHooks = {}): Promise<number> {
    const program = createLabProgram(io, hooks);
    try {
        await program.parseAsync([...argv]);
        return 0;
    } catch (e) {
        if (e instanceof CommanderError) return e.exitCode === 0 ? 0 : 2;
        // A LabCliError, an exercise's ExerciseError (one problem a line), or a failure of the store.
        const message = e instanceof Error ? e.message : String(e);
        io.err(
            message
                .split('\n')
                .map((line) => `maa-lab: error: ${line}\n`)
                .join(''),
        );
        return 1;
    }
}
