#!/usr/bin/env node
// Makes sure Debian's chromium is installed at /usr/bin/chromium for the e2e tests and the IDE
// benchmark (playwright-core drives it; no browser download). Installs it with apt-get when
// missing (needs root); prints the path. Usage: node scripts/ensure-chromium.mjs
import { spawnSync } from 'node:child_process';
import { existsSync } from 'node:fs';
import { fileURLToPath } from 'node:url';

export const CHROMIUM = process.env.MAA_CHROMIUM ?? '/usr/bin/chromium';

export function ensureChromium({ quiet = false } = {}) {
    if (existsSync(CHROMIUM)) return CHROMIUM;
    const isRoot = typeof process.getuid === 'function' && process.getuid() === 0;
    if (!isRoot) {
        throw new Error(
            `${CHROMIUM} is missing and this process is not root, so it cannot install it.\n` +
                `Install Debian's chromium yourself: sudo apt-get install -y chromium (or set MAA_CHROMIUM to a chromium binary).`,
        );
    }
    if (!quiet) console.log(`ensure-chromium: ${CHROMIUM} is missing; installing Debian's chromium with apt-get…`);
    const env = { ...process.env, DEBIAN_FRONTEND: 'noninteractive' };
    const stdio = quiet ? 'ignore' : 'inherit';
    let result = spawnSync('apt-get', ['install', '-y', '--no-install-recommends', 'chromium'], { stdio, env });
    if (result.status !== 0) {
        // The package lists may be missing on a fresh machine.
        spawnSync('apt-get', ['update'], { stdio, env });
        result = spawnSync('apt-get', ['install', '-y', '--no-install-recommends', 'chromium'], { stdio, env });
    }
    if (result.error) throw new Error(`ensure-chromium: could not run apt-get: ${result.error.message}`);
    if (result.status !== 0 || !existsSync(CHROMIUM)) {
        throw new Error(`ensure-chromium: apt-get install chromium failed (exit ${result.status}); ${CHROMIUM} is still missing`);
    }
    return CHROMIUM;
}

if (process.argv[1] && fileURLToPath(import.meta.url) === process.argv[1]) {
    try {
        console.log(ensureChromium());
    } catch (error) {
        console.error(error.message);
        process.exit(1);
    }
}
