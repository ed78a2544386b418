import { existsSync, statSync } from 'node:fs';
import { stat } from 'node:fs/promises';
import path from 'node:path';
import type { CheckDiagnostic } from '@maa/language-server';
import type { GenerateAnswer, IdeDiagnostic } from '@maa/protocol';
import { MODEL_ROOT_MARKER, resolveModelRoot } from '@maa/language-server/model-root';
import { ConfinedRoot, checkRelativePath } from './confinement.js';
import { HttpError } from './http-util.js';
import type { Workspace } from './workspace.js';

export type { GenerateAnswer, IdeDiagnostic } from '@maa/protocol';

/** The folder of a generated platform (absolute) next to what the answer reports. */
export interface GenerationOutcome extends GenerateAnswer {
    platformDir: string;
}

/** One run of generator-core's orchestrator, as plain data (it can be sent to a worker thread). */
export interface GenerateJob {
    appFile: string;
    modelRoot: string;
    platform: string;
    outDir: string;
    discoveryRoots: readonly string[];
}

/** What a run gives back, as plain data: its diagnostics and the platform's files, or an input error (a 400). */
export type GenerateJobResult =
    | { kind: 'done'; ok: boolean; diagnostics: CheckDiagnostic[]; files: string[] | undefined }
    | { kind: 'input-error'; message: string };

/** Runs one GenerateJob (in-process by default; the lab server runs them in worker threads). */
export type GenerateRunner = (job: GenerateJob) => Promise<GenerateJobResult>;

/** Runs one GenerateJob in this thread: fresh language services, generator-core's orchestrator. */
export async function runGenerateJob(job: GenerateJob): Promise<GenerateJobResult> {
    const [{ createMaaServices }, { generate, GenerateInputError }, { NodeFileSystem }] = await Promise.all([
        import('@maa/language-server'),
        import('@maa/generator-core/node'),
        import('langium/node'),
    ]);
    try {
        const result = await generate({
            services: createMaaServices(NodeFileSystem),
            appFile: job.appFile,
            modelRoot: job.modelRoot,
            platforms: [job.platform],
            outDir: job.outDir,
            discoveryRoots: job.discoveryRoots,
        });
        const generated = result.platforms.find((p) => p.platform === job.platform);
        return {
            kind: 'done',
            ok: result.ok,
            diagnostics: result.diagnostics.map((d) => ({ ...d })),
            files: generated ? [...generated.files] : undefined,
        };
    } catch (e) {
        if (e instanceof GenerateInputError) return { kind: 'input-error', message: e.message };
        throw e;
    }
}

/**
 * Runs generator-core's orchestrator for the workspace's applications (in-process unless a runner
 * is given), one run at a time (a queue): two runs must not interleave their transactions on one
 * output folder, and the language services are not shared between runs (every run loads the
 * model root afresh).
 */
export class GenerationService {
    private queue: Promise<unknown> = Promise.resolve();

    /**
     * @param outRoot the backend's output folder: `<app path>/<platform>/` below it
     * @param discoveryRoots further folders generators are discovered from (the backend's installation)
     * @param runner runs one generator run (default: in this thread, runGenerateJob)
     */
    constructor(
        private readonly workspace: Workspace,
        readonly outRoot: string,
        private readonly discoveryRoots: readonly string[],
        private readonly runner: GenerateRunner = runGenerateJob,
    ) {}

    /** The output folder (of every platform) of an application, after checking the app path's syntax. */
    appOutDir(app: string): string {
        return path.join(this.outRoot, ...checkRelativePath(app, 'app'));
    }

    /** Confinement for reading one generated platform's files. */
    platformRoot(app: string, platform: string): ConfinedRoot {
        checkPlatformName(platform);
        return new ConfinedRoot(path.join(this.appOutDir(app), platform), `the generated output of ${app} (${platform})`);
    }

    generate(app: string, platform: string): Promise<GenerationOutcome> {
        const run = this.queue.then(() => this.run(app, platform));
        this.queue = run.catch(() => undefined);
        return run;
    }

    private async run(app: string, platform: string): Promise<GenerationOutcome> {
        checkPlatformName(platform);
        if (!app.endsWith('.arcapp')) throw new HttpError(400, `not an application configuration (expected .arcapp): ${app}`);
        const appFile = await this.workspace.confined.resolve(app, 'app');
        if (!existsSync(appFile) || !statSync(appFile).isFile()) throw new HttpError(404, `not found: ${app}`);
        const outDir = this.appOutDir(app);
        const result = await this.runner({
            appFile,
            modelRoot: this.modelRootOf(appFile),
            platform,
            outDir,
            discoveryRoots: this.discoveryRoots,
        });
        if (result.kind === 'input-error') throw new HttpError(400, result.message);
        const platformDir = path.join(outDir, platform);
        const files = result.files
            ? await Promise.all(
                  [...result.files].sort().map(async (f) => ({ path: f, size: (await stat(path.join(platformDir, f))).size })),
              )
            : [];
        return { ok: result.ok, platform, files, diagnostics: result.diagnostics.map((d) => this.toIde(d)), platformDir };
    }

    /**
     * The model root of the app by the one rule of `resolveModelRoot` (docs/user-guide.md, "Model
     * roots"), inside the workspace; an `.arcapp` declares no package, so nothing is read.
     */
    modelRootOf(appFile: string): string {
        const posix = (p: string): string => p.split(path.sep).join('/');
        const root = resolveModelRoot(posix(appFile), {
            hasMarker: (folder) => existsSync(path.join(folder, MODEL_ROOT_MARKER)),
            stopAt: posix(path.resolve(this.workspace.root)),
        });
        return path.resolve(root.split('/').join(path.sep) || path.sep);
    }

    private toIde(d: CheckDiagnostic): IdeDiagnostic {
        const rel = path.relative(this.workspace.root, d.file);
        const file = rel.startsWith('..') || path.isAbsolute(rel) ? d.file : rel.split(path.sep).join('/');
        return {
            file,
            range: {
                start: { line: Math.max(0, d.line - 1), character: Math.max(0, d.column - 1) },
                end: { line: Math.max(0, d.endLine - 1), character: Math.max(0, d.endColumn - 1) },
            },
            severity: d.severity,
            code: d.code,
            message: d.message,
        };
    }
}

/** A platform name is one path segment (it names the output folder). */
export function checkPlatformName(platform: string): void {
    if (!/^[A-Za-z_][A-Za-z0-9_-]*$/.test(platform)) throw new HttpError(400, `invalid platform name: ${JSON.stringify(platform)}`);
}
