// Installs a Debian package with apt-get for the scripts that make sure a system program is there
// (ensure-chromium.mjs, ensure-postgresql.mjs): one root check, one install with a retry after
// `apt-get update` (the package lists may be missing on a fresh machine), one kind of error.
import { spawnSync } from 'node:child_process';

/**
 * `apt-get install -y --no-install-recommends <pkg>`; throws with `hint` (what a user does instead)
 * when this process is not root or apt-get cannot run or fails. `tool` prefixes the messages.
 */
export function aptInstall(pkg, { tool, missing, hint, quiet = false }) {
    const isRoot = typeof process.getuid === 'function' && process.getuid() === 0;
    if (!isRoot) throw new Error(`${missing} and this process is not root, so it cannot install it.\n${hint}`);
    if (!quiet) console.log(`${tool}: ${missing}; installing Debian's ${pkg} with apt-get…`);
    const env = { ...process.env, DEBIAN_FRONTEND: 'noninteractive' };
    const stdio = quiet ? 'ignore' : 'inherit';
    const install = () => spawnSync('apt-get', ['install', '-y', '--no-install-recommends', pkg], { stdio, env });
    let result = install();
    if (result.status !== 0 && !result.error) {
        spawnSync('apt-get', ['update'], { stdio, env });
        result = install();
    }
    if (result.error) throw new Error(`${tool}: could not run apt-get: ${result.error.message}`);
    if (result.status !== 0) throw new Error(`${tool}: apt-get install ${pkg} failed (exit ${result.status})`);
}
