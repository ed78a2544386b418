/**
 * How stream tests run, behind one interface so that the same test controller works in VS Code
 * desktop (the `maa-gen` CLI: cli-runner.ts) and in the browser IDE (the backend's
 * `POST /api/test`: web-runner.ts). Pure (no `vscode`, no Node).
 */
import type { StreamTestReport } from './report.js';

/** A file as the editor knows it: its URI (as a string), its path (the URI's, POSIX) and its file system path. */
export interface FileRef {
    readonly uri: string;
    readonly path: string;
    readonly fsPath: string;
}

export interface StreamTestRequest {
    /** The application configuration whose `timesync` platform runs the tests. */
    readonly app: FileRef;
    /** The stream files to run. */
    readonly files: readonly FileRef[];
    /** Only the tests of these names (every test of the files when empty). */
    readonly cases: readonly string[];
}

export interface StreamTestRunner {
    /**
     * Runs the tests; the report's `file`s are the URIs of the request's files (a result of a
     * file the request did not name keeps the runner's path). Rejects with the reason when no
     * report comes (generation failed, no Python, …); aborting the signal stops the run.
     */
    run(request: StreamTestRequest, signal: AbortSignal): Promise<StreamTestReport>;
}

/** The report with each result's `file` replaced by the URI of the request file `sameFile` matches. */
export function withUris(
    report: StreamTestReport,
    files: readonly FileRef[],
    sameFile: (reported: string, ref: FileRef) => boolean,
): StreamTestReport {
    return {
        ...report,
        results: report.results.map((r) => {
            const ref = files.find((f) => sameFile(r.file, f));
            return ref ? { ...r, file: ref.uri } : r;
        }),
    };
}
