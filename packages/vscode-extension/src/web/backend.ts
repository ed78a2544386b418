/**
 * The browser IDE backend (`maa-ide`, docs/ide.md "Backend HTTP API") as the web entry needs it:
 * where it is, and Generate as `POST /api/generate` (the web GenerateRunner).
 */
import { answers } from '@maa/protocol';
import type { GenerateReport } from '../generate-report.js';
import { type GenerateRunner, reportFromAnswer } from '../generate-runner.js';

/** The part of `location` the backend's address comes from (typed here: this package compiles without the DOM library). */
interface PageLocation {
    readonly href: string;
}

/**
 * The backend's base URL: the folder of the page that hosts the workbench (`maa-ide` serves the
 * page and the API from one origin, `http://host:port/` → `http://host:port`; the lab's `…/ide/<course>/<exercise>/<login>/` → that folder).
 */
export function backendBase(location: PageLocation | undefined = (globalThis as { location?: PageLocation }).location): string {
    if (!location) throw new Error('the MontiArc web extension needs the page of the browser IDE (maa-ide) to find its backend');
    return new URL('.', location.href).href.replace(/\/$/, '');
}

/** The error of a refused request: the backend's `{ error }` when it sent one, else the status. */
export async function failure(response: Response, what: string): Promise<Error> {
    let message = `${response.status} ${response.statusText}`;
    try {
        const body = (await response.json()) as { error?: unknown };
        if (typeof body.error === 'string') message = body.error;
    } catch {
        /* not JSON */
    }
    return new Error(`${what}: ${message}`);
}

/** What was generated: the app (its path below the workspace) and the platform. */
export interface Generation {
    readonly app: string;
    readonly platform: string;
}

const generationListeners = new Set<(g: Generation) => void>();

/** Calls `listener` after each generation through a backendRunner (Show Generated Code follows the last one); returns its removal. */
export function onGenerated(listener: (g: Generation) => void): () => void {
    generationListeners.add(listener);
    return () => generationListeners.delete(listener);
}

/**
 * Generate through the backend. `relative` turns the picked `.arcapp` into its path below the
 * workspace (the request's `app`); `root` is the workspace folder's path, for the report's files.
 */
export function backendRunner(
    base: string,
    root: string,
    relative: (appFile: string) => string,
    fetchFn: typeof fetch = fetch,
): GenerateRunner {
    return {
        async run(request, signal): Promise<GenerateReport> {
            const what = `generating ${relative(request.appFile)} for ${request.platform}`;
            const response = await fetchFn(`${base}/api/generate`, {
                method: 'POST',
                body: JSON.stringify({ app: relative(request.appFile), platform: request.platform }),
                headers: { 'Content-Type': 'application/json' },
                signal,
            });
            if (!response.ok) throw await failure(response, what);
            for (const listener of generationListeners) listener({ app: relative(request.appFile), platform: request.platform });
            return reportFromAnswer(answers.generate.parse(await response.json(), `${what}: the backend's answer`), root);
        },
    };
}
