/**
 * `POST /api/test`: the stream tests (`*.stream`) of an application, as `maa-gen test APP
 * [FILE…] [--case NAME…] --format json` runs them and with the same JSON answer. The platform is
 * generated in-process by the backend's GenerationService (generator-core, as `maa-gen test`
 * does through the CLI's generate), then the time-synchronous runtime's test runner
 * (`python -m maa_timesync.streamtest BUILD --json FILE…`, the same runner the CLI starts) runs
 * the files, asynchronously: the CLI's own test command waits for Python synchronously, which a
 * server that answers other requests meanwhile cannot. A client that goes away stops the run.
 */
import { spawn } from 'node:child_process';
import { stat } from 'node:fs/promises';
import path from 'node:path';
// The subpath, not the package's index: that would load the generators (and Langium) at every maa-ide start.
import { findStreamFiles, type StreamTestResult, selectCases as selectStreamCases } from '@maa/generators-python/stream-tests';
import type { IdeDiagnostic } from '@maa/protocol';
import type { GenerationService } from './generation.js';
import { HttpError } from './http-util.js';
import type { Workspace } from './workspace.js';

/** The request body. Paths are relative to the workspace (POSIX). */
export interface StreamTestRequestBody {
    /** The application configuration (`.arcapp`). */
    app: string;
    /** The stream files to run (default: every `*.stream` below the application's model root). */
    files?: string[];
    /** Only the tests of these names (`maa-gen test --case`). */
    cases?: string[];
    /** The python-timesync platform (default `timesync`, as `maa-gen test --platform`). */
    platform?: string;
}

/** One test's result, as in `maa-gen test --format json` (`file` relative to the workspace). */
export type { StreamTestResult };

export interface StreamTestAnswer {
    /** False when the platform did not generate (no test ran; `diagnostics` says why). */
    ok: boolean;
    results: StreamTestResult[];
    summary: { passed: number; failed: number };
    diagnostics: IdeDiagnostic[];
}

function stringList(body: Record<string, unknown>, field: string): string[] | undefined {
    const v = body[field];
    if (v === undefined) return undefined;
    if (!Array.isArray(v) || !v.every((x) => typeof x === 'string' && x !== ''))
        throw new HttpError(400, `'${field}' must be an array of non-empty strings`);
    return v as string[];
}

/** The request body checked field by field (400 for what is wrong). */
export function streamTestRequest(body: Record<string, unknown>): StreamTestRequestBody {
    const { app, platform } = body;
    if (typeof app !== 'string' || app === '') throw new HttpError(400, "missing or empty string field 'app'");
    if (platform !== undefined && typeof platform !== 'string') throw new HttpError(400, "'platform' must be a string");
    const files = stringList(body, 'files');
    const cases = stringList(body, 'cases');
    return { app, ...(files ? { files } : {}), ...(cases ? { cases } : {}), ...(platform ? { platform } : {}) };
}

const summaryOf = (results: readonly StreamTestResult[]): StreamTestAnswer['summary'] => {
    const passed = results.filter((r) => r.passed).length;
    return { passed, failed: results.length - passed };
};

export class StreamTestService {
    /** @param python the Python 3.11+ that runs the build (read per run; default `$MAA_PYTHON` or `python3`, as the CLI's) */
    constructor(
        private readonly workspace: Workspace,
        private readonly generation: GenerationService,
        private readonly python: () => string = () => process.env['MAA_PYTHON'] ?? 'python3',
    ) {}

    /** Generates the platform and runs the tests; `signal` aborts the Python run. */
    async run(request: StreamTestRequestBody, signal: AbortSignal): Promise<StreamTestAnswer> {
        const files = await this.streamFiles(request);
        const generated = await this.generation.generate(request.app, request.platform ?? 'timesync');
        if (!generated.ok) return { ok: false, results: [], summary: summaryOf([]), diagnostics: generated.diagnostics };
        const chosen = files ?? (await findStreamFiles(this.generation.modelRootOf(await this.workspace.confined.resolve(request.app))));
        const results = chosen.length === 0 ? [] : selectCases(await this.runPython(generated.platformDir, chosen, signal), request.cases);
        return { ok: true, results, summary: summaryOf(results), diagnostics: generated.diagnostics };
    }

    /** The named stream files (absolute; each must be a `.stream` file of the workspace), or undefined for the default. */
    private async streamFiles(request: StreamTestRequestBody): Promise<string[] | undefined> {
        if (!request.files) return undefined;
        return Promise.all(
            request.files.map(async (rel) => {
                if (!rel.endsWith('.stream')) throw new HttpError(400, `not a stream test file (expected .stream): ${rel}`);
                const abs = await this.workspace.confined.resolve(rel, 'file');
                if (!(await stat(abs).catch(() => undefined))?.isFile()) throw new HttpError(404, `not found: ${rel}`);
                return abs;
            }),
        );
    }

    private runPython(build: string, files: readonly string[], signal: AbortSignal): Promise<StreamTestResult[]> {
        const python = this.python();
        return new Promise((resolve, reject) => {
            const child = spawn(python, ['-m', 'maa_timesync.streamtest', build, '--json', ...files], {
                cwd: build,
                env: { ...process.env, PYTHONDONTWRITEBYTECODE: '1' },
                stdio: ['ignore', 'pipe', 'pipe'],
            });
            const out: Buffer[] = [];
            const err: Buffer[] = [];
            const kill = (): void => {
                child.kill();
            };
            signal.addEventListener('abort', kill, { once: true });
            child.stdout.on('data', (c: Buffer) => out.push(c));
            child.stderr.on('data', (c: Buffer) => err.push(c));
            child.on('error', (e) => reject(new HttpError(500, `could not start ${python}: ${e.message}`)));
            child.on('close', (code) => {
                signal.removeEventListener('abort', kill);
                try {
                    const raw = JSON.parse(Buffer.concat(out).toString('utf8')) as StreamTestResult[];
                    resolve(raw.map((r) => ({ ...r, file: this.relative(r.file) })));
                } catch {
                    const stderr = Buffer.concat(err).toString('utf8').trim();
                    reject(new HttpError(500, `the stream test runner failed (exit ${code}): ${stderr}`));
                }
            });
        });
    }

    private relative(file: string): string {
        const rel = path.relative(this.workspace.root, file);
        return rel.startsWith('..') || path.isAbsolute(rel) ? file : rel.split(path.sep).join('/');
    }
}

/** The results of the named tests (all when none is named), as `maa-gen test --case` (@maa/generators-python's selection): a name no file has a test of is refused (400). */
export function selectCases(results: readonly StreamTestResult[], cases: readonly string[] | undefined): StreamTestResult[] {
    return selectStreamCases(results, cases, (message) => new HttpError(400, message));
}
