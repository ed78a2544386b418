/** The Python that runs the grading driver: the sim-server venv's, found the way the lab finds maa-sim. */
import { existsSync } from 'node:fs';
import { createRequire } from 'node:module';
import path from 'node:path';
import { fileURLToPath } from 'node:url';

/** sim-server's folder: the installed @maa/sim-server, else the clone's `sim-server/`. */
function simServerDir(): string {
    try {
        return path.dirname(createRequire(import.meta.url).resolve('@maa/sim-server/package.json'));
    } catch {
        return path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..', '..', '..', 'sim-server');
    }
}

/** `$MAA_GRADING_PYTHON`, else sim-server's development venv (`sim-server/.venv/bin/python`, scripts/setup_env.sh creates it). */
export function defaultPython(env: NodeJS.ProcessEnv = process.env): string {
    return env['MAA_GRADING_PYTHON'] ?? path.join(simServerDir(), '.venv', 'bin', 'python');
}

/** Whether the default Python exists (tests skip without it). */
export function hasDefaultPython(): boolean {
    return existsSync(defaultPython());
}
