/** The process streams and location a command talks to; injectable so commands stay testable. */
export interface CliIo {
    readonly cwd: string;
    readonly env: NodeJS.ProcessEnv;
    readonly stdoutIsTTY: boolean;
    readonly stderrIsTTY: boolean;
    /** Width of the terminal behind stderr, when it is one. */
    readonly stderrColumns?: number;
    out(text: string): void;
    err(text: string): void;
}

export function processIo(): CliIo {
    return {
        cwd: process.cwd(),
        env: process.env,
        stdoutIsTTY: process.stdout.isTTY === true,
        stderrIsTTY: process.stderr.isTTY === true,
        stderrColumns: process.stderr.columns,
        out: (text) => void process.stdout.write(text),
        err: (text) => void process.stderr.write(text),
    };
}

/**
 * What a command writes, kept (pipes, not terminals): for running `main()` in-process with the
 * output of a `maa-gen` process, as the CLI's tests and the Python suites' warm maa-gen do.
 */
export class CapturedIo implements CliIo {
    readonly stdoutIsTTY = false;
    readonly stderrIsTTY = false;
    stdout = '';
    stderr = '';

    constructor(
        readonly cwd: string,
        readonly env: NodeJS.ProcessEnv,
    ) {}

    // Own properties, not methods: commands pass copies of their io on (`{ ...io, ... }`).
    readonly out = (text: string): void => {
        this.stdout += text;
    };

    readonly err = (text: string): void => {
        this.stderr += text;
    };
}
