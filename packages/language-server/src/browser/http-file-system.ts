import { URI, type FileSystemNode, type FileSystemProvider } from 'langium';

/** The workspace folder the browser IDE opens: `file:///workspace/<path>` is `/api/file?path=<path>`. */
export const WORKSPACE_URI = URI.parse('file:///workspace/');

/** An entry of `GET /api/files` (docs/ide.md, "Backend HTTP API"). */
export interface WorkspaceEntry {
    readonly path: string;
    readonly type: 'file' | 'directory';
    readonly size?: number;
}

export interface HttpFileSystemOptions {
    /** Where the backend API lives (`<base>/api/files`); may be set later with setApiBase. */
    readonly apiBase?: string;
    /** The listing is fetched again when older than this (a start-up walk reuses one listing). */
    readonly listingTtlMs?: number;
    readonly fetch?: typeof fetch;
}

/**
 * The workspace as the IDE backend serves it over HTTP, for a language server in a Web Worker:
 * the workspace folder `file:///workspace/` is indexed like a folder on disk, so cross-file
 * references and model roots (`maa.json`) work as in the desktop tools. Everything outside the
 * workspace folder does not exist. The synchronous methods answer from what was fetched before
 * (the latest listing, files read before); Langium's workspace code uses the asynchronous ones.
 */
export class HttpFileSystemProvider implements FileSystemProvider {
    private apiBase: string;
    private readonly ttl: number;
    private readonly fetch: typeof fetch;
    private listing: { at: number; entries: Map<string, WorkspaceEntry>; children: Map<string, WorkspaceEntry[]> } | undefined;
    private pendingListing: Promise<NonNullable<HttpFileSystemProvider['listing']>> | undefined;
    private readonly texts = new Map<string, string>();

    constructor(options: HttpFileSystemOptions = {}) {
        this.apiBase = (options.apiBase ?? '').replace(/\/+$/, '');
        this.ttl = options.listingTtlMs ?? 1000;
        this.fetch = options.fetch ?? ((input, init) => globalThis.fetch(input, init));
    }

    setApiBase(apiBase: string): void {
        this.apiBase = apiBase.replace(/\/+$/, '');
        this.listing = undefined;
        this.texts.clear();
    }

    /** Forgets the listing (after files were created or deleted). */
    invalidate(): void {
        this.listing = undefined;
    }

    async stat(uri: URI): Promise<FileSystemNode> {
        const path = this.pathOf(uri);
        const listing = await this.fetchListing();
        return this.node(uri, path, listing.entries);
    }

    statSync(uri: URI): FileSystemNode {
        return this.node(uri, this.pathOf(uri), this.listing?.entries ?? new Map());
    }

    async exists(uri: URI): Promise<boolean> {
        const path = workspacePath(uri);
        if (path === undefined) return false;
        return path === '' || (await this.fetchListing()).entries.has(path);
    }

    existsSync(uri: URI): boolean {
        const path = workspacePath(uri);
        return path === '' || (path !== undefined && (this.listing?.entries.has(path) ?? false));
    }

    async readBinary(uri: URI): Promise<Uint8Array> {
        return new TextEncoder().encode(await this.readFile(uri));
    }

    readBinarySync(uri: URI): Uint8Array {
        return new TextEncoder().encode(this.readFileSync(uri));
    }

    async readFile(uri: URI): Promise<string> {
        const path = this.pathOf(uri);
        const response = await this.fetch(`${this.apiBase}/api/file?path=${encodeURIComponent(path)}`);
        if (!response.ok) throw new Error(`${uri.toString()}: ${response.status} ${await errorText(response)}`);
        const text = await response.text();
        this.texts.set(path, text);
        return text;
    }

    readFileSync(uri: URI): string {
        const text = this.texts.get(this.pathOf(uri));
        if (text === undefined) throw new Error(`${uri.toString()}: not read yet (only asynchronous reads go over HTTP)`);
        return text;
    }

    async readDirectory(uri: URI): Promise<FileSystemNode[]> {
        const path = this.pathOf(uri);
        return this.children(uri, path, await this.fetchListing());
    }

    readDirectorySync(uri: URI): FileSystemNode[] {
        const path = this.pathOf(uri);
        if (!this.listing) throw new Error(`${uri.toString()}: the workspace has not been listed yet`);
        return this.children(uri, path, this.listing);
    }

    private children(uri: URI, path: string, listing: NonNullable<HttpFileSystemProvider['listing']>): FileSystemNode[] {
        if (path !== '' && listing.entries.get(path)?.type !== 'directory') throw new Error(`${uri.toString()}: no such directory`);
        return (listing.children.get(path) ?? []).map((e) => ({
            isFile: e.type === 'file',
            isDirectory: e.type === 'directory',
            uri: toUri(e.path),
        }));
    }

    private node(uri: URI, path: string, entries: Map<string, WorkspaceEntry>): FileSystemNode {
        if (path === '') return { isFile: false, isDirectory: true, uri };
        const entry = entries.get(path);
        if (!entry) throw new Error(`${uri.toString()}: no such file or directory`);
        return { isFile: entry.type === 'file', isDirectory: entry.type === 'directory', uri };
    }

    private pathOf(uri: URI): string {
        const path = workspacePath(uri);
        if (path === undefined) throw new Error(`${uri.toString()}: outside the workspace ${WORKSPACE_URI.toString()}`);
        return path;
    }

    private fetchListing(): Promise<NonNullable<HttpFileSystemProvider['listing']>> {
        if (this.listing && Date.now() - this.listing.at < this.ttl) return Promise.resolve(this.listing);
        this.pendingListing ??= (async () => {
            try {
                const response = await this.fetch(`${this.apiBase}/api/files`);
                if (!response.ok) throw new Error(`listing the workspace: ${response.status} ${await errorText(response)}`);
                const body = (await response.json()) as { entries: WorkspaceEntry[] };
                const entries = new Map(body.entries.map((e) => [e.path, e]));
                const children = new Map<string, WorkspaceEntry[]>();
                for (const e of body.entries) {
                    const parent = e.path.includes('/') ? e.path.substring(0, e.path.lastIndexOf('/')) : '';
                    children.set(parent, [...(children.get(parent) ?? []), e]);
                }
                this.listing = { at: Date.now(), entries, children };
                return this.listing;
            } finally {
                this.pendingListing = undefined;
            }
        })();
        return this.pendingListing;
    }
}

/** The path below the workspace folder (`""` for the folder itself), or undefined outside it. */
export function workspacePath(uri: URI): string | undefined {
    if (uri.scheme !== WORKSPACE_URI.scheme || uri.authority !== WORKSPACE_URI.authority) return undefined;
    const root = WORKSPACE_URI.path; // '/workspace/'
    if (uri.path === root.slice(0, -1) || uri.path === root) return '';
    return uri.path.startsWith(root) ? uri.path.substring(root.length).replace(/\/+$/, '') : undefined;
}

export function toUri(path: string): URI {
    return URI.parse(`${WORKSPACE_URI.toString()}${path.split('/').map(encodeURIComponent).join('/')}`);
}

async function errorText(response: Response): Promise<string> {
    try {
        const body = (await response.json()) as { error?: string };
        return body.error ?? response.statusText;
    } catch {
        return response.statusText;
    }
}
