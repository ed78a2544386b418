import path from 'node:path';
import { Command, InvalidArgumentError, Option } from 'commander';
import { CliError, ExitCode } from '../errors.js';
import type { CliIo } from '../io.js';
import { findMaaSim } from '../sim/maa-sim.js';
import { prepareTarget, type SimTarget } from '../sim/prepare.js';
import { prepareRos2 } from '../sim/ros2.js';
import { progressListener, summaryJson, summaryText } from '../sim/report.js';
import { type MaaSimOutcome, runMaaSim } from '../sim/run.js';

export interface SimCommandOptions {
    platform?: string;
    untilGoal?: boolean;
    /** Simulated seconds. */
    duration?: number;
    record?: string;
    headless?: boolean;
    viewer?: boolean;
    speed?: number;
    out?: string;
    root?: string;
    maaSim?: string;
    format: 'text' | 'json';
}

/**
 * `maa-gen sim APP.arcapp [--platform P] [--until-goal] [--duration S] [--record FILE.mcap]
 * [--headless | --viewer]`: generates the platform when its output is missing or older than the
 * models, runs it in maa-sim (lock-step for a timesync platform, ROS 2 for a ros2 one) with
 * progress on stderr, and prints a summary. Exit 0 when the goal was reached (`--until-goal`) or
 * the run completed, 1 when not, 2 for usage problems; a failed generation returns its own code.
 */
export async function runSim(appArg: string, options: SimCommandOptions, io: CliIo): Promise<ExitCode> {
    if (options.headless && options.viewer) throw new CliError('--headless and --viewer exclude each other');
    const record = options.record === undefined ? undefined : path.resolve(io.cwd, options.record);
    if (record !== undefined && path.extname(record) !== '.mcap') throw new CliError(`--record needs a .mcap file: ${options.record}`);
    const target = await prepareTarget(appArg, options, io);
    if (typeof target === 'number') return target;
    // a ros2 platform runs in the ROS 2 environment (its nodes import the generated messages)
    const maaSim =
        target.mode === 'ros2' && options.maaSim === undefined
            ? await prepareRos2(target.platformDir, io)
            : await findMaaSim(options.maaSim, io);
    const listener = progressListener(io);
    let outcome: MaaSimOutcome;
    try {
        outcome = await runMaaSim(
            {
                maaSim,
                packageDir: target.packageDir,
                mode: target.mode,
                untilGoal: options.untilGoal === true,
                duration: options.duration,
                record,
                viewer: options.viewer === true,
                // a person watching the viewer wants real time; headless runs go as fast as they can
                speed: options.speed ?? (options.viewer ? 1 : undefined),
            },
            listener,
        );
    } catch (e) {
        throw new CliError(`cannot run the simulator ${maaSim}: ${e instanceof Error ? e.message : String(e)}`);
    } finally {
        listener.done();
    }
    return report(target, outcome, options, io);
}

/** The summary and the exit code of a run. */
function report(target: SimTarget, outcome: MaaSimOutcome, options: SimCommandOptions, io: CliIo): ExitCode {
    const { finished } = outcome;
    if (!finished) {
        const how = outcome.signal ? `signal ${outcome.signal}` : `exit code ${outcome.exitCode}`;
        io.err(`maa-gen: the simulator ended without finishing the run (${how})\n`);
        return outcome.exitCode === ExitCode.usage ? ExitCode.usage : ExitCode.errors;
    }
    io.out(options.format === 'json' ? summaryJson(target, finished) : summaryText(target, finished, options.untilGoal === true, io.cwd));
    if (options.untilGoal) return finished.goal_reached ? ExitCode.ok : ExitCode.errors;
    const failed = finished.reason.startsWith('error') || finished.reason === 'a node failed';
    return failed ? ExitCode.errors : ExitCode.ok;
}

function positiveNumber(value: string): number {
    const n = Number(value);
    if (!Number.isFinite(n) || n <= 0) throw new InvalidArgumentError('expected a number > 0');
    return n;
}

function speed(value: string): number {
    const n = Number(value);
    if (!Number.isFinite(n) || n < 0 || n > 1000) throw new InvalidArgumentError('expected 0 (as fast as possible) .. 1000');
    return n;
}

export function simCommand(io: CliIo, setExitCode: (code: ExitCode) => void): Command {
    return new Command('sim')
        .description("run an application's platform in the simulator (generating it first when needed)")
        .argument('<app>', 'the application configuration file (APP.arcapp)')
        .option('-p, --platform <name>', 'the platform to run (required when the application has several)')
        .option('--until-goal', 'stop when the toast lies on the plate; exit 0 then, 1 when the run ends otherwise')
        .addOption(new Option('--duration <seconds>', 'stop after this much simulated time').argParser(positiveNumber))
        .option('--record <file.mcap>', 'record every port topic and the scene state into an MCAP file (ROS 2 schemas)')
        .option('--headless', 'no 3D view, no rosbridge endpoint (the default)')
        .option('--viewer', "serve the simulator's 3D view (viser) and print its URL; runs at real time unless --speed says otherwise")
        .addOption(new Option('--speed <factor>', 'simulated seconds per wall second; 0 = as fast as possible').argParser(speed))
        .option('-o, --out <dir>', 'output folder of the generated code (default: "generated" next to the .arcapp)')
        .option('-r, --root <dir>', 'model root (default: as maa-gen generate)')
        .option(
            '--maa-sim <file>',
            "the maa-sim executable (default: $MAA_SIM, the clone's sim-server/.venv, else one installed into the user's cache on first use; ros2: the clone's ROS 2 environment)",
        )
        .addOption(new Option('-f, --format <format>', 'summary format').choices(['text', 'json']).default('text'))
        .addHelpText(
            'after',
            `
What it does:
  generates the platform when its output is missing or older than a model file (as
  maa-gen generate does, its report on stderr), then runs maa-sim on the generated package:
  lock-step mode for a platform whose output has lockstep.json (timesync), ROS 2 mode for one
  with deployment.json (ros2: in a clone's ROS 2 environment, packages/generators-python/
  .venv-ros2, after installing the generated interface package into it). Without --until-goal
  or --duration it runs until Ctrl-C. Progress (simulated time, real-time factor, goal) goes
  to stderr: one line redrawn on a terminal, a line a second otherwise. The summary goes to
  stdout.

Exit codes:
  0  the goal was reached (--until-goal), or the run completed
  1  the goal was not reached, the run failed, or the models have errors
  2  usage problem (no such platform, several platforms and no --platform, no maa-sim)

Examples:
  maa-gen sim examples/toast-service/TR.arcapp --platform timesync --until-goal
  maa-gen sim TR.arcapp --platform timesync --duration 20 --record run.mcap
  maa-gen sim TR.arcapp --platform timesync --viewer`,
        )
        .action(async (app: string, options: SimCommandOptions) => {
            setExitCode(await runSim(app, options, io));
        });
}
