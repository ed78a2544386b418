/**
 * The browser IDE's StreamTestRunner: the backend's `POST /api/test` (docs/ide.md), which
 * answers what `maa-gen test --format json` prints, with paths relative to the workspace.
 * Aborting the signal aborts the request, and the backend stops the Python run. Pure (fetch only).
 */
import type { StreamTestReport, StreamTestResult } from './report.js';
import { type FileRef, type StreamTestRequest, type StreamTestRunner, withUris } from './runner.js';

/** The backend's answer (`ok` false: the platform did not generate, `diagnostics` say why). */
interface TestAnswer extends StreamTestReport {
    readonly ok: boolean;
    readonly diagnostics?: ReadonlyArray<{
        readonly file: string;
        readonly range: { readonly start: { readonly line: number } };
        readonly severity: string;
        readonly message: string;
    }>;
}

function isAnswer(x: unknown): x is TestAnswer {
    const a = x as Partial<TestAnswer> | null;
    return typeof a === 'object' && a !== null && typeof a.ok === 'boolean' && Array.isArray(a.results) && typeof a.summary === 'object';
}

/** The message of a generation that failed: its errors, one a line (`file:line: message`). */
export function generationFailure(answer: TestAnswer): Error {
    const errors = (answer.diagnostics ?? []).filter((d) => d.severity === 'error');
    const lines = errors.map((d) => `${d.file}:${d.range.start.line + 1}: ${d.message}`);
    return new Error(['generation failed; no stream test was run', ...lines].join('\n'));
}

export class WebStreamTestRunner implements StreamTestRunner {
    /**
     * @param base the backend's base URL (web/backend.ts `backendBase()`)
     * @param root the workspace folder's path (`/workspace` in the browser IDE): file paths below it are sent relative
     */
    constructor(
        private readonly base: string,
        private readonly root: string,
        // a wrapper, not `fetch` itself: a browser's fetch called as a method of this object
        // throws "Illegal invocation" (Node's does not, so only the browser host shows it)
        private readonly fetchFn: typeof fetch = (input, init) => fetch(input, init),
    ) {}

    /** A file's path below the workspace folder. */
    relative(ref: FileRef): string {
        const prefix = `${this.root.replace(/\/+$/, '')}/`;
        return ref.path.startsWith(prefix) ? ref.path.slice(prefix.length) : ref.path.replace(/^\/+/, '');
    }

    async run(request: StreamTestRequest, signal: AbortSignal): Promise<StreamTestReport> {
        const body = {
            app: this.relative(request.app),
            files: request.files.map((f) => this.relative(f)),
            ...(request.cases.length > 0 ? { cases: request.cases } : {}),
        };
        const response = await this.fetchFn(`${this.base}/api/test`, {
            method: 'POST',
            body: JSON.stringify(body),
            headers: { 'Content-Type': 'application/json' },
            signal,
        });
        let answer: unknown;
        try {
            answer = await response.json();
        } catch {
            answer = undefined;
        }
        if (!response.ok) {
            const error = (answer as { error?: unknown } | undefined)?.error;
            throw new Error(`testing ${body.app}: ${typeof error === 'string' ? error : `${response.status} ${response.statusText}`}`);
        }
        if (!isAnswer(answer)) throw new Error(`testing ${body.app}: the backend's answer is no test report`);
        if (!answer.ok) throw generationFailure(answer);
        const report: StreamTestReport = { results: answer.results as readonly StreamTestResult[], summary: answer.summary };
        return withUris(report, request.files, (file, ref) => file === this.relative(ref));
    }
}
