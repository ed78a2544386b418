import path from 'node:path';
import { Command, InvalidArgumentError } from 'commander';
import { defaults, startIdeServer } from './server.js';

function parsePort(value: string): number {
  const port = Number(value);
  if (!Number.isInteger(port) || port < 0 || port > 65535) throw new InvalidArgumentError('a TCP port from 0 (any free port) to 65535');
  return port;
}

interface CliOptions {
  workspace: string;
  port: number;
  host: string;
  appDir: string;
  maaSim: string;
  ros2Venv: string;
}

export function createProgram(): Command {
  return new Command('maa-ide')
    .description('the IDE backend: serves the browser IDE, the workspace, code generation and simulation sessions on one origin')
    .option('-w, --workspace <dir>', 'the folder to edit', process.cwd())
    .option('-p, --port <n>', 'HTTP port (0 = any free port)', parsePort, defaults.port)
    .option('--host <address>', 'address to listen on', defaults.host)
    .option('--app-dir <dir>', 'the built web app', defaults.appDir)
    .option('--maa-sim <path>', "the simulator's maa-sim executable (lockstep sessions)", defaults.maaSim)
    .option('--ros2-venv <dir>', 'the Python venv of ROS 2 sessions (rclpy, rosidl, maa-sim; the default one is set up when missing)', defaults.ros2Venv)
    .helpOption('-h, --help', 'show help')
    .addHelpText(
      'after',
      `
API (docs/ide.md): /api/files, /api/file, /api/apps, /api/generate, /api/generated/{file,trace},
/api/sim/{start,stop,status}; the simulator's rosbridge at /sim/rosbridge and viser at /sim/viser/.
Generated code goes to <workspace>/../.maa-ide-out/. ROS 2 sessions run in --ros2-venv, where the
generated interface package gets built and installed first. Ctrl-C stops a running simulation too.

Examples:
  maa-ide --workspace .maa-workspace
  maa-ide --workspace ~/models --port 0      (prints the port it got)`,
    );
}

/** Entry point of the `maa-ide` bin. */
export function run(argv: readonly string[]): void {
  const program = createProgram();
  program.parse([...argv]);
  const options = program.opts<CliOptions>();
  const workspace = path.resolve(options.workspace);
  startIdeServer({ workspace, port: options.port, host: options.host, appDir: options.appDir, maaSim: options.maaSim, ros2Venv: options.ros2Venv }).then(
    (server) => {
      console.log(`maa-ide: serving ${workspace} at ${server.url}`);
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
