import { spawn } from 'node:child_process';
import { existsSync } from 'node:fs';
import { createRequire } from 'node:module';
import path from 'node:path';
import { createInterface } from 'node:readline';
import { findInterfacePackages, ros2EnvironmentLock } from '@maa/protocol/sim-package';
import { CliError } from '../errors.js';
import type { CliIo } from '../io.js';

/**
 * The ROS 2 environment of ros2 platforms, the one the IDE backend uses (docs/ide.md): the venv
 * `packages/generators-python/.venv-ros2` with rclpy, the rosidl toolchain and maa-sim, made by
 * that package's `scripts/setup_ros2_venv.sh`; the generated interface packages are built and
 * installed into it by `scripts/install_ros2_interfaces.sh` (skipped while unchanged), since the
 * nodes maa-sim starts import their messages. Both scripts come with a clone, not with the
 * registry's packages.
 */
function generatorsPythonDir(): string {
    return path.dirname(createRequire(import.meta.url).resolve('@maa/generators-python/package.json'));
}

/** Runs a setup script under the environment's lock (shared with the IDE backend), its output on stderr. */
function runLocked(venv: string, script: string, args: string[], io: CliIo): Promise<void> {
    const flock = existsSync('/usr/bin/flock') || existsSync('/bin/flock');
    const [command, argv] = flock ? ['flock', [ros2EnvironmentLock(venv), 'bash', script, ...args]] : ['bash', [script, ...args]];
    return new Promise((resolve, reject) => {
        const child = spawn(command, argv, {
            stdio: ['ignore', 'pipe', 'pipe'],
            env: { ...process.env, PIP_DISABLE_PIP_VERSION_CHECK: '1' },
        });
        createInterface({ input: child.stdout }).on('line', (line) => io.err(`${line}\n`));
        createInterface({ input: child.stderr }).on('line', (line) => io.err(`${line}\n`));
        child.on('error', (e) => reject(new CliError(`cannot run ${script}: ${e.message}`)));
        child.on('close', (code) =>
            code === 0 ? resolve() : reject(new CliError(`${path.basename(script)} failed (exit code ${code})`, 1)),
        );
    });
}

/**
 * Makes the ROS 2 environment ready for a generated ros2 platform (the venv when missing, which
 * takes minutes the first time; every interface package of the platform) and answers its maa-sim.
 */
export async function prepareRos2(platformDir: string, io: CliIo): Promise<string> {
    const dir = generatorsPythonDir();
    const venv = path.join(dir, '.venv-ros2');
    const maaSim = path.join(venv, 'bin', 'maa-sim');
    const setup = path.join(dir, 'scripts', 'setup_ros2_venv.sh');
    const install = path.join(dir, 'scripts', 'install_ros2_interfaces.sh');
    if (!existsSync(setup) || !existsSync(install)) {
        throw new CliError(
            'ROS 2 mode needs the ROS 2 environment of a clone (packages/generators-python/scripts); ' +
                'or name the maa-sim of a Python with rclpy and the generated interface package with --maa-sim',
        );
    }
    if (!existsSync(maaSim)) {
        io.err(`maa-gen: setting up the ROS 2 environment ${venv} (rclpy, the rosidl toolchain, maa-sim; minutes the first time)\n`);
        await runLocked(venv, setup, [], io);
    }
    for (const interfaces of findInterfacePackages(platformDir)) {
        io.err(`maa-gen: installing the interface package ${path.basename(interfaces)} into ${venv} (skipped while unchanged)\n`);
        await runLocked(venv, install, [venv, interfaces], io);
    }
    return maaSim;
}
