/**
 * The desktop StreamTestRunner: `maa-gen test APP.arcapp FILE… [--case NAME…] --format json`,
 * run with the command **MontiArc: Generate** uses (settings.ts `generateCommand`), in the
 * application's folder; aborting kills the child.
 */
import { execFile } from 'node:child_process';
import path from 'node:path';
import { parseTestReport } from './report.js';
import type { StreamTestReport } from './report.js';
import { type StreamTestRequest, type StreamTestRunner, withUris } from './runner.js';

/** The arguments of `maa-gen test` for a request (file system paths); `python`: the `--python` to pass, if any. */
export function testArgs(request: StreamTestRequest, python?: string): string[] {
    return [
        'test',
        request.app.fsPath,
        ...request.files.map((f) => f.fsPath),
        ...request.cases.flatMap((c) => ['--case', c]),
        ...(python ? ['--python', python] : []),
        '--format',
        'json',
    ];
}

export class CliStreamTestRunner implements StreamTestRunner {
    /**
     * @param command the `maa-gen` executable (resolved per run: settings may change)
     * @param python the Python to run the build with (empty: the CLI's default, `$MAA_PYTHON` or `python3`)
     */
    constructor(
        private readonly command: () => string,
        private readonly python: () => string = () => '',
    ) {}

    run(request: StreamTestRequest, signal: AbortSignal): Promise<StreamTestReport> {
        const command = this.command();
        const cwd = path.dirname(request.app.fsPath);
        return new Promise((resolve, reject) => {
            if (signal.aborted) {
                reject(new Error('cancelled'));
                return;
            }
            const child = execFile(
                command,
                testArgs(request, this.python()),
                { cwd, maxBuffer: 64 * 1024 * 1024, shell: process.platform === 'win32' },
                (error, stdout, stderr) => {
                    signal.removeEventListener('abort', kill);
                    if (signal.aborted) {
                        reject(new Error('cancelled'));
                        return;
                    }
                    try {
                        const report = parseTestReport(stdout, stderr);
                        resolve(withUris(report, request.files, (file, ref) => path.resolve(cwd, file) === path.resolve(ref.fsPath)));
                    } catch (e) {
                        reject(error && !stdout && !stderr ? new Error(`could not run ${command}: ${error.message}`) : e);
                    }
                },
            );
            const kill = (): void => {
                child.kill();
            };
            signal.addEventListener('abort', kill, { once: true });
        });
    }
}
