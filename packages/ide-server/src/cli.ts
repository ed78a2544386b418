import path from 'node:path';
import { Command, CommanderError, InvalidArgumentError } from 'commander';
import { tokenProblem } from './access.js';
import { defaults, startIdeServer } from './server.js';

function parsePort(value: string): number {
    const port = Number(value);
    if (!Number.isInteger(port) || port < 0 || port > 65535) throw new InvalidArgumentError('a TCP port from 0 (any free port) to 65535');
    return port;
}

function parseSeconds(value: string): number {
    const seconds = Number(value);
    if (!Number.isFinite(seconds) || seconds <= 0) throw new InvalidArgumentError('a positive number of seconds');
    return seconds;
}

function parseToken(value: string): string {
    const problem = tokenProblem(value);
    if (problem) throw new InvalidArgumentError(problem);
    return value;
}

interface CliOptions {
    workspace: string;
    port: number;
    host: string;
    appDir: string;
    maaSim: string;
    ros2Venv: string;
    token?: string;
    sessionIdle: number;
}

export function createProgram(): Command {
    return new Command('maa-ide')
        .description('the IDE backend: serves the browser IDE, the workspace, code generation and simulation sessions on one origin')
        .option('-w, --workspace <dir>', 'the folder to edit', process.cwd())
        .option('-p, --port <n>', 'HTTP port (0 = any free port)', parsePort, defaults.port)
        .option('--host <address>', 'address to listen on', defaults.host)
        .option('--app-dir <dir>', 'the built web app', defaults.appDir)
        .option('--maa-sim <path>', "the simulator's maa-sim executable (lockstep sessions)", defaults.maaSim)
        .option(
            '--ros2-venv <dir>',
            'the Python venv of ROS 2 sessions (rclpy, rosidl, maa-sim; the default one is set up when missing)',
            defaults.ros2Venv,
        )
        .option('--token <t>', 'the secret every request must carry (default: $MAA_IDE_TOKEN, else a new random one per start)', parseToken)
        .option(
            '--session-idle <seconds>',
            'a simulation ends when no client was connected for this long',
            parseSeconds,
            defaults.sessionIdleSeconds,
        )
        .helpOption('-h, --help', 'show help')
        .addHelpText(
            'after',
            `
Access (docs/ide.md): open the URL maa-ide prints (http://127.0.0.1:<port>/?token=...); the
browser keeps the token in the cookie maa-ide-token-<port>. Scripts send "Authorization: Bearer
<token>". Only requests to 127.0.0.1, localhost, [::1] or --host (with the served port) are
answered, and only from this origin (a foreign Origin header gets 403).

API (docs/ide.md): /api/files, /api/file, /api/apps, /api/generate, /api/generated/{file,trace},
/api/sim/{start,stop,status}; the simulator's rosbridge at /sim/rosbridge and viser at /sim/viser/.
Generated code goes to <workspace>/../.maa-ide-out/. ROS 2 sessions run in --ros2-venv, where the
generated interface package gets built and installed first. A simulation ends when its last
client (a rosbridge or viser WebSocket; any /api/sim request counts as a sign of life) has been
gone for --session-idle seconds, and when maa-ide exits (Ctrl-C), with every process it started.
Hidden files and folders (.git, ...) cannot be written or deleted through the API.

Examples:
  maa-ide --workspace .maa-workspace
  maa-ide --workspace ~/models --port 0      (prints the port it got)
  MAA_IDE_TOKEN=$(openssl rand -hex 32) maa-ide --workspace .maa-workspace
  curl -H "Authorization: Bearer $MAA_IDE_TOKEN" http://127.0.0.1:3000/api/files`,
        );
}

/** Entry point of the `maa-ide` bin. */
export function run(argv: readonly string[]): void {
    const program = createProgram().exitOverride();
    try {
        program.parse([...argv]);
    } catch (e) {
        // Commander printed the message (or the help); a usage error exits 2 like a failed start.
        process.exit(e instanceof CommanderError && e.exitCode === 0 ? 0 : 2);
    }
    const options = program.opts<CliOptions>();
    const workspace = path.resolve(options.workspace);
    const fromEnv = process.env['MAA_IDE_TOKEN'];
    // Nothing maa-ide starts (setup scripts, the simulator, the user's components) needs it.
    delete process.env['MAA_IDE_TOKEN'];
    let token = options.token;
    if (token === undefined && fromEnv !== undefined && fromEnv !== '') {
        const problem = tokenProblem(fromEnv);
        if (problem) {
            console.error(`maa-ide: error: MAA_IDE_TOKEN: ${problem}`);
            process.exit(2);
        }
        token = fromEnv;
    }
    startIdeServer({
        workspace,
        port: options.port,
        host: options.host,
        appDir: options.appDir,
        maaSim: options.maaSim,
        ros2Venv: options.ros2Venv,
        token,
        sessionIdleSeconds: options.sessionIdle,
    }).then(
        (server) => {
            console.log(`maa-ide: serving ${workspace} at ${server.loginUrl}`);
            let stopping = false;
            const stop = (signal: NodeJS.Signals): void => {
                if (stopping) {
                    // A second Ctrl-C while the simulator shuts down: do not wait any longer.
                    console.error(`maa-ide: ${signal} again, exiting at once`);
                    process.exit(130);
                }
                stopping = true;
                console.log(`maa-ide: ${signal}, shutting down`);
                server.close().then(
                    () => process.exit(0),
                    (e: unknown) => {
                        console.error(`maa-ide: error while shutting down: ${(e as Error).message}`);
                        process.exit(1);
                    },
                );
            };
            process.on('SIGINT', stop);
            process.on('SIGTERM', stop);
        },
        (e: unknown) => {
            const err = e as NodeJS.ErrnoException;
            const message = err.code === 'EADDRINUSE' ? `port ${options.port} on ${options.host} is in use (try --port 0)` : err.message;
            console.error(`maa-ide: error: ${message}`);
            process.exit(2);
        },
    );
}
