/** The `maa-ide` backend API (docs/ide.md, "Backend HTTP API"); its types and checks are @maa/protocol's. */
import {
    answers,
    traceFileContract,
    type AppInfo,
    type Contract,
    type GenerateAnswer,
    type IdeDiagnostic,
    type TraceElement,
    type TraceFile,
    type TSchema,
    type Static,
    type WorkspaceEntry,
} from '@maa/protocol';

export type FileEntry = WorkspaceEntry;
export type GenerateDiagnostic = IdeDiagnostic;
export type GenerateResult = GenerateAnswer;
export type { TraceElement, TraceFile };

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
        const body = (await response.json()) as { error?: string };
        if (body.error) message = body.error;
    } catch {
        /* not JSON */
    }
    return new Error(`${what}: ${message}`);
}

/** A JSON answer, checked against its contract (a bad answer is an error naming the field, not a crash later). */
async function json<T extends TSchema>(
    input: string,
    init: RequestInit | undefined,
    what: string,
    contract: Contract<T>,
): Promise<Static<T>> {
    const response = await fetch(input, init);
    if (!response.ok) throw await failure(response, what);
    return contract.parse(await response.json(), `${what}: the backend's answer`);
}

async function text(input: string, what: string): Promise<string> {
    const response = await fetch(input);
    if (!response.ok) throw await failure(response, what);
    return await response.text();
}

const q = encodeURIComponent;

export const api = {
    files: () => json('api/files', undefined, 'listing the workspace', answers.files),
    readFile: (path: string) => text(`api/file?path=${q(path)}`, `reading ${path}`),
    writeFile: (path: string, content: string) =>
        json(
            `api/file?path=${q(path)}`,
            {
                method: 'PUT',
                body: content,
                headers: { 'Content-Type': 'text/plain; charset=utf-8' },
            },
            `saving ${path}`,
            answers.ok,
        ),
    apps: async (): Promise<AppInfo[]> => (await json('api/apps', undefined, 'listing the applications', answers.apps)).apps,
    generate: (app: string, platform: string) =>
        json(
            'api/generate',
            {
                method: 'POST',
                body: JSON.stringify({ app, platform }),
                headers: { 'Content-Type': 'application/json' },
            },
            `generating ${app} for ${platform}`,
            answers.generate,
        ),
    generatedFile: (app: string, platform: string, path: string) =>
        text(`api/generated/file?app=${q(app)}&platform=${q(platform)}&path=${q(path)}`, `reading generated ${path}`),
    trace: (app: string, platform: string) =>
        json(`api/generated/trace?app=${q(app)}&platform=${q(platform)}`, undefined, 'reading the trace', traceFileContract),
};
