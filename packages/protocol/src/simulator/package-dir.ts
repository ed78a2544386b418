/**
 * Where a generated platform's simulator package is: the folder `maa-sim run --package` takes,
 * holding `lockstep.json` (lock-step mode) or `deployment.json` (ROS 2 mode), and the ROS 2
 * interface packages a ros2 platform needs installed. Shared by the IDE backend's simulation
 * sessions and `maa-gen sim`. Node only (it reads the file system), so it
 * is its own subpath, `@maa/protocol/sim-package`, outside the package index the browser loads.
 */
import { createHash } from 'node:crypto';
import { type Dirent, existsSync, readdirSync, readFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
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

/**
 * The generated ROS 2 interface packages of a platform folder (ament_cmake packages that generate
 * messages, e.g. `rospython/toast_service_robot_interfaces/`): folders at most two levels below
 * it with a package.xml and a CMakeLists.txt that calls rosidl_generate_interfaces, sorted.
 */
export function findInterfacePackages(platformDir: string): string[] {
    const found: string[] = [];
    const visit = (dir: string, depth: number): void => {
        const cmake = path.join(dir, 'CMakeLists.txt');
        if (existsSync(path.join(dir, 'package.xml')) && existsSync(cmake)) {
            let text = '';
            try {
                text = readFileSync(cmake, 'utf8');
            } catch {
                // unreadable: not ours
            }
            if (/\brosidl_generate_interfaces\s*\(/.test(text)) found.push(dir);
            return;
        }
        if (depth === 2) return;
        let entries: Dirent[];
        try {
            entries = readdirSync(dir, { withFileTypes: true });
        } catch {
            return;
        }
        for (const e of entries) {
            if (e.isDirectory() && !e.name.startsWith('.')) visit(path.join(dir, e.name), depth + 1);
        }
    };
    visit(platformDir, 0);
    return found.sort();
}

/**
 * The lock file that serializes the setup of a ROS 2 environment (a venv with rclpy and maa-sim)
 * and the builds of interface packages into it, across the processes that share the venv (the IDE
 * backend, maa-gen sim): flock(1) on it.
 */
export function ros2EnvironmentLock(venv: string): string {
    return path.join(tmpdir(), `maa-ide-ros2-${createHash('sha256').update(path.resolve(venv)).digest('hex').slice(0, 16)}.lock`);
}
