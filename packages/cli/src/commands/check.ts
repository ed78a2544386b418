import path from 'node:path';
import { Command, Option } from 'commander';
import type { RootSpec } from '@maa/language-server';
import { CliError, ExitCode } from '../errors.js';
import { formatJson } from '../format/json.js';
import { displayPath, formatDiagnosticsText, formatSummaryText } from '../format/text.js';
import { loadChecker } from '../check-loader.js';
import type { CliIo } from '../io.js';
import { createProgress } from '../progress.js';
import { MODEL_FILE_EXTENSIONS, resolveRoots } from '../roots.js';
import { listModelFiles, sortDiagnostics, summarize } from '../summary.js';

export type CheckFormat = 'text' | 'json';

export interface CheckOptions {
    format: CheckFormat;
}

/**
 * `maa-gen check [--format text|json] PATH...`: checks model roots and reports diagnostics.
 * Returns the exit code: 0 without errors, 1 with errors; usage and I/O problems throw.
 */
export async function runCheck(paths: readonly string[], options: CheckOptions, io: CliIo): Promise<ExitCode> {
    const roots = resolveRoots(paths, io.cwd);
    refuseRootsWithoutModels(roots, io.cwd);
    const progress = createProgress(io);
    let found: Awaited<ReturnType<typeof import('@maa/language-server').checkModelRoots>>;
    try {
        progress?.update('loading the language services');
        // Loaded on demand, so that --help and usage errors stay fast (the one-module bundle
        // where the build wrote one: see check-loader.ts).
        const { checkModelRoots, CheckInputError } = await loadChecker(io.env);
        try {
            found = await checkModelRoots(roots, progress ? { onProgress: (msg) => progress.update(msg) } : {});
        } catch (e) {
            // An I/O problem met while checking (e.g. an unreadable file): its message is for the user.
            if (e instanceof CheckInputError) throw new CliError(e.message);
            throw e;
        }
    } finally {
        progress?.done();
    }
    const diagnostics = sortDiagnostics(found, roots);
    const summary = summarize(diagnostics, roots);

    if (options.format === 'json') {
        io.out(formatJson(diagnostics, summary));
    } else {
        const color = io.stdoutIsTTY && !io.env['NO_COLOR'];
        io.out(formatDiagnosticsText(diagnostics, { cwd: io.cwd, color }));
        io.err(`${formatSummaryText(summary)}\n`);
    }
    return summary.errors > 0 ? ExitCode.errors : ExitCode.ok;
}

/**
 * A folder argument without a single model file is almost always a wrong path (the parent or a
 * sibling of the project): said plainly, exit 2, instead of a clean "0 errors in 0 files".
 */
function refuseRootsWithoutModels(roots: readonly RootSpec[], cwd: string): void {
    const empty = roots.filter((r) => r.files === undefined && listModelFiles(r.root).length === 0);
    if (empty.length === 0) return;
    const shown = (root: string): string => (root === path.resolve(cwd) ? '.' : displayPath(root, cwd));
    throw new CliError(
        empty.map((r) => `no models found in ${shown(r.root)} (no ${MODEL_FILE_EXTENSIONS.join(', ')} files below it)`).join('\n'),
    );
}

export function checkCommand(io: CliIo, setExitCode: (code: ExitCode) => void): Command {
    return new Command('check')
        .description('check model roots (folders) or single model files and report diagnostics')
        .argument(
            '<paths...>',
            'model roots or model files: each folder is an independent model root; a file is checked ' +
                'within its folder and only its own diagnostics are reported',
        )
        .addOption(new Option('-f, --format <format>', 'output format').choices(['text', 'json']).default('text'))
        .addHelpText(
            'after',
            `
Output:
  text  one line per diagnostic on stdout, "file:line:col: severity code message"
        (paths relative to the current folder), then a summary line on stderr
  json  exactly one object on stdout: {"diagnostics": [...], "summary": {...}}

Exit codes:
  0  no errors (warnings and infos allowed)
  1  at least one error
  2  usage or I/O problem (missing path, unreadable file, a folder without models)
  3  internal error (a bug; MAA_GEN_DEBUG=1 prints the stack trace)

Examples:
  maa-gen check examples/toast-service
  maa-gen check --format json models/a models/b
  maa-gen check models/a/toast/Controller.arc`,
        )
        .action(async (paths: string[], options: CheckOptions) => {
            setExitCode(await runCheck(paths, options, io));
        });
}
