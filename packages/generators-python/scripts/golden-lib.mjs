// Shared by the golden-file tests and scripts/update-golden.mjs: generates every case of
// test/golden/cases.json into <base>/<name>, where base is a folder directly inside .cache/ (so
// the trace file's relative model root is the same for every base), and lists the files that are
// compared with test/golden/<name>/.
import { existsSync, mkdirSync, mkdtempSync, readdirSync, readFileSync } from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';

export const packageDir = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..');
export const goldenDir = path.join(packageDir, 'test', 'golden');
export const cacheDir = path.join(packageDir, '.cache');

/** A fresh base folder for one run (concurrent test runs must not share output folders). */
export function freshBase() {
    mkdirSync(cacheDir, { recursive: true });
    return mkdtempSync(path.join(cacheDir, 'golden-'));
}
/** Folders of the output that are verbatim copies of rte/ (compared with rte/ instead): at the
 * top of the platform folder (timesync) or of its package folder (ROS 2: `<pkg>/maa_ros2`). */
export const RTE_FOLDERS = ['maa_behavior', 'maa_timesync', 'maa_ros2'];

/** Where the copies of rte/<name> are in a platform folder, if there. */
export function rteCopy(dir, name) {
    if (existsSync(path.join(dir, name))) return path.join(dir, name);
    for (const e of readdirSync(dir, { withFileTypes: true })) {
        if (e.isDirectory() && existsSync(path.join(dir, e.name, name))) return path.join(dir, e.name, name);
    }
    return undefined;
}

export function goldenCases() {
    return JSON.parse(readFileSync(path.join(goldenDir, 'cases.json'), 'utf8'));
}

/** Generates one case; returns the orchestrator's result and the platform folder. */
export async function generateCase(c, base) {
    const { createMaaServices } = await import('@maa/language-server');
    const { generate } = await import('@maa/generator-core/node');
    const { NodeFileSystem } = await import('langium/node');
    const outDir = path.join(base, c.name);
    const result = await generate({
        services: createMaaServices(NodeFileSystem),
        appFile: path.resolve(packageDir, c.app),
        platforms: [c.platform],
        outDir,
        discoveryRoots: [packageDir],
    });
    return { result, dir: path.join(outDir, c.platform) };
}

/** Relative paths (with /) of the files below dir, sorted, without the RTE copies. */
export function listFiles(dir, skipRte = true) {
    const out = [];
    const visit = (d, rel) => {
        for (const e of readdirSync(d, { withFileTypes: true })) {
            const r = rel ? `${rel}/${e.name}` : e.name;
            if (e.name === '__pycache__' || e.name === '.ruff_cache') continue;
            if (e.isDirectory()) {
                if (!(skipRte && !rel.includes('/') && RTE_FOLDERS.includes(e.name))) visit(path.join(d, e.name), r);
            } else out.push(r);
        }
    };
    visit(dir, '');
    return out.sort();
}
