/**
 * Which application configuration (`.arcapp`) runs a `.stream` file, by the rule of `maa-gen
 * test APP.arcapp`: the command runs the stream files below the application's model root (the
 * one rule of `resolveModelRoot`: the nearest folder above the `.arcapp` with a `maa.json`, else
 * its folder), skipping hidden folders, `node_modules` and `generated`, on the application's
 * platform `timesync`. So a stream file belongs to an application with a `timesync` platform whose
 * model root holds it; with several, the one with the nearest root (then the first by path).
 * Pure: paths are POSIX (URI paths), the caller answers whether a folder holds a `maa.json`.
 */
import { resolveModelRoot } from '@maa/language-server/model-root';
import { platformsOf } from '../platforms.js';

/** The platform `maa-gen test` runs by default (its `--platform`). */
export const TEST_PLATFORM = 'timesync';

export interface AppCandidate {
    /** The `.arcapp` file (POSIX path). */
    readonly path: string;
    readonly text: string;
}

/** The folders of `file` below `root` (none when it is not below it): `a/b` for `root/a/b/F.stream`. */
function foldersBelow(root: string, file: string): string[] | undefined {
    const prefix = root.endsWith('/') ? root : `${root}/`;
    if (!file.startsWith(prefix)) return undefined;
    return file.slice(prefix.length).split('/').slice(0, -1);
}

/** Whether `maa-gen test` finds `file` when it walks `root` (it skips hidden folders, node_modules and generated). */
export function walkedFrom(root: string, file: string): boolean {
    const folders = foldersBelow(root, file);
    return folders?.every((f) => !f.startsWith('.') && f !== 'node_modules' && f !== 'generated') ?? false;
}

/**
 * The application that runs `streamFile`, or undefined when none does.
 * @param stopAt the workspace folder (no `maa.json` is looked for above it)
 */
export function appOfStreamFile(
    streamFile: string,
    apps: readonly AppCandidate[],
    hasMarker: (folder: string) => boolean,
    stopAt?: string,
): string | undefined {
    let best: { path: string; depth: number } | undefined;
    for (const app of [...apps].sort((a, b) => (a.path < b.path ? -1 : a.path > b.path ? 1 : 0))) {
        if (!platformsOf(app.text)?.platforms.includes(TEST_PLATFORM)) continue;
        const root = resolveModelRoot(app.path, stopAt === undefined ? { hasMarker } : { hasMarker, stopAt });
        if (!walkedFrom(root, streamFile)) continue;
        const depth = root.split('/').length;
        if (!best || depth > best.depth) best = { path: app.path, depth };
    }
    return best?.path;
}
