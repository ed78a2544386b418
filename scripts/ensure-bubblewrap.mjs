#!/usr/bin/env node
// Makes sure bubblewrap (`bwrap`) is installed: maa_sim.sandbox runs students' code in it (grading
// runs, the lab's live simulations) and sim-server/tests/test_sandbox.py attacks it. Installs
// Debian's `bubblewrap` with apt-get when missing (needs root); prints the path of bwrap.
// Usage: node scripts/ensure-bubblewrap.mjs   (MAA_BWRAP names another bwrap, as for maa_sim.sandbox)
import { accessSync, constants } from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { aptInstall } from './apt-install.mjs';

/** The bwrap maa_sim.sandbox uses: MAA_BWRAP, else bwrap on PATH, else /usr/bin/bwrap; undefined when none is executable. */
export function findBwrap() {
    const onPath = (process.env.PATH ?? '')
        .split(path.delimiter)
        .filter(Boolean)
        .map((dir) => path.join(dir, 'bwrap'));
    const candidates = [process.env.MAA_BWRAP, ...onPath, '/usr/bin/bwrap'].filter(Boolean);
    return candidates.find((file) => {
        try {
            accessSync(file, constants.X_OK);
            return true;
        } catch {
            return false;
        }
    });
}

export function ensureBubblewrap({ quiet = false } = {}) {
    const found = findBwrap();
    if (found) return found;
    aptInstall('bubblewrap', {
        tool: 'ensure-bubblewrap',
        missing: 'bubblewrap (bwrap) is missing',
        hint: "Install Debian's bubblewrap yourself: sudo apt-get install -y bubblewrap (or set MAA_BWRAP to a bwrap).",
        quiet,
    });
    const bwrap = findBwrap();
    if (!bwrap) throw new Error('ensure-bubblewrap: apt-get installed bubblewrap, but bwrap is still missing');
    return bwrap;
}

if (process.argv[1] && fileURLToPath(import.meta.url) === process.argv[1]) {
    try {
        console.log(ensureBubblewrap());
    } catch (error) {
        console.error(error.message);
        process.exit(1);
    }
}
