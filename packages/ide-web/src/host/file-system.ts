/**
 * The workspace served by the backend (`GET /api/files`, `GET|PUT|DELETE /api/file`) as a VS Code
 * file system provider for `file:///workspace/…`, laid over the workbench's `file` scheme: the
 * explorer, the editors, Save and the extension's `workspace.fs` all go through it. Paths outside
 * /workspace answer "not found", so the overlay falls through to the workbench's own files.
 */
import { Emitter } from '@codingame/monaco-vscode-api/vscode/vs/base/common/event';
import type { URI } from '@codingame/monaco-vscode-api/vscode/vs/base/common/uri';
import {
    FileChangeType,
    FilePermission,
    FileSystemProviderCapabilities,
    FileSystemProviderError,
    FileSystemProviderErrorCode,
    FileType,
    type IFileChange,
    type IFileSystemProviderWithFileReadWriteCapability,
    type IStat,
} from '@codingame/monaco-vscode-files-service-override';
import { api } from '../api.js';
import { type EntryType, WorkspaceTree } from './workspace-tree.js';

/** The workspace folder's path in the workbench (the old IDE's URIs use the same). */
export const WORKSPACE_ROOT = '/workspace';

const fileType = (type: EntryType): FileType => (type === 'directory' ? FileType.Directory : FileType.File);

/** Which files the user may not change (lab mode: the exercise's read-only files; all, for an instructor's view). */
export type ReadOnlyRule = (path: string) => boolean;

export class BackendFileSystem implements IFileSystemProviderWithFileReadWriteCapability {
    readonly capabilities = FileSystemProviderCapabilities.FileReadWrite | FileSystemProviderCapabilities.PathCaseSensitive;
    private readonly changes = new Emitter<readonly IFileChange[]>();
    readonly onDidChangeFile = this.changes.event;
    readonly onDidChangeCapabilities = new Emitter<void>().event;

    private constructor(
        private readonly tree: WorkspaceTree,
        private readonly readOnly: ReadOnlyRule,
    ) {}

    /** The provider over the backend's current listing; `readOnly` files open as read-only editors. */
    static async load(readOnly: ReadOnlyRule = () => false): Promise<BackendFileSystem> {
        const listing = await api.files();
        return new BackendFileSystem(new WorkspaceTree(listing.entries), readOnly);
    }

    /** The model files of the workspace (paths below the root), for the language server to see at start. */
    files(): string[] {
        const out: string[] = [];
        const walk = (dir: string): void => {
            for (const [name, type] of this.tree.readdir(dir) ?? []) {
                const path = dir ? `${dir}/${name}` : name;
                if (type === 'directory') walk(path);
                else out.push(path);
            }
        };
        walk('');
        return out;
    }

    watch(): { dispose(): void } {
        // The backend has no change feed; the tree follows what goes through this provider.
        return { dispose: () => undefined };
    }

    async stat(resource: URI): Promise<IStat> {
        const path = this.pathOf(resource);
        const stat = this.tree.stat(path);
        if (!stat) throw FileSystemProviderError.create(`not found: ${resource.path}`, FileSystemProviderErrorCode.FileNotFound);
        return {
            type: fileType(stat.type),
            size: stat.size,
            mtime: stat.mtime,
            ctime: 0,
            ...(stat.type === 'file' && this.readOnly(path) ? { permissions: FilePermission.Readonly } : {}),
        };
    }

    async readdir(resource: URI): Promise<[string, FileType][]> {
        const children = this.tree.readdir(this.pathOf(resource));
        if (!children)
            throw FileSystemProviderError.create(`not a folder: ${resource.path}`, FileSystemProviderErrorCode.FileNotADirectory);
        return children.map(([name, type]) => [name, fileType(type)]);
    }

    async readFile(resource: URI): Promise<Uint8Array> {
        const path = this.pathOf(resource);
        if (this.tree.stat(path)?.type !== 'file')
            throw FileSystemProviderError.create(`not found: ${resource.path}`, FileSystemProviderErrorCode.FileNotFound);
        return new TextEncoder().encode(await api.readFile(path));
    }

    async writeFile(resource: URI, content: Uint8Array): Promise<void> {
        const path = this.pathOf(resource);
        this.refuseReadOnly(path);
        const existed = this.tree.stat(path) !== undefined;
        await api.writeFile(path, new TextDecoder().decode(content));
        this.tree.written(path, content.byteLength);
        this.changes.fire([{ resource, type: existed ? FileChangeType.UPDATED : FileChangeType.ADDED }]);
    }

    async mkdir(resource: URI): Promise<void> {
        // The backend makes folders when a file is written into them; until then the folder lives here.
        this.tree.created(this.pathOf(resource));
    }

    async delete(resource: URI): Promise<void> {
        const path = this.pathOf(resource);
        const stat = this.tree.stat(path);
        if (!stat) throw FileSystemProviderError.create(`not found: ${resource.path}`, FileSystemProviderErrorCode.FileNotFound);
        if (stat.type === 'file') {
            this.refuseReadOnly(path);
            const response = await fetch(`api/file?path=${encodeURIComponent(path)}`, { method: 'DELETE' });
            if (!response.ok)
                throw FileSystemProviderError.create(
                    `deleting ${path}: ${response.status} ${response.statusText}`,
                    FileSystemProviderErrorCode.Unknown,
                );
        } else if ((this.tree.readdir(path) ?? []).length > 0) {
            throw FileSystemProviderError.create(
                `deleting a folder with files is not supported: ${path}`,
                FileSystemProviderErrorCode.NoPermissions,
            );
        }
        this.tree.removed(path);
        this.changes.fire([{ resource, type: FileChangeType.DELETED }]);
    }

    async rename(from: URI): Promise<void> {
        throw FileSystemProviderError.create(
            `renaming is not supported by the backend: ${from.path}`,
            FileSystemProviderErrorCode.NoPermissions,
        );
    }

    private refuseReadOnly(path: string): void {
        if (this.readOnly(path))
            throw FileSystemProviderError.create(`${path} is read-only in this exercise`, FileSystemProviderErrorCode.NoPermissions);
    }

    /** The path below the workspace root; "not found" for anything else (the overlay's next provider answers). */
    private pathOf(resource: URI): string {
        const p = resource.path;
        if (p === WORKSPACE_ROOT) return '';
        if (p.startsWith(`${WORKSPACE_ROOT}/`)) return p.slice(WORKSPACE_ROOT.length + 1);
        throw FileSystemProviderError.create(`not in the workspace: ${p}`, FileSystemProviderErrorCode.FileNotFound);
    }
}
