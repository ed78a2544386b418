// The size of a workspace after a save: its current files and bytes with the saved file replacing
// the one at its path (413 when that passes a limit; the answer says which and by how much).
import type { LabStore } from '../storage/index.js';
import { tooLarge } from './errors.js';
import type { QuotaOptions } from './options.js';

export async function checkWorkspaceSize(
    store: LabStore,
    quotas: Pick<QuotaOptions, 'workspaceBytes' | 'workspaceFiles'>,
    workspaceId: number,
    path: string,
    newBytes: number,
): Promise<void> {
    const size = await store.workspaceSize(workspaceId);
    const existing = await store.readFile(workspaceId, path);
    const oldBytes = existing?.content == null ? 0 : Buffer.byteLength(existing.content);
    const files = size.files + (existing ? 0 : 1);
    const bytes = size.bytes - oldBytes + newBytes;
    if (files > quotas.workspaceFiles)
        throw tooLarge(
            'workspaceFiles',
            quotas.workspaceFiles,
            `workspace quota: a workspace holds at most ${quotas.workspaceFiles} files and this one has ${size.files}; delete a file before adding ${path}`,
        );
    if (bytes > quotas.workspaceBytes)
        throw tooLarge(
            'workspaceBytes',
            quotas.workspaceBytes,
            `workspace quota: a workspace holds at most ${quotas.workspaceBytes} bytes; with ${path} (${newBytes} bytes) it would hold ${bytes}; delete or shorten files first`,
        );
}
