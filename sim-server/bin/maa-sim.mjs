#!/usr/bin/env node
// `npx maa-sim ...`: runs the simulator, installing it into a cached venv on first use
// (lib/sim-env.mjs). Arguments, standard streams and the exit code are maa-sim's own; SIGINT and
// SIGTERM are passed on, so the launcher can stand wherever a maa-sim executable is expected.
import { spawn } from 'node:child_process';
import { ensureMaaSim } from '../lib/sim-env.mjs';

let maaSim;
try {
    maaSim = await ensureMaaSim();
} catch (error) {
    console.error(error.message);
    process.exit(2);
}
const child = spawn(maaSim, process.argv.slice(2), { stdio: 'inherit' });
for (const signal of ['SIGINT', 'SIGTERM', 'SIGHUP']) process.on(signal, () => child.kill(signal));
child.on('error', (error) => {
    console.error(`maa-sim: could not start ${maaSim}: ${error.message}`);
    process.exit(2);
});
child.on('close', (code, signal) => process.exit(code ?? (signal === 'SIGINT' ? 130 : 143)));
