// The IDE's file routes on a lab workspace (docs/ide.md "Backend HTTP API", below the
// workspace's prefix): the same answers as maa-ide's, with the files in the database. Every save
// and delete is a revision; the exercise's read-only files are refused (403), a save past the
// workspace quota too (413).
import { isReadOnly } from '@maa/protocol/exercise';
import type { FilesAnswer, WorkspaceEntry } from '@maa/protocol';
import { HttpError, readBody, sendJson, sendText } from '@maa/ide-server/http';
import { listApps, requireQuery } from '@maa/ide-server';
import type { AuthedRequest, LabRoutes } from '../http/routes.js';
import { checkWorkspaceSize, type QuotaOptions } from '../quotas/index.js';
import { InvalidPathError, type FileRevisionInfo } from '../storage/index.js';
import { checkWorkspacePath } from '../storage/paths.js';
import type { RuntimePool } from './pool.js';
import { type OpenedWorkspace, openWorkspaceFor, requireOwner, WS_PREFIX } from './resolve.js';

const OK = { ok: true } as const;

export function addFileRoutes(routes: LabRoutes, pool: RuntimePool, quotas: QuotaOptions): void {
    const route = (method: string, path: string, handler: (r: AuthedRequest, opened: OpenedWorkspace) => Promise<void>) =>
        routes.add({
            method,
            path: `${WS_PREFIX}${path}`,
            access: 'user',
            handler: async (r) => handler(r, await openWorkspaceFor(r.store, r.auth, r.params)),
        });

    route('GET', '/files', async ({ res, store }, opened) => {
        const files = await store.listFiles(opened.workspace.id);
        sendJson(res, 200, { root: opened.exercise.name, entries: entriesOf(files) } satisfies FilesAnswer);
    });
    route('GET', '/file', async ({ res, store, url }, opened) => {
        const rel = filePath(url);
        const file = await withPathCheck(() => store.readFile(opened.workspace.id, rel));
        if (!file) throw new HttpError(404, `not found: ${rel}`);
        sendText(res, 200, file.content ?? '');
    });
    route('PUT', '/file', async ({ req, res, store, url, auth }, opened) => {
        const rel = writablePath(opened, url, 'save files');
        const body = await readBody(req, quotas.workspaceBytes);
        const content = utf8(body, rel);
        await checkWorkspaceSize(store, quotas, opened.workspace.id, rel, body.length);
        await withPathCheck(() => store.saveFile({ workspaceId: opened.workspace.id, path: rel, content, authorId: auth.user.id }));
        sendJson(res, 200, OK);
    });
    route('DELETE', '/file', async ({ res, store, url, auth }, opened) => {
        const rel = writablePath(opened, url, 'delete files');
        // A folder (the explorer deletes them): every file below it.
        const files = await store.listFiles(opened.workspace.id);
        const targets = files.filter((f) => f.path === rel || f.path.startsWith(`${rel}/`)).map((f) => f.path);
        if (targets.length === 0) throw new HttpError(404, `not found: ${rel}`);
        const locked = targets.filter((p) => isReadOnly(opened.spec, p));
        if (locked.length > 0) throw readOnlyError(opened, locked[0] as string);
        for (const p of targets) await store.deleteFile({ workspaceId: opened.workspace.id, path: p, authorId: auth.user.id });
        sendJson(res, 200, OK);
    });
    route('GET', '/apps', async ({ res }, opened) => {
        const runtime = pool.get(opened);
        const apps = await runtime.use(async () => {
            await runtime.folder.sync();
            return listApps(runtime.ide);
        });
        sendJson(res, 200, { apps });
    });
}

/** Every current file and the folders they lie in, sorted by path (as maa-ide lists a folder). */
export function entriesOf(files: readonly FileRevisionInfo[]): WorkspaceEntry[] {
    const entries = new Map<string, WorkspaceEntry>();
    for (const f of files) {
        const segments = f.path.split('/');
        for (let i = 1; i < segments.length; i++) {
            const dir = segments.slice(0, i).join('/');
            if (!entries.has(dir)) entries.set(dir, { path: dir, type: 'directory' });
        }
        entries.set(f.path, { path: f.path, type: 'file', size: f.size });
    }
    return [...entries.values()].sort((a, b) => (a.path < b.path ? -1 : a.path > b.path ? 1 : 0));
}

/** The `path` query parameter, a workspace path (400 otherwise). */
function filePath(url: URL): string {
    const rel = requireQuery(url.searchParams, 'path');
    try {
        return checkWorkspacePath(rel);
    } catch (e) {
        if (e instanceof InvalidPathError) throw new HttpError(400, e.message);
        throw e;
    }
}

/** The path of a save or delete: the owner's, not hidden, not read-only. */
function writablePath(opened: OpenedWorkspace, url: URL, what: string): string {
    requireOwner(opened, what);
    const rel = filePath(url);
    const hidden = rel.split('/').find((s) => s.startsWith('.'));
    if (hidden !== undefined)
        throw new HttpError(403, `${rel}: hidden files and folders (here ${hidden}) cannot be written through the IDE`);
    if (isReadOnly(opened.spec, rel)) throw readOnlyError(opened, rel);
    return rel;
}

function readOnlyError(opened: OpenedWorkspace, rel: string): HttpError {
    return new HttpError(
        403,
        `${rel} is part of the exercise ${opened.exercise.name} and read-only (exercise.json readOnly); edit the other files`,
    );
}

function utf8(body: Buffer, rel: string): string {
    try {
        return new TextDecoder('utf-8', { fatal: true }).decode(body);
    } catch {
        throw new HttpError(400, `${rel}: a workspace file must be UTF-8 text`);
    }
}

/** A path storage refuses (absolute, `..`, control characters) is a 400. */
async function withPathCheck<T>(body: () => Promise<T>): Promise<T> {
    try {
        return await body();
    } catch (e) {
        if (e instanceof InvalidPathError) throw new HttpError(400, e.message);
        throw e;
    }
}
