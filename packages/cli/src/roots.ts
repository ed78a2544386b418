import { accessSync, constants, existsSync, readFileSync, statSync, type Stats } from 'node:fs';
import path from 'node:path';
import type { RootSpec } from '@maa/language-server';
import { LANGUAGE_FACTS } from '@maa/language-server/language-facts';
import { declaredPackage, MODEL_ROOT_MARKER, resolveModelRoot } from '@maa/language-server/model-root';
import { CliError } from './errors.js';

/**
 * File extensions of model files: those of every file language of the family, from the language
 * facts the grammar composer writes (so a new language is discovered without a change here). The
 * checker's own discovery (`checkRoots`) reads the same extensions from the family's service
 * registry, so `.arcapp` application configurations have always been checked with their folder;
 * as file arguments they are checked within the root of modelRootOfFile, the same root that is
 * the default `--root` of `maa-gen generate` and `maa-gen test` and the one the IDE generates in.
 */
export const MODEL_FILE_EXTENSIONS: readonly string[] = [...new Set(LANGUAGE_FACTS.languages.flatMap((l) => l.fileExtensions))].sort();

export function isModelFile(file: string): boolean {
    return MODEL_FILE_EXTENSIONS.includes(path.extname(file));
}

/**
 * Turns the path arguments of `check` into model roots.
 *
 * - A directory is an independent model root: all its model files are checked and reported.
 * - A file is checked within its model root (see modelRootOfFile): every model file of that
 *   root is loaded for scoping, but only the named files are reported.
 *
 * Roots keep the order of their first mention; a directory argument wins over file arguments in
 * the same root. All problems with the arguments are collected into one CliError, one per line.
 */
export function resolveRoots(args: readonly string[], cwd: string): RootSpec[] {
    const roots = new Map<string, { whole: boolean; files: string[] }>();
    const problems: string[] = [];

    for (const arg of args) {
        const abs = path.resolve(cwd, arg);
        const stats = statOrProblem(abs, arg, problems);
        if (!stats) continue;
        if (stats.isDirectory()) {
            if (!readable(abs, constants.R_OK | constants.X_OK)) {
                problems.push(`cannot read directory: ${arg} (permission denied)`);
                continue;
            }
            const entry = roots.get(abs);
            if (entry) {
                entry.whole = true;
                entry.files = [];
            } else {
                roots.set(abs, { whole: true, files: [] });
            }
        } else if (stats.isFile()) {
            if (!isModelFile(abs)) {
                problems.push(`not a model file (expected ${MODEL_FILE_EXTENSIONS.join(' or ')}): ${arg}`);
                continue;
            }
            let text: string;
            try {
                text = readFileSync(abs, 'utf8');
            } catch (e) {
                problems.push(`cannot read file: ${arg} (${describe(e)})`);
                continue;
            }
            const root = modelRootOfFile(abs, text);
            const entry = roots.get(root);
            if (!entry) {
                roots.set(root, { whole: false, files: [abs] });
            } else if (!entry.whole && !entry.files.includes(abs)) {
                entry.files.push(abs);
            }
        } else {
            problems.push(`not a file or directory: ${arg}`);
        }
    }

    if (problems.length > 0) {
        throw new CliError(problems.join('\n'));
    }
    return [...roots].map(([root, { whole, files }]) => (whole ? { root } : { root, files }));
}

function statOrProblem(abs: string, arg: string, problems: string[]): Stats | undefined {
    try {
        return statSync(abs);
    } catch (e) {
        const code = (e as NodeJS.ErrnoException).code;
        if (code === 'ENOENT' || code === 'ENOTDIR') {
            problems.push(`path not found: ${arg}`);
        } else {
            problems.push(`cannot access: ${arg} (${describe(e)})`);
        }
        return undefined;
    }
}

function describe(e: unknown): string {
    const code = (e as NodeJS.ErrnoException).code;
    if (code === 'EACCES' || code === 'EPERM') return 'permission denied';
    if (code === 'EISDIR') return 'is a directory';
    return code ?? (e instanceof Error ? e.message : String(e));
}

/**
 * The model root of a single file, by the one rule of `resolveModelRoot` (docs/user-guide.md,
 * "Model roots"): the nearest folder from the file's upwards with a `maa.json`; else the folder
 * that holds its package folders (`models/` for `models/toast/ctrl/Controller.arc` declaring
 * `package toast.ctrl;`); else the file's own folder.
 */
export function modelRootOfFile(file: string, text: string | undefined): string {
    const posix = (p: string): string => p.split(path.sep).join('/');
    const root = resolveModelRoot(posix(path.resolve(file)), {
        hasMarker: (folder) => existsSync(path.join(folder, MODEL_ROOT_MARKER)),
        packageName: text === undefined ? undefined : declaredPackage(text),
    });
    return path.resolve(root.split('/').join(path.sep) || path.sep);
}

/**
 * The default model root of an application configuration: an `.arcapp` declares no package (its
 * grammar has none), so only the `maa.json` rule and its own folder apply; nothing is read.
 */
export function modelRootOfApp(appFile: string): string {
    return modelRootOfFile(appFile, undefined);
}

function readable(abs: string, mode: number): boolean {
    try {
        accessSync(abs, mode);
        return true;
    } catch {
        return false;
    }
}

/** The application configuration a command names (`APP.arcapp`), resolved against `cwd`; usage problems throw. */
export function appFileArg(appArg: string, cwd: string): string {
    const appFile = path.resolve(cwd, appArg);
    let isFile: boolean;
    try {
        isFile = statSync(appFile).isFile();
    } catch {
        throw new CliError(`path not found: ${appArg}`);
    }
    if (!isFile) throw new CliError(`not a file: ${appArg}`);
    if (path.extname(appFile) !== '.arcapp') throw new CliError(`not an application configuration (expected .arcapp): ${appArg}`);
    return appFile;
}
