import { statSync } from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { Command, Option } from 'commander';
import type { CheckDiagnostic } from '@maa/language-server';
import { CliError, ExitCode } from '../errors.js';
import { appFileArg, modelRootOfApp } from '../roots.js';
import { jsonDiagnostic } from '../format/json.js';
import { displayPath, formatDiagnosticsText } from '../format/text.js';
import type { CliIo } from '../io.js';
import { createProgress } from '../progress.js';
import { loadGenerateServices } from '../generate-loader.js';

export type GenerateFormat = 'text' | 'json';

/** GenCodes.WriteFailed of @maa/generator-core (not imported: the generator core is loaded on demand). */
const WRITE_FAILED = 'gen/write-failed';

export interface GenerateCommandOptions {
    platform?: string[];
    out?: string;
    root?: string;
    format: GenerateFormat;
}

/** The folder of this CLI's package: generators installed next to maa-gen are found too. */
function installationDir(): string {
    return path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..', '..');
}

/** The outcome of @maa/generator-core's generate (a type only: the module is loaded on demand). */
type GenerateResult = Awaited<ReturnType<typeof import('@maa/generator-core/node').generate>>;

/** Where generation reads and writes, resolved against the current folder. */
export interface GenerateInputs {
    readonly appFile: string;
    readonly modelRoot: string;
    readonly outDir: string;
}

/**
 * `maa-gen generate APP.arcapp [--platform P]... [--out DIR] [--root DIR]`: generates code for
 * the platforms of an application configuration. Exit 0 when generated (warnings allowed),
 * 1 when checks or a generator failed, 2 when the output cannot be written (nothing is written
 * then: the diagnostic `gen/write-failed` names the path); usage problems throw.
 */
export async function runGenerate(appArg: string, options: GenerateCommandOptions, io: CliIo): Promise<ExitCode> {
    const inputs = resolveInputs(appArg, options, io);
    const json = options.format === 'json';
    const result = await runGenerator(inputs, options.platform, !json, io);
    const diagnostics: CheckDiagnostic[] = [...result.diagnostics];
    if (json) reportJson(result, diagnostics, io);
    else reportText(result, diagnostics, io);
    return exitCodeOf(result.ok, diagnostics);
}

/** The application file, model root and output folder of the command line; usage problems throw. */
function resolveInputs(appArg: string, options: GenerateCommandOptions, io: CliIo): GenerateInputs {
    const appFile = appFileArg(appArg, io.cwd);
    const modelRoot = options.root ? path.resolve(io.cwd, options.root) : modelRootOfApp(appFile);
    if (options.root && !isDirectory(modelRoot)) throw new CliError(`model root not found: ${options.root}`);
    const outDir = path.resolve(io.cwd, options.out ?? path.join(path.dirname(appFile), 'generated'));
    return { appFile, modelRoot, outDir };
}

function isDirectory(p: string): boolean {
    try {
        return statSync(p).isDirectory();
    } catch {
        return false;
    }
}

/**
 * Runs the generator core with progress on stderr; with `generatorLines` (generate's text report)
 * also one line per generator there as it finishes. An input problem the core reports is a
 * usage error. Used by generate, test and sim.
 */
export async function runGenerator(
    { appFile, modelRoot, outDir }: GenerateInputs,
    platforms: string[] | undefined,
    generatorLines: boolean,
    io: CliIo,
): Promise<GenerateResult> {
    const progress = createProgress(io);
    // Per-generator lines are part of the text report (stderr), not just progress.
    const report = (line: string): void => {
        if (!generatorLines) return;
        progress?.done();
        io.err(`${line}\n`);
    };
    try {
        progress?.update('loading the language services');
        // Loaded on demand, so that --help and usage errors stay fast (the bundle where the build
        // wrote one: see generate-loader.ts).
        const { createMaaServices, generate, GenerateInputError, NodeFileSystem } = await loadGenerateServices(io.env);
        try {
            return await generate({
                services: createMaaServices(NodeFileSystem),
                appFile,
                modelRoot,
                platforms,
                outDir,
                discoveryRoots: [installationDir()],
                displayPath: (p) => displayPath(p, io.cwd),
                onProgress: (p) => {
                    if (p.phase === 'generate' && p.files !== undefined) report(`${p.message}`);
                    else progress?.update(p.message);
                },
            });
        } catch (e) {
            if (e instanceof GenerateInputError) throw new CliError(e.message);
            throw e;
        }
    } finally {
        progress?.done();
    }
}

/** The numbers of the summary: the JSON `summary` and the text report's last line. */
function countsOf(result: GenerateResult, diagnostics: readonly CheckDiagnostic[]): { errors: number; warnings: number; files: number } {
    return {
        errors: diagnostics.filter((d) => d.severity === 'error').length,
        warnings: diagnostics.filter((d) => d.severity === 'warning').length,
        files: result.platforms.reduce((n, p) => n + p.files.length, 0),
    };
}

