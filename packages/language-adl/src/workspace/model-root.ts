/**
 * The one rule that decides the model root of a file, shared by the command line (`maa-gen check`
 * file arguments, the default `--root` of `maa-gen generate` and `maa-gen test`), the IDE backend,
 * the IDE front end and the language server (for a file in no configured root). It is pure (no
 * file system access of its own; the caller answers `hasMarker`), so browsers can use it too.
 * The rule is documented once, in docs/user-guide.md ("Model roots").
 *
 * Folders are POSIX-style: absolute (`/a/b`, `C:/a/b`) or relative to a workspace (`a/b`, with
 * `''` the workspace folder itself). Callers convert native paths before and after.
 */

/** The project file whose folder is a model root. */
export const MODEL_ROOT_MARKER = 'maa.json';

export interface ModelRootOptions {
    /** Whether `folder` holds a `maa.json` (the caller looks; this function never touches a disk). */
    hasMarker(folder: string): boolean;
    /**
     * The highest folder a root may be (a workspace folder): no marker is looked for above it, and
     * the package rule gives no root above it. A file outside `stopAt` gets neither rule.
     */
    stopAt?: string;
    /** The package the file declares (`a.b`), if any. */
    packageName?: string;
}

/**
 * The model root of `file`:
 * 1. the nearest folder from the file's folder upwards (not above `stopAt`) that holds `maa.json`;
 * 2. else, when the file declares a package whose segments equal its trailing folders, the folder
 *    above those folders (`models/` for `models/toast/ctrl/C.arc` declaring `package toast.ctrl;`);
 * 3. else the file's own folder.
 */
export function resolveModelRoot(file: string, options: ModelRootOptions): string {
    const folder = parentOf(file) ?? '';
    const stopAt = options.stopAt === undefined ? undefined : withoutSlash(options.stopAt);
    const inside = stopAt === undefined || isInside(folder, stopAt);
    if (inside) {
        for (let dir: string | undefined = folder; dir !== undefined; dir = dir === stopAt ? undefined : parentOf(dir)) {
            if (options.hasMarker(dir)) return dir;
        }
        const byPackage = packageRoot(folder, options.packageName);
        if (byPackage !== undefined && (stopAt === undefined || isInside(byPackage, stopAt))) return byPackage;
    }
    return folder;
}

/** `package a.b;` at the start of a model file (after a byte-order mark, white space and comments), if any. */
const PACKAGE_DECLARATION =
    /^\uFEFF?(?:\s|\/\/[^\n]*|\/\*[\s\S]*?\*\/)*package\s+([\p{L}_$][\p{L}\p{N}_$]*(?:\s*\.\s*[\p{L}_$][\p{L}\p{N}_$]*)*)\s*;/u;

/** The package a model file's text declares at its start (`a.b`, spaces removed), if any. */
export function declaredPackage(text: string): string | undefined {
    const declared = PACKAGE_DECLARATION.exec(text)?.[1];
    return declared === undefined
        ? undefined
        : declared
              .split('.')
              .map((s) => s.trim())
              .join('.');
}

/** The folder above the trailing folders that spell `packageName`, if they do. */
function packageRoot(folder: string, packageName: string | undefined): string | undefined {
    if (!packageName) return undefined;
    let dir: string | undefined = folder;
    for (const segment of packageName.split('.').reverse()) {
        if (dir === undefined || lastSegment(dir) !== segment) return undefined;
        dir = parentOf(dir);
    }
    return dir;
}

function lastSegment(folder: string): string {
    return folder.substring(folder.lastIndexOf('/') + 1);
}

/** The folder holding `p`; undefined above a file system root (`/`, `C:/`) or the workspace (`''`). */
function parentOf(p: string): string | undefined {
    if (p === '' || p === '/' || /^[A-Za-z]:\/?$/.test(p)) return undefined;
    const trimmed = p.length > 1 && p.endsWith('/') ? p.slice(0, -1) : p;
    const i = trimmed.lastIndexOf('/');
    if (i < 0) return '';
    if (i === 0) return '/';
    if (i === 2 && /^[A-Za-z]:/.test(trimmed)) return trimmed.slice(0, 3);
    return trimmed.slice(0, i);
}

function withoutSlash(folder: string): string {
    return folder.length > 1 && folder.endsWith('/') && !/^[A-Za-z]:\/$/.test(folder) ? folder.slice(0, -1) : folder;
}

function isInside(folder: string, stopAt: string): boolean {
    if (stopAt === '') return !folder.startsWith('/') && !/^[A-Za-z]:/.test(folder);
    return folder === stopAt || folder.startsWith(stopAt.endsWith('/') ? stopAt : `${stopAt}/`);
}
