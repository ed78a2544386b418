// `POST <prefix>/reset` (instructors): the student's workspace becomes a fresh copy of the
// exercise's newest starter, as new revisions by the instructor (deleted: files the starter does
// not have; saved: starter files whose content differs), so the history keeps what was there.
// A running simulation of the workspace ends first.
import { HttpError, sendJson } from '@maa/ide-server/http';
import type { LabRoutes } from '../http/routes.js';
import type { LabStore } from '../storage/index.js';
import type { RuntimePool } from './pool.js';
import { type OpenedWorkspace, openWorkspaceFor, WS_PREFIX } from './resolve.js';
import type { LabSimulations } from './simulations.js';

export interface ResetOutcome {
    starterVersion: number;
    saved: string[];
    deleted: string[];
}

export function addResetRoute(routes: LabRoutes, pool: RuntimePool, sims: LabSimulations): void {
    routes.add({
        method: 'POST',
        path: `${WS_PREFIX}/reset`,
        access: 'instructor',
        handler: async ({ res, store, auth, params }) => {
            const opened = await openWorkspaceFor(store, auth, params);
            const runtime = pool.find(opened.workspace.id);
            if (runtime?.sim) await sims.stop(runtime, 'the workspace was reset');
            sendJson(res, 200, { ok: true, ...(await resetWorkspace(store, opened, auth.user.id)) });
        },
    });
}

export async function resetWorkspace(store: LabStore, opened: OpenedWorkspace, authorId: number): Promise<ResetOutcome> {
    const starter = await store.starterVersion(opened.exercise.id);
    if (!starter) throw new HttpError(409, `the exercise ${opened.exercise.name} has no starter`);
    const workspaceId = opened.workspace.id;
    const deleted: string[] = [];
    const saved: string[] = [];
    for (const file of await store.listFiles(workspaceId)) {
        if (file.path in starter.files) continue;
        await store.deleteFile({ workspaceId, path: file.path, authorId });
        deleted.push(file.path);
    }
    for (const [path, content] of Object.entries(starter.files)) {
        const current = await store.readFile(workspaceId, path);
        if (current?.content !== content) {
            await store.saveFile({ workspaceId, path, content, authorId });
            saved.push(path);
        }
        await store.setStarterFile(workspaceId, { path, baseVersion: starter.version, conflictVersion: null });
    }
    return { starterVersion: starter.version, saved, deleted };
}
