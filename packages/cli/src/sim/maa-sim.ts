import { accessSync, constants } from 'node:fs';
import path from 'node:path';
import { CliError } from '../errors.js';
import type { CliIo } from '../io.js';

function executable(file: string): boolean {
    try {
        accessSync(file, constants.X_OK);
        return true;
    } catch {
        return false;
    }
}

/**
 * The simulator to run: `--maa-sim FILE`, else what @maa/sim-server's launcher finds (the IDE
 * backend uses the same): `$MAA_SIM`, the clone's `sim-server/.venv/bin/maa-sim` (made by
 * `bash sim-server/scripts/setup_env.sh`), or a venv in the user's cache folder that it installs
 * on first use, its progress on stderr. A usage error says why when there is none.
 */
export async function findMaaSim(explicit: string | undefined, io: CliIo): Promise<string> {
    if (explicit !== undefined) {
        const file = path.resolve(io.cwd, explicit);
        if (!executable(file)) throw new CliError(`the simulator ${explicit} is not an executable file`);
        return file;
    }
    const { ensureMaaSim } = await import('@maa/sim-server');
    let maaSim: string;
    try {
        maaSim = await ensureMaaSim({ env: io.env, onProgress: (line) => io.err(`${line}\n`) });
    } catch (e) {
        throw new CliError(`the simulator maa-sim could not be set up: ${e instanceof Error ? e.message : String(e)}`);
    }
    if (!executable(maaSim)) throw new CliError(`the simulator ${maaSim} is not an executable file`);
    return maaSim;
}
