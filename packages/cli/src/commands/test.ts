import { spawnSync } from 'node:child_process';
import { mkdtempSync, rmSync, statSync } from 'node:fs';
import { tmpdir } from 'node:os';
import path from 'node:path';
import { Command, Option } from 'commander';
import type { StreamTestResult } from '@maa/generators-python';
import type { CheckDiagnostic } from '@maa/language-server';
import { CliError, ExitCode } from '../errors.js';
import { appFileArg, modelRootOfApp } from '../roots.js';
import { jsonDiagnostic } from '../format/json.js';
import { displayPath, formatDiagnosticsText } from '../format/text.js';
import type { CliIo } from '../io.js';
import { exitCodeOf, runGenerator } from './generate.js';

export interface TestCommandOptions {
    platform: string;
    out?: string;
    root?: string;
    python?: string;
    format: 'text' | 'json';
    /** Only the tests of these names (`--case`, repeatable); every test when empty or absent. */
    case?: string[];
}

/**
 * `maa-gen test APP.arcapp [FILE.stream...]`: generates the application's python-timesync
 * platform and runs the stream tests (`*.stream` next to the models) against it.
 */
export async function runTest(appArg: string, files: string[], options: TestCommandOptions, io: CliIo): Promise<ExitCode> {
    const { appFile, modelRoot } = resolveApp(appArg, options, io);
    const streamFiles = await resolveStreamFiles(files, modelRoot, io);
    const json = options.format === 'json';
    const tempOut = options.out ? undefined : mkdtempSync(path.join(tmpdir(), 'maa-gen-test-'));
    const outDir = options.out ? path.resolve(io.cwd, options.out) : tempOut!;
    try {
        const result = await runGenerator({ appFile, modelRoot, outDir }, [options.platform], false, io);
        const diagnostics: CheckDiagnostic[] = [...result.diagnostics];
        if (!result.ok) {
            if (json) reportJson([], diagnostics, false, io);
            else io.out(formatDiagnosticsText(diagnostics, { cwd: io.cwd, color: false }));
            io.err('maa-gen test: generation failed; no stream test was run\n');
            return exitCodeOf(false, diagnostics);
        }
        if (streamFiles.length === 0) {
            io.err(`maa-gen test: no .stream files in ${displayPath(modelRoot, io.cwd)}\n`);
            if (json) reportJson([], diagnostics, true, io);
            return ExitCode.ok;
        }
        const results = await selectCases(runStreamTests(path.join(outDir, options.platform), streamFiles, options, io), options.case);
        const failed = results.filter((r) => !r.passed).length;
        if (json) reportJson(results, diagnostics, true, io);
        else reportText(results, io);
        return failed === 0 ? ExitCode.ok : ExitCode.errors;
    } finally {
        if (tempOut) rmSync(tempOut, { recursive: true, force: true });
    }
}

/** The application file and its model root; usage problems throw. */
function resolveApp(appArg: string, options: TestCommandOptions, io: CliIo): { appFile: string; modelRoot: string } {
    const appFile = appFileArg(appArg, io.cwd);
    const modelRoot = options.root ? path.resolve(io.cwd, options.root) : modelRootOfApp(appFile);
    return { appFile, modelRoot };
}

/** The named stream files (each must exist), or every one below the model root. */
async function resolveStreamFiles(files: readonly string[], modelRoot: string, io: CliIo): Promise<string[]> {
    if (files.length === 0) return (await generatorsPython()).findStreamFiles(modelRoot);
    const streamFiles = files.map((f) => path.resolve(io.cwd, f));
    for (const f of streamFiles) {
        try {
            statSync(f);
        } catch {
            throw new CliError(`path not found: ${displayPath(f, io.cwd)}`);
        }
    }
    return streamFiles;
}

