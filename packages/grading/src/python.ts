/** The Python that runs the grading driver: the sim-server venv's, found the way maa-sim is found. */
import { existsSync } from 'node:fs';
import path from 'node:path';
import { cachedVenv, ensureMaaSim, packageDir } from '@maa/sim-server';

/**
 * `$MAA_GRADING_PYTHON`; else the development venv of a clone (`sim-server/.venv`, created by
 * `sim-server/scripts/setup_env.sh`, which installs Ray); else the cached venv @maa/sim-server's
 * launcher installs maa-sim into.
 */
export function defaultPython(env: NodeJS.ProcessEnv = process.env): string {
    return givenOrDevelopment(env) ?? path.join(cachedVenv(env), 'bin', 'python');
}

/** `$MAA_GRADING_PYTHON`, else a clone's development venv when it exists (both used as they are). */
function givenOrDevelopment(env: NodeJS.ProcessEnv): string | undefined {
    const own = env['MAA_GRADING_PYTHON'];
    if (own) return own;
    const development = path.join(packageDir, '.venv', 'bin', 'python');
    return existsSync(development) ? development : undefined;
}

/** Whether the default Python exists (tests skip without it). */
export function hasDefaultPython(): boolean {
    return existsSync(defaultPython());
}

/**
 * The Python that runs the grading driver, ready to run it: {@link defaultPython} when it is
 * `$MAA_GRADING_PYTHON` or a clone's development venv; otherwise @maa/sim-server's launcher
 * installs maa-sim with its `grade` extra (Ray) into its cached venv first, once (progress lines
 * on stderr), so an installed @maa/grading works without a clone.
 */
export async function gradingPython(env: NodeJS.ProcessEnv = process.env): Promise<string> {
    const ready = givenOrDevelopment(env);
    if (ready) return ready;
    const maaSim = await ensureMaaSim({ env, extras: ['grade'] });
    return path.join(path.dirname(maaSim), 'python');
}