/** `--format json`: exactly one object on stdout (docs/cli.md documents its fields). */
function reportJson(result: GenerateResult, diagnostics: readonly CheckDiagnostic[], io: CliIo): void {
    const { errors, warnings, files } = countsOf(result, diagnostics);
    io.out(
        `${JSON.stringify(
            {
                diagnostics: diagnostics.map(jsonDiagnostic),
                platforms: result.platforms.map((p) => ({
                    platform: p.platform,
                    outDir: p.outDir,
                    generators: p.generators,
                    files: p.files,
                    written: p.written,
                    unchanged: p.unchanged,
                    kept: p.kept,
                    removed: p.removed,
                    keptStale: p.keptStale,
                })),
                summary: { ok: result.ok, errors, warnings, files, platforms: result.platforms.length },
            },
            null,
            2,
        )}\n`,
    );
}

/** `--format text`: the diagnostics on stdout, a line per platform and the summary on stderr. */
function reportText(result: GenerateResult, diagnostics: readonly CheckDiagnostic[], io: CliIo): void {
    const { errors, warnings, files } = countsOf(result, diagnostics);
    const color = io.stdoutIsTTY && !io.env['NO_COLOR'];
    io.out(formatDiagnosticsText(diagnostics, { cwd: io.cwd, color }));
    for (const p of result.platforms) {
        const parts = [`${p.written.length} written`, `${p.unchanged.length} unchanged`];
        if (p.kept.length > 0) parts.push(`${p.kept.length} user file${p.kept.length === 1 ? '' : 's'} kept`);
        if (p.removed.length > 0) parts.push(`${p.removed.length} stale removed`);
        io.err(`${p.platform}: ${plural(p.files.length, 'file')} in ${displayPath(p.outDir, io.cwd)} (${parts.join(', ')})\n`);
    }
    const counts = `${plural(errors, 'error')}, ${plural(warnings, 'warning')}`;
    io.err(
        result.ok
            ? `${counts}; generated ${plural(files, 'file')} for ${plural(result.platforms.length, 'platform')}\n`
            : `${counts}; nothing was generated\n`,
    );
}

/** 0 generated; 2 when the output could not be written (an I/O problem, docs/cli.md); 1 for other errors. */
export function exitCodeOf(ok: boolean, diagnostics: readonly CheckDiagnostic[]): ExitCode {
    if (ok) return ExitCode.ok;
    return diagnostics.some((d) => d.severity === 'error' && d.code === WRITE_FAILED) ? ExitCode.usage : ExitCode.errors;
}

function plural(n: number, word: string): string {
    return `${n} ${word}${n === 1 ? '' : 's'}`;
}

export function generateCommand(io: CliIo, setExitCode: (code: ExitCode) => void): Command {
    return new Command('generate')
        .description('generate code for the platforms of an application configuration (.arcapp)')
        .argument('<app>', 'the application configuration file (APP.arcapp)')
        .addOption(
            new Option('-p, --platform <name>', 'generate this platform only (repeatable; default: every platform)').argParser(
                (value: string, previous: string[] | undefined) => [...(previous ?? []), value],
            ),
        )
        .option('-o, --out <dir>', 'output folder; platform P is written to DIR/P (default: "generated" next to the .arcapp)')
        .option(
            '-r, --root <dir>',
            'model root the names of the configuration resolve in (default: the nearest folder above the .arcapp with a maa.json, else its folder)',
        )
        .addOption(new Option('-f, --format <format>', 'output format').choices(['text', 'json']).default('text'))
        .addHelpText(
            'after',
            `
What it does:
  loads the configuration and the architecture, runs the language checks, the configuration
  checks (app/...) and the generators' own rules, then runs the data type generator and the
  component generator (which hands each behavior block to the behavior generator of its
  language) and writes every platform's files with a trace file (.maa-trace.json). Nothing is
  written when any step fails; user files and protected regions are never overwritten.
  DIR/P is a link to a version folder in DIR/.maa-gen, switched in one step, so a platform
  folder is always wholly the old or wholly the new output, even if maa-gen is killed.

Output:
  text  diagnostics on stdout ("file:line:col: severity code message"), one line per generator
        with its file count and a summary on stderr
  json  exactly one object on stdout: {"diagnostics", "platforms", "summary"}

Exit codes:
  0  generated (warnings allowed)
  1  errors in the models, the configuration or a generator: nothing was written
  2  usage or I/O problem (missing file, unknown platform, an output that cannot be
     written: gen/write-failed names the path; nothing was changed)
  3  internal error (a bug; MAA_GEN_DEBUG=1 prints the stack trace)

Examples:
  maa-gen generate examples/toast-service/TR.arcapp
  maa-gen generate TR.arcapp --platform rospython --out build/gen
  maa-gen generators            (lists the installed generators)`,
        )
        .action(async (app: string, options: GenerateCommandOptions) => {
            setExitCode(await runGenerate(app, options, io));
        });
}
