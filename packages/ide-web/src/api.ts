/** The `maa-ide` backend API (docs/ide.md, "Backend HTTP API"). */
import type { AppInfo, TextRange } from './contracts.js';

export interface FileEntry {
    path: string;
    type: 'file' | 'directory';
    size?: number;
}

export interface GenerateDiagnostic {
    file?: string;
    range?: TextRange;
    severity: 'error' | 'warning' | 'info' | string;
    code?: string;
    message: string;
}

export interface GenerateResult {
    ok: boolean;
    platform: string;
    files: { path: string; size: number }[];
    diagnostics: GenerateDiagnostic[];
    error?: string;
}

export interface TraceElement {
    file: string;
    /** 1-based [startLine, startColumn, endLine, endColumn]. */
    range: [number, number, number, number];
    path?: string;
    type?: string;
    name?: string;
}

export interface TraceFile {
    version: number;
    modelRoot?: string;
    files: { path: string; traces: { lines: [number, number]; element: TraceElement }[] }[];
}

export const WORKSPACE_URI = 'file:///workspace/';

export function uriOf(path: string): string {
    return WORKSPACE_URI + path.split('/').map(encodeURIComponent).join('/');
}

/** The workspace path of a `file:///workspace/...` URI, or undefined for other URIs. */
export function pathOf(uri: string): string | undefined {
    if (!uri.startsWith(WORKSPACE_URI)) return undefined;
    return uri.slice(WORKSPACE_URI.length).split('/').map(decodeURIComponent).join('/');
}

async function failure(response: Response, what: string): Promise<Error> {
    let message = `${response.status} ${response.statusText}`;
    try {
        const body = await response.json() as { error?: string };
        if (body.error) message = body.error;
    } catch { /* not JSON */ }
    return new Error(`${what}: ${message}`);
}

async function json<T>(input: string, init: RequestInit | undefined, what: string): Promise<T> {
    const response = await fetch(input, init);
    if (!response.ok) throw await failure(response, what);
    return await response.json() as T;
}

async function text(input: string, what: string): Promise<string> {
    const response = await fetch(input);
    if (!response.ok) throw await failure(response, what);
    return await response.text();
}

const q = encodeURIComponent;

export const api = {
    files: () => json<{ root: string; entries: FileEntry[] }>('api/files', undefined, 'listing the workspace'),
    readFile: (path: string) => text(`api/file?path=${q(path)}`, `reading ${path}`),
    writeFile: (path: string, content: string) => json<{ ok: boolean }>(`api/file?path=${q(path)}`, {
        method: 'PUT', body: content, headers: { 'Content-Type': 'text/plain; charset=utf-8' },
    }, `saving ${path}`),
    apps: async () => (await json<{ apps: AppInfo[] }>('api/apps', undefined, 'listing the applications')).apps,
    generate: (app: string, platform: string) => json<GenerateResult>('api/generate', {
        method: 'POST', body: JSON.stringify({ app, platform }), headers: { 'Content-Type': 'application/json' },
    }, `generating ${app} for ${platform}`),
    generatedFile: (app: string, platform: string, path: string) =>
        text(`api/generated/file?app=${q(app)}&platform=${q(platform)}&path=${q(path)}`, `reading generated ${path}`),
    trace: (app: string, platform: string) =>
        json<TraceFile>(`api/generated/trace?app=${q(app)}&platform=${q(platform)}`, undefined, 'reading the trace'),
};
