/**
 * The browser IDE's generated files, as the web entry's **Show Generated Code** and **Show Model
 * Element** need them (generated-code.ts has the commands). maa-ide keeps the generated output
 * outside the workspace and serves it (docs/ide.md "Backend HTTP API": `GET /api/generated/trace`,
 * `GET /api/generated/file`), so a generated file is a read-only document on the scheme
 * `maa-generated`: `maa-generated:/<platform>/<path>?app=<app path>`. Pure: no `vscode`, no Node
 * built-ins; `fetch` comes in.
 */
import { MODEL_ROOT_MARKER, resolveModelRoot } from '@maa/language-server/model-root';
import type { TraceFile } from '@maa/protocol';
import { failure, type Generation } from './backend.js';
import { type GeneratedLocation, generatedCodeAt, type ModelLocation, modelElementAt } from '../trace.js';

/** The URI scheme of the generated files' documents. */
export const GENERATED_SCHEME = 'maa-generated';

/** A generated file: the application (`.arcapp` path below the workspace), the platform, the path below the platform folder. */
export interface GeneratedRef {
    readonly app: string;
    readonly platform: string;
    readonly path: string;
}

/** One generation of an application for a platform (a trace belongs to one). */
export type GenerationRef = Generation;

/** The URI parts of a generated file's document (`vscode.Uri.from` takes them). */
export function generatedUriParts(ref: GeneratedRef): { scheme: string; path: string; query: string } {
    return { scheme: GENERATED_SCHEME, path: `/${ref.platform}/${ref.path}`, query: new URLSearchParams({ app: ref.app }).toString() };
}

/** The generated file a document URI names; undefined for another scheme or a malformed URI. */
export function parseGeneratedUri(uri: { scheme: string; path: string; query: string }): GeneratedRef | undefined {
    if (uri.scheme !== GENERATED_SCHEME) return undefined;
    const app = new URLSearchParams(uri.query).get('app');
    const match = /^\/([^/]+)\/(.+)$/.exec(uri.path);
    if (!app || !match?.[1] || !match[2]) return undefined;
    return { app, platform: match[1], path: match[2] };
}

/** The folders from the app's folder up to the workspace root (where `maa.json` may be), nearest first. */
export function markerFolders(appFile: string, root: string): string[] {
    const top = root.replace(/\/+$/, '');
    const folders: string[] = [];
    for (let dir = appFile.slice(0, appFile.lastIndexOf('/')); dir.length >= top.length && dir.startsWith(top); ) {
        folders.push(dir);
        if (dir === top) break;
        dir = dir.slice(0, dir.lastIndexOf('/'));
    }
    return folders;
}

/** The marker file of a folder (`<folder>/maa.json`). */
export function markerOf(folder: string): string {
    return `${folder}/${MODEL_ROOT_MARKER}`;
}

/**
 * The model root of an application (an absolute `.arcapp` path below `root`) by maa-ide's rule
 * (the nearest folder with `maa.json`, else the app's folder); `markers` are the folders that hold one.
 */
export function appModelRoot(appFile: string, root: string, markers: ReadonlySet<string>): string {
    return resolveModelRoot(appFile, { hasMarker: (folder) => markers.has(folder), stopAt: root });
}

/**
 * A trace as the workspace sees it: its model root (relative to maa-ide's output folder, which the
 * browser does not know) replaced by the app's model root in the workspace, and `/<platform>` as its
 * platform folder, so that generated files are the paths of their `maa-generated` URIs.
 */
export interface WorkspaceTrace {
    readonly generation: GenerationRef;
    readonly trace: TraceFile;
    readonly platformDir: string;
}

export function workspaceTrace(generation: GenerationRef, trace: TraceFile, modelRoot: string): WorkspaceTrace {
    return { generation, trace: { ...trace, modelRoot }, platformDir: `/${generation.platform}` };
}

/** A generated location with the generated file it is in. */
export interface GeneratedHit extends GeneratedLocation {
    readonly ref: GeneratedRef;
}

/** Model → generated: the generated lines of the innermost element at `pos` in `modelFile` (a workspace path). */
export function generatedHits(w: WorkspaceTrace, modelFile: string, pos: { line: number; character: number }): GeneratedHit[] {
    const prefix = `${w.platformDir}/`;
    return generatedCodeAt(w.trace, w.platformDir, modelFile, pos).map((g) => ({
        ...g,
        ref: { ...w.generation, path: g.file.slice(prefix.length) },
    }));
}

/** Generated → model: the model element (its workspace path and range) the 0-based `line` of a generated file comes from. */
export function modelElementOf(w: WorkspaceTrace, path: string, line: number): ModelLocation | undefined {
    return modelElementAt(w.trace, w.platformDir, `${w.platformDir}/${path}`, line);
}

/** The backend's generated output (`base`: backendBase()). */
export class GeneratedOutput {
    constructor(
        private readonly base: string,
        private readonly fetchFn: typeof fetch = (input, init) => fetch(input, init),
    ) {}

    /** The trace of a generation; undefined when the app has not been generated for the platform (404). */
    async trace(g: GenerationRef): Promise<TraceFile | undefined> {
        const response = await this.fetchFn(`${this.base}/api/generated/trace?${new URLSearchParams({ ...g })}`);
        if (response.status === 404) return undefined;
        if (!response.ok) throw await failure(response, `reading the trace of ${g.app} (${g.platform})`);
        return (await response.json()) as TraceFile;
    }

    /** A generated file's text. */
    async file(ref: GeneratedRef): Promise<string> {
        const response = await this.fetchFn(`${this.base}/api/generated/file?${new URLSearchParams({ ...ref })}`);
        if (!response.ok) throw await failure(response, `reading ${ref.path} generated from ${ref.app} (${ref.platform})`);
        return response.text();
    }
}
