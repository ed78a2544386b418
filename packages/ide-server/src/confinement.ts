import { lstat, realpath } from 'node:fs/promises';
import path from 'node:path';
import { HttpError } from './http-util.js';

/** The longest file or folder name (one path segment) Linux file systems take (NAME_MAX). */
export const MAX_NAME_BYTES = 255;

/**
 * Checks the syntax of a client path (relative, POSIX, no `..`): 400 otherwise. Query values
 * arrive URL-decoded, so `%2e%2e/` is checked as `../`.
 */
export function checkRelativePath(rel: string, what = 'path'): string[] {
    if (rel === '') throw new HttpError(400, `empty ${what}`);
    if (rel.includes('\0')) throw new HttpError(400, `${what} contains a NUL byte: ${JSON.stringify(rel)}`);
    if (rel.includes('\\')) throw new HttpError(400, `${what} contains a backslash (use '/'): ${rel}`);
    if (rel.startsWith('/') || /^[A-Za-z]:/.test(rel)) throw new HttpError(400, `absolute ${what} not allowed: ${rel}`);
    const segments = rel.split('/').filter((s) => s !== '' && s !== '.');
    if (segments.some((s) => s === '..')) throw new HttpError(400, `'..' segments are not allowed in ${what}: ${rel}`);
    if (segments.length === 0) throw new HttpError(400, `${what} names no file: ${rel}`);
    const long = segments.find((s) => Buffer.byteLength(s) > MAX_NAME_BYTES);
    if (long !== undefined) {
        throw new HttpError(
            400,
            `a name in ${what} is too long (${Buffer.byteLength(long)} bytes; file systems allow ${MAX_NAME_BYTES}): ${long.slice(0, 40)}…`,
        );
    }
    return segments;
}

function inside(root: string, target: string): boolean {
    return target === root || target.startsWith(root.endsWith(path.sep) ? root : root + path.sep);
}

async function exists(p: string): Promise<boolean> {
    try {
        await lstat(p);
        return true;
    } catch {
        return false;
    }
}

/**
 * A folder that client paths are confined to (the workspace, the generated output). Symlinks
 * are resolved: a path whose real location, or for a new file the real location of its
 * nearest existing parent, lies outside the root is refused with 403.
 */
export class ConfinedRoot {
    private realRoot: string | undefined;

    constructor(
        readonly root: string,
        private readonly label = 'the workspace',
    ) {}

    private async real(): Promise<string> {
        // Resolved on first use: the output root may appear only after the first generation.
        this.realRoot ??= await realpath(this.root);
        return this.realRoot;
    }

    /** The absolute path of `rel` after the syntax and symlink checks (the file need not exist). */
    async resolve(rel: string, what = 'path'): Promise<string> {
        return (await this.locate(rel, what)).target;
    }

    /**
     * Like resolve, for writing and deleting: a hidden segment (`.git`, `.vscode`, ...) in the
     * path, or in where its symlinks lead, is refused with 403, so the API cannot plant a git hook.
     */
    async resolveWritable(rel: string, what = 'path'): Promise<string> {
        const { target, segments, realRelative } = await this.locate(rel, what);
        const hidden = [...segments, ...realRelative].find((s) => s.startsWith('.'));
        if (hidden !== undefined)
            throw new HttpError(403, `${rel}: hidden files and folders (here ${hidden}) cannot be written through the IDE`);
        return target;
    }

    private async locate(rel: string, what: string): Promise<{ target: string; segments: string[]; realRelative: string[] }> {
        const segments = checkRelativePath(rel, what);
        const target = path.join(this.root, ...segments);
        let realRoot: string;
        try {
            realRoot = await this.real();
        } catch {
            throw new HttpError(404, `not found: ${rel} (${this.label} does not exist)`);
        }
        // The nearest existing ancestor (the target itself when it exists) decides where it lies.
        let probe = target;
        while (!(await exists(probe))) {
            const parent = path.dirname(probe);
            if (parent === probe) break;
            probe = parent;
        }
        let real: string;
        try {
            real = await realpath(probe);
        } catch {
            // lstat saw it but realpath fails: a dangling symlink, whose target we cannot vouch for.
            throw new HttpError(403, `${rel} is a symlink whose target does not exist`);
        }
        if (!inside(realRoot, real)) throw new HttpError(403, `${rel} resolves outside ${this.label}`);
        const realTarget = path.join(real, path.relative(probe, target));
        const realRelative = path
            .relative(realRoot, realTarget)
            .split(path.sep)
            .filter((s) => s !== '');
        return { target, segments, realRelative };
    }
}
