/**
 * Where a generated platform's simulator package is: the folder `maa-sim run --package` takes,
 * holding `lockstep.json` (lock-step mode) or `deployment.json` (ROS 2 mode). Shared by the IDE
 * backend's simulation sessions and `maa-gen sim`. Node only (it reads the file system), so it
 * is its own subpath, `@maa/protocol/sim-package`, outside the package index the browser loads.
 */
import { type Dirent, existsSync, readdirSync } from 'node:fs';
import path from 'node:path';
import { DEPLOYMENT_FILE_NAME, LOCKSTEP_FILE_NAME } from '../formats.js';

/** maa-sim's execution modes (`--mode`). */
export type SimPackageMode = 'lockstep' | 'ros2';

/** The file a generated package must hold for a mode (docs/simulation.md). */
export const SIM_PACKAGE_FILE: Readonly<Record<SimPackageMode, string>> = {
    lockstep: LOCKSTEP_FILE_NAME,
    ros2: DEPLOYMENT_FILE_NAME,
};

/** The platform folder itself or a folder at most two levels below it that holds `file`. */
export function findPackageDir(platformDir: string, file: string): string | undefined {
    const queue: Array<[string, number]> = [[platformDir, 0]];
    while (queue.length > 0) {
        const [dir, depth] = queue.shift()!;
        if (existsSync(path.join(dir, file))) return dir;
        if (depth === 2) continue;
        let entries: Dirent[];
        try {
            entries = readdirSync(dir, { withFileTypes: true });
        } catch {
            continue;
        }
        for (const e of entries.sort((a, b) => a.name.localeCompare(b.name))) {
            if (e.isDirectory() && !e.name.startsWith('.')) queue.push([path.join(dir, e.name), depth + 1]);
        }
    }
    return undefined;
}

/** The package of a generated platform and the mode it runs in (lock-step first), or undefined. */
export function findSimPackage(platformDir: string): { mode: SimPackageMode; dir: string } | undefined {
    for (const mode of ['lockstep', 'ros2'] as const) {
        const dir = findPackageDir(platformDir, SIM_PACKAGE_FILE[mode]);
        if (dir) return { mode, dir };
    }
    return undefined;
}
