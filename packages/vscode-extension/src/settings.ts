/**
 * The extension's settings (`maa.*`): their manifest schema and how they become the language
 * server's start options and the generate command's arguments. Pure (no `vscode` import), so the
 * mapping is tested without an editor.
 */
import path from 'node:path';

/** The manifest's `contributes.configuration.properties`. */
export const SETTINGS = {
    'maa.generate.outDir': {
        type: 'string',
        default: 'generated',
        markdownDescription:
            "Where **MontiArc: Generate** writes: a folder relative to the application configuration (`.arcapp`) or absolute. The default is `maa-gen generate`'s (`generated` next to the `.arcapp`); each platform gets a subfolder.",
    },
    'maa.generate.command': {
        type: 'string',
        default: '',
        markdownDescription:
            "The `maa-gen` command used by **MontiArc: Generate**. Empty: the workspace's `node_modules/.bin/maa-gen` when installed there, else `maa-gen` on the `PATH`.",
    },
    'maa.server.nodeArgs': {
        type: 'array',
        items: { type: 'string' },
        default: [],
        markdownDescription:
            'Extra Node options for the language server process (e.g. `--max-old-space-size=4096` for very large workspaces).',
    },
    'maa.trace.server': {
        type: 'string',
        enum: ['off', 'messages', 'verbose'],
        default: 'off',
        description: 'Logs the messages between VS Code and the MontiArc language server (output channel "MontiArc Language Server").',
    },
} as const;

export interface MaaSettings {
    readonly outDir: string;
    readonly command: string;
    readonly nodeArgs: readonly string[];
}

/** Reads the settings through a getter like `WorkspaceConfiguration.get`, with the manifest defaults. */
export function readSettings(get: (key: string) => unknown): MaaSettings {
    const str = (key: keyof typeof SETTINGS, fallback: string): string => {
        const v = get(key);
        return typeof v === 'string' ? v : fallback;
    };
    const args = get('maa.server.nodeArgs');
    return {
        outDir: str('maa.generate.outDir', SETTINGS['maa.generate.outDir'].default) || SETTINGS['maa.generate.outDir'].default,
        command: str('maa.generate.command', SETTINGS['maa.generate.command'].default).trim(),
        nodeArgs: Array.isArray(args) ? args.filter((a): a is string => typeof a === 'string') : [],
    };
}

/** The start options of the language server (vscode-languageclient's NodeModule with IPC transport). */
export interface ServerStart {
    readonly module: string;
    readonly args: string[];
    readonly options: { execArgv: string[] };
}

/** How the server starts in normal and in debug mode: `node <server> --node-ipc`, the debug run with an inspector port. */
export function serverStart(serverModule: string, settings: MaaSettings): { run: ServerStart; debug: ServerStart } {
    const run: ServerStart = { module: serverModule, args: [], options: { execArgv: [...settings.nodeArgs] } };
    return { run, debug: { ...run, options: { execArgv: [...settings.nodeArgs, '--nolazy', '--inspect=6009'] } } };
}

/** The folder generation writes to for an application configuration. */
export function outDirOf(appFile: string, settings: MaaSettings): string {
    return path.resolve(path.dirname(appFile), settings.outDir);
}

/** The `maa-gen` executable: the setting, else the workspace's installed CLI when it exists, else the PATH's. */
export function generateCommand(settings: MaaSettings, workspaceFolders: readonly string[], exists: (file: string) => boolean): string {
    if (settings.command) return settings.command;
    for (const folder of workspaceFolders) {
        const local = path.join(folder, 'node_modules', '.bin', process.platform === 'win32' ? 'maa-gen.cmd' : 'maa-gen');
        if (exists(local)) return local;
    }
    return 'maa-gen';
}

/** The arguments of `maa-gen generate` for one platform, with a JSON report on stdout. */
export function generateArgs(appFile: string, platform: string, settings: MaaSettings): string[] {
    return ['generate', appFile, '--platform', platform, '--out', outDirOf(appFile, settings), '--format', 'json'];
}

export { type ContributedLanguage, watchedFiles } from './model-files.js';
