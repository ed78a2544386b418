/**
 * What the simulate commands need to know before anything runs: which maa-ide to start, and the
 * application path as the backend names it. Pure (file checks injected).
 */
import path from 'node:path';

/** The simulate settings (contributions: SIMULATE_SETTINGS). */
export interface SimulateSettings {
    /** maa-ide's bin script; empty: the workspace's `node_modules/@maa/ide-server`, else `maa-ide` on the PATH. */
    readonly backend: string;
    /** The Node executable that runs maa-ide. */
    readonly node: string;
}

export const SIMULATE_SETTINGS = {
    'maa.simulate.backend': {
        type: 'string',
        default: '',
        markdownDescription:
            "The IDE backend's script (`maa-ide`, from `@maa/ide-server`) that **MontiArc: Start Simulation** starts. Empty: the workspace's `node_modules/.bin/maa-ide`, else `maa-ide` on the `PATH`.",
        scope: 'machine-overridable',
    },
    'maa.simulate.node': {
        type: 'string',
        default: 'node',
        markdownDescription: 'The Node executable (20.10 or newer) that runs the IDE backend for simulations.',
        scope: 'machine-overridable',
    },
} as const;

export function readSimulateSettings(get: (key: string) => unknown): SimulateSettings {
    const backend = get('maa.simulate.backend');
    const node = get('maa.simulate.node');
    return {
        backend: typeof backend === 'string' ? backend.trim() : '',
        node: typeof node === 'string' && node.trim() !== '' ? node.trim() : 'node',
    };
}

/**
 * maa-ide's script: the setting, else the first workspace folder's `node_modules/.bin/maa-ide`,
 * else `maa-ide` on the PATH (`pathDirs`); `realpath` follows npm's bin links to the script.
 * Undefined when none exists.
 */
export function backendScript(
    settings: SimulateSettings,
    folders: readonly string[],
    pathDirs: readonly string[],
    exists: (file: string) => boolean,
    realpath: (file: string) => string,
): string | undefined {
    const candidates = settings.backend
        ? [settings.backend]
        : [
              ...folders.map((f) => path.join(f, 'node_modules', '.bin', 'maa-ide')),
              ...pathDirs.filter((d) => d !== '').map((d) => path.join(d, 'maa-ide')),
          ];
    const found = candidates.find((c) => exists(c));
    return found ? realpath(found) : undefined;
}

/**
 * The application as the backend names it: its path relative to the workspace folder, with `/`.
 * Undefined when the file is not inside the folder.
 */
export function backendAppPath(folder: string, appFile: string): string | undefined {
    const rel = path.relative(folder, appFile);
    if (rel === '' || rel.startsWith('..') || path.isAbsolute(rel)) return undefined;
    return rel.split(path.sep).join('/');
}
