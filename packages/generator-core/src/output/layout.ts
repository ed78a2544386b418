import { randomBytes } from 'node:crypto';
import { lstatSync, readlinkSync, type Stats, statSync } from 'node:fs';
import path from 'node:path';

/**
 * The on-disk layout of an output root `<out>` (docs/generating.md, "Output folder"):
 *
 *     <out>/P                   a symbolic link to `.maa-gen/P.v<id>` (relative)
 *     <out>/.maa-gen/P.v<id>/   the files of platform P (one folder per generation)
 *     <out>/.maa-gen/lock       held while a generation writes into <out>
 *
 * A generation builds a new version folder beside the current one and switches `<out>/P` to it
 * by renaming a new symbolic link over the old one: one rename, so a reader sees either the old
 * or the new tree. Every name below `.maa-gen` that matches a pattern of this module is ours;
 * anything else there (and anything else in `<out>`) is never deleted.
 */
export const STATE_DIR = '.maa-gen';

const ID = '[0-9a-f]{12}';
const VERSION = new RegExp(`^(.+)\\.v(${ID})$`);
const TEMP_LINK = new RegExp(`^link\\.${ID}$`);
/** A plain platform folder moved aside while it is converted to the link layout. */
const OLD_FOLDER = new RegExp(`^old\\.(.+)\\.(${ID})$`);
/** Temporary lock files: `lock.<pid>.<id>`. */
const TEMP_LOCK = new RegExp(`^lock\\.(\\d+)\\.${ID}$`);
/** Staging folders of the writer before the link layout (`.maa-staging-<P>.<pid>.<hex>`, in `<out>`). */
const LEGACY_STAGING = /^\.maa-staging-.+\.\d+\.[0-9a-f]{8}$/;

export function newId(): string {
    return randomBytes(6).toString('hex');
}

export const names = {
    version: (platform: string, id: string): string => `${platform}.v${id}`,
    tempLink: (id: string): string => `link.${id}`,
    oldFolder: (platform: string, id: string): string => `old.${platform}.${id}`,
    tempLock: (id: string): string => `lock.${process.pid}.${id}`,
    /** The target written into `<out>/P`: relative, so a moved or copied `<out>` keeps working. */
    linkTarget: (version: string): string => `${STATE_DIR}/${version}`,
};

/** Classifies a name found in `<out>/.maa-gen` (undefined: not ours, never touched). */
export function ownEntry(
    name: string,
):
    | { kind: 'version'; platform: string }
    | { kind: 'temp-link' }
    | { kind: 'old-folder'; platform: string }
    | { kind: 'temp-lock'; pid: number }
    | undefined {
    let m = VERSION.exec(name);
    if (m) return { kind: 'version', platform: m[1]! };
    if (TEMP_LINK.test(name)) return { kind: 'temp-link' };
    m = OLD_FOLDER.exec(name);
    if (m) return { kind: 'old-folder', platform: m[1]! };
    m = TEMP_LOCK.exec(name);
    if (m) return { kind: 'temp-lock', pid: Number(m[1]) };
    return undefined;
}

export function isLegacyStaging(name: string): boolean {
    return LEGACY_STAGING.test(name);
}

/** What `<out>/P` is now. */
export type RootState =
    | { readonly kind: 'missing' }
    /** Our link; `exists` is false when its version folder is gone. */
    | { readonly kind: 'version'; readonly version: string; readonly exists: boolean }
    /** A plain folder (written before the link layout, or by hand): converted by the next commit. */
    | { readonly kind: 'folder' }
    | { readonly kind: 'foreign-link'; readonly target: string }
    | { readonly kind: 'other' };

export function rootState(outRoot: string, platform: string): RootState {
    const root = path.join(outRoot, platform);
    let st: Stats;
    try {
        st = lstatSync(root);
    } catch (e) {
        if ((e as NodeJS.ErrnoException).code === 'ENOENT') return { kind: 'missing' };
        throw e;
    }
    if (st.isDirectory()) return { kind: 'folder' };
    if (!st.isSymbolicLink()) return { kind: 'other' };
    const target = readlinkSync(root);
    const prefix = `${STATE_DIR}/`;
    const version = target.startsWith(prefix) ? target.slice(prefix.length) : '';
    const own = ownEntry(version);
    if (own?.kind !== 'version' || own.platform !== platform) return { kind: 'foreign-link', target };
    let exists = false;
    try {
        exists = statSync(path.join(outRoot, STATE_DIR, version)).isDirectory();
    } catch {
        exists = false;
    }
    return { kind: 'version', version, exists };
}

/**
 * A file system problem while writing the output, naming the path a user knows (the platform
 * folder's path, not the hidden version folder's) and the reason in words.
 */
export class OutputWriteError extends Error {
    constructor(
        readonly path: string,
        readonly reason: string,
    ) {
        super(`${path}: ${reason}`);
        this.name = 'OutputWriteError';
    }
}

const REASONS: Record<string, string> = {
    EACCES: 'permission denied',
    EPERM: 'operation not permitted',
    EROFS: 'read-only file system',
    ENOSPC: 'no space left on the device',
    EDQUOT: 'disk quota exceeded',
    ENOTDIR: 'a file is where a folder is needed',
    EISDIR: 'a folder is where a file is needed',
    EEXIST: 'already exists',
    ENAMETOOLONG: 'the name is too long',
    EMFILE: 'too many open files',
    EIO: 'input/output error',
};

/** Turns an error of `fs` into an OutputWriteError; `display` maps internal paths to user paths. */
export function toWriteError(e: unknown, fallbackPath: string, display: (p: string) => string = (p) => p): OutputWriteError {
    if (e instanceof OutputWriteError) return e;
    const err = e as NodeJS.ErrnoException;
    const where = display(typeof err.path === 'string' ? err.path : fallbackPath);
    // The code, not the message: fs messages repeat absolute paths.
    const reason = err.code ? (REASONS[err.code] ?? `${err.code}${err.syscall ? ` (${err.syscall})` : ''}`) : err.message || String(e);
    return new OutputWriteError(where, reason);
}
