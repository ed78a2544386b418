/** Exit codes of every maa-gen command. */
export const ExitCode = {
    /** The command succeeded; `check` found no errors (warnings are fine). */
    ok: 0,
    /** `check` found at least one error-severity diagnostic. */
    errors: 1,
    /** Wrong usage or an I/O problem (missing path, unreadable file, an output that cannot be written). */
    usage: 2,
    /** An unexpected failure inside maa-gen (a bug). */
    internal: 3,
} as const;
export type ExitCode = (typeof ExitCode)[keyof typeof ExitCode];

/**
 * A problem caused by the command line or the file system, not by a bug: its message is meant
 * for the user and is printed without a stack trace.
 */
export class CliError extends Error {
    constructor(
        message: string,
        readonly exitCode: ExitCode = ExitCode.usage,
    ) {
        super(message);
        this.name = 'CliError';
    }
}
