import {
    chmodSync,
    copyFileSync,
    linkSync,
    lstatSync,
    mkdirSync,
    readdirSync,
    readlinkSync,
    rmdirSync,
    statSync,
    symlinkSync,
    writeFileSync,
} from 'node:fs';
import path from 'node:path';
import { OutputWriteError } from './layout.js';
import type { Checkpoints } from './pause.js';
import type { WritePlan } from './writer.js';

/**
 * Fills a new version folder: the plan's files are written, everything else of the previous
 * tree (`source`: unchanged generated files, user files, files no generation wrote, folders,
 * symbolic links) is carried over, except the files the plan removes. Files are carried over as
 * hard links (the folders lie on one file system), so nothing is copied and the previous tree
 * stays as it is; a file system without hard links gets copies. `shown(rel)` is the path a
 * user knows, for error messages.
 */
export function buildVersion(
    plan: WritePlan,
    source: string | undefined,
    version: string,
    checkpoints: Checkpoints,
    shown: (rel: string) => string,
): void {
    // Each folder made once (a model's files share a few folders: one mkdir per file would be ~1,000 calls).
    const made = new Set<string>();
    for (const f of plan.write) {
        const target = path.join(version, ...f.path.split('/'));
        const folder = path.dirname(target);
        if (!made.has(folder)) {
            mkdirSync(folder, { recursive: true });
            made.add(folder);
        }
        writeFileSync(target, f.content, { flag: 'wx' });
        checkpoints.reached('staging');
    }
    if (source !== undefined) {
        const skip = new Set([...plan.write.map((f) => f.path), ...plan.remove]);
        carryOver(source, version, '', skip, checkpoints, shown);
        chmodSync(version, statSync(source).mode & 0o7777);
    }
    // Folders that only held files this generation no longer produces.
    for (const rel of plan.remove) {
        let dir = path.dirname(path.join(version, ...rel.split('/')));
        while (dir.startsWith(version + path.sep) && tryRmdir(dir)) dir = path.dirname(dir);
    }
    checkpoints.ended('staging');
}

function carryOver(
    from: string,
    to: string,
    rel: string,
    skip: ReadonlySet<string>,
    checkpoints: Checkpoints,
    shown: (rel: string) => string,
): void {
    for (const name of readdirSync(path.join(from, rel)).sort()) {
        const r = rel ? `${rel}/${name}` : name;
        if (skip.has(r)) continue;
        const src = path.join(from, ...r.split('/'));
        const dst = path.join(to, ...r.split('/'));
        const st = lstatSync(src);
        const existing = lstatOrUndefined(dst);
        if (st.isDirectory()) {
            if (existing && !existing.isDirectory())
                throw new OutputWriteError(shown(r), 'is a folder, but a generated file of that name goes there');
            if (!existing) mkdirSync(dst);
            carryOver(from, to, r, skip, checkpoints, shown);
            chmodSync(dst, st.mode & 0o7777);
            continue;
        }
        if (existing) {
            const why = existing.isDirectory() ? 'is a file where generated files need a folder' : 'is in the way of a generated file';
            throw new OutputWriteError(shown(r), why);
        }
        if (st.isSymbolicLink()) symlinkSync(readlinkSync(src), dst);
        else if (st.isFile()) linkOrCopy(src, dst);
        else
            throw new OutputWriteError(
                shown(r),
                'is neither a file, a folder nor a symbolic link, so it cannot be carried over to the new generation',
            );
        checkpoints.reached('staging');
    }
}

function linkOrCopy(src: string, dst: string): void {
    try {
        linkSync(src, dst);
    } catch (e) {
        const code = (e as NodeJS.ErrnoException).code;
        if (code !== 'EPERM' && code !== 'ENOTSUP' && code !== 'EOPNOTSUPP' && code !== 'EMLINK') throw e;
        copyFileSync(src, dst);
        chmodSync(dst, statSync(src).mode & 0o7777);
    }
}

function lstatOrUndefined(p: string): ReturnType<typeof lstatSync> | undefined {
    try {
        return lstatSync(p);
    } catch {
        return undefined;
    }
}

function tryRmdir(dir: string): boolean {
    try {
        if (readdirSync(dir).length > 0) return false;
        rmdirSync(dir);
        return true;
    } catch {
        return false;
    }
}