/** Runs the time-synchronous RTE's stream test runner on a generated build; one result per test. */
function runStreamTests(build: string, streamFiles: readonly string[], options: TestCommandOptions, io: CliIo): StreamTestResult[] {
    const python = options.python ?? io.env['MAA_PYTHON'] ?? 'python3';
    const run = spawnSync(python, ['-m', 'maa_timesync.streamtest', build, '--json', ...streamFiles], {
        cwd: build,
        encoding: 'utf8',
        env: { ...io.env, PYTHONDONTWRITEBYTECODE: '1' },
    });
    if (run.error) throw new CliError(`could not start ${python}: ${run.error.message}`);
    try {
        return JSON.parse(run.stdout) as StreamTestResult[];
    } catch {
        throw new CliError(`the stream test runner failed (exit ${run.status}):\n${run.stderr.trim()}`, ExitCode.internal);
    }
}

/** The results of the tests `--case` names (@maa/generators-python's selection); a name no file has a test of is a usage problem. */
export async function selectCases(results: readonly StreamTestResult[], cases: readonly string[] | undefined): Promise<StreamTestResult[]> {
    return (await generatorsPython()).selectStreamCases(results, cases, (message) => new CliError(message));
}

/**
 * @maa/generators-python, loaded on demand: a static import made every command, `check` and
 * `--help` included, load the whole generator and language family first (issue 18).
 */
function generatorsPython(): Promise<typeof import('@maa/generators-python')> {
    return import('@maa/generators-python');
}

/**
 * `--format json`: exactly one object on stdout, also when the models do not generate (then
 * `summary.generated` is false, `results` empty and `diagnostics` says why; docs/cli.md).
 */
function reportJson(results: readonly StreamTestResult[], diagnostics: readonly CheckDiagnostic[], generated: boolean, io: CliIo): void {
    const passed = results.filter((r) => r.passed).length;
    const summary = { generated, passed, failed: results.length - passed };
    const report = {
        diagnostics: diagnostics.map(jsonDiagnostic),
        results: results.map((r) => ({ ...r, file: displayPath(r.file, io.cwd) })),
        summary,
    };
    io.out(`${JSON.stringify(report, null, 2)}\n`);
}

function reportText(results: readonly StreamTestResult[], io: CliIo): void {
    for (const r of results) {
        io.out(`${r.passed ? 'ok  ' : 'FAIL'} ${displayPath(r.file, io.cwd)}:${r.line}${r.test ? ` ${r.test}` : ''}\n`);
        for (const p of r.problems) io.out(`       ${p}\n`);
    }
    const passed = results.filter((r) => r.passed).length;
    io.err(`stream tests: ${passed} passed, ${results.length - passed} failed\n`);
}

export function testCommand(io: CliIo, setExitCode: (code: ExitCode) => void): Command {
    return new Command('test')
        .description('run the stream tests (*.stream) of an application on its python-timesync build')
        .argument('<app>', 'the application configuration file (APP.arcapp)')
        .argument('[files...]', 'stream test files (default: every *.stream file of the model root)')
        .option('-p, --platform <name>', 'the platform to test (a python-timesync platform)', 'timesync')
        .option('-o, --out <dir>', 'keep the generated build in DIR/<platform> (default: a temporary folder)')
        .option('-r, --root <dir>', 'model root (default: the nearest folder above the .arcapp with a maa.json, else its folder)')
        .option('--python <interpreter>', 'Python 3.11+ to run the build (default: $MAA_PYTHON or python3)')
        .addOption(new Option('-f, --format <format>', 'output format').choices(['text', 'json']).default('text'))
        .option(
            '-c, --case <name>',
            'report only the test of this name (repeatable; default: every test of the files)',
            (name: string, previous: string[] = []) => [...previous, name],
        )
        .addHelpText(
            'after',
            `
What it does:
  generates the platform (like "maa-gen generate --platform"), then runs every test of the
  stream test files against the generated components: input streams per port in, output
  streams per port compared item by item (docs/generating-timesync.md describes the format).

Exit codes:
  0  every test passed
  1  a test failed, or the models do not generate
  2  usage or I/O problem
  3  internal error

Examples:
  maa-gen test examples/toast-service/TR.arcapp
  maa-gen test TR.arcapp toast/Controller.stream --format json
  maa-gen test TR.arcapp toast/Controller.stream --case "a plate starts loading the bread"`,
        )
        .action(async (app: string, files: string[], options: TestCommandOptions) => {
            setExitCode(await runTest(app, files, options, io));
        });
}
