import { readFileSync, statSync, utimesSync } from 'node:fs';
import path from 'node:path';
import type { appAst } from '@maa/generator-core';
import { TRACE_FILE_NAME } from '@maa/protocol/formats';
import { findSimPackage, type SimPackageMode } from '@maa/protocol/sim-package';
import { runGenerate } from '../commands/generate.js';
import { CliError, ExitCode } from '../errors.js';
import { loadGenerateServices } from '../generate-loader.js';
import type { CliIo } from '../io.js';
import { appFileArg, modelRootOfApp } from '../roots.js';
import { listModelFiles } from '../summary.js';

/** What `maa-gen sim` runs: the generated package of one platform and its mode. */
export interface SimTarget {
    readonly platform: string;
    readonly platformDir: string;
    readonly packageDir: string;
    readonly mode: SimPackageMode;
}

export interface PrepareOptions {
    readonly platform?: string;
    readonly out?: string;
    readonly root?: string;
}

/**
 * The platform names of an application configuration, in their order (parsed, not linked). It
 * loads the generation path the generation after it uses (the bundle when current), so a cold
 * `maa-gen sim` loads the packages once, not twice; `langium` imported after that is the one the
 * generation path redirects to.
 */
export async function appPlatforms(appFile: string, env: NodeJS.ProcessEnv = process.env): Promise<string[]> {
    const { createMaaServices, NodeFileSystem } = await loadGenerateServices(env);
    const { URI } = await import('langium');
    const services = createMaaServices(NodeFileSystem);
    const document = services.shared.workspace.LangiumDocumentFactory.fromString<appAst.ArcAppModel>(
        readFileSync(appFile, 'utf8'),
        URI.file(appFile),
    );
    return document.parseResult.value.application?.platforms.map((p) => p.name) ?? [];
}

/** `--platform` checked against the application's platforms; required when there are several. */
export function choosePlatform(platforms: readonly string[], requested: string | undefined, appArg: string): string {
    if (platforms.length === 0) throw new CliError(`${appArg} declares no platform`);
    if (requested !== undefined) {
        if (!platforms.includes(requested)) {
            throw new CliError(`${appArg} has no platform ${requested} (its platforms: ${platforms.join(', ')})`);
        }
        return requested;
    }
    if (platforms.length > 1) {
        throw new CliError(`${appArg} has ${platforms.length} platforms (${platforms.join(', ')}): choose one with --platform`);
    }
    return platforms[0]!;
}

/** The newest modification time (ms) of the model files below a folder (the files `maa-gen check` reads). */
function newestModelTime(dir: string): number {
    return listModelFiles(dir).reduce((newest, file) => Math.max(newest, statSync(file).mtimeMs), 0);
}

/** Whether a platform's output is missing or older than a model file of its root (or the configuration). */
export function isStale(platformDir: string, modelRoot: string, appFile: string): boolean {
    let generated: number;
    try {
        generated = statSync(path.join(platformDir, TRACE_FILE_NAME)).mtimeMs;
    } catch {
        return true;
    }
    return Math.max(newestModelTime(modelRoot), statSync(appFile).mtimeMs) > generated;
}

/**
 * Generation leaves unchanged files (and the trace file) as they were, so a model file that was
 * saved without a change would make every later run generate again: the trace file's time says
 * when the output was last checked against the models instead.
 */
function markChecked(platformDir: string): void {
    const now = new Date();
    try {
        utimesSync(path.join(platformDir, TRACE_FILE_NAME), now, now);
    } catch {
        // no trace file: the next run generates again, which is only slower
    }
}

/** An io whose stdout goes to stderr: generation's report must not mix into the simulation's summary. */
function reportOnStderr(io: CliIo): CliIo {
    return { ...io, stdoutIsTTY: io.stderrIsTTY, out: (text) => io.err(text) };
}

/**
 * Resolves the platform and generates it when its output is missing or older than the models
 * (with `maa-gen generate`'s code path, reporting on stderr), then finds its simulator package.
 * Returns the generator's exit code instead when generation failed.
 */
export async function prepareTarget(appArg: string, options: PrepareOptions, io: CliIo): Promise<SimTarget | ExitCode> {
    const appFile = appFileArg(appArg, io.cwd);
    const platform = choosePlatform(await appPlatforms(appFile, io.env), options.platform, appArg);
    const outDir = path.resolve(io.cwd, options.out ?? path.join(path.dirname(appFile), 'generated'));
    const platformDir = path.join(outDir, platform);
    const modelRoot = options.root ? path.resolve(io.cwd, options.root) : modelRootOfApp(appFile);
    if (isStale(platformDir, modelRoot, appFile)) {
        io.err(`maa-gen: generating ${platform} (its output is missing or older than the models)\n`);
        const code = await runGenerate(
            appArg,
            { platform: [platform], out: options.out, root: options.root, format: 'text' },
            reportOnStderr(io),
        );
        if (code !== ExitCode.ok) return code;
        markChecked(platformDir);
    }
    const found = findSimPackage(platformDir);
    if (!found) {
        throw new CliError(
            `the platform ${platform} has no lockstep.json or deployment.json in ${platformDir}: its generators make nothing the simulator runs`,
        );
    }
    return { platform, platformDir, packageDir: found.dir, mode: found.mode };
}
