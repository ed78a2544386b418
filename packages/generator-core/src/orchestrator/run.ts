import path from 'node:path';
import { performance } from 'node:perf_hooks';
import type { AppPlatform } from '../generated/ast.js';
import type { Generator, TemplateRenderer } from '../generators/types.js';
import type { FinishedFile } from '../output/file-builder.js';
import type { RegisteredGenerator } from '../registry/registry.js';
import type { GenerateOptions, GenerationDiagnostic, GenerationProgress, GenerationTimings, PlatformResult } from './types.js';

/**
 * What a stage of the pipeline returns: its product and the diagnostics it found (warnings
 * travel with a success), or a failure with the diagnostics that stopped generation.
 */
export type StageResult<T> =
    | { readonly ok: true; readonly value: T; readonly diagnostics: readonly GenerationDiagnostic[] }
    | { readonly ok: false; readonly diagnostics: readonly GenerationDiagnostic[] };

export function hasErrors(diagnostics: readonly GenerationDiagnostic[]): boolean {
    return diagnostics.some((d) => d.severity === 'error');
}

/** A success with `value`, unless an error is among the diagnostics. */
export function outcome<T>(value: T, diagnostics: readonly GenerationDiagnostic[] = []): StageResult<T> {
    return hasErrors(diagnostics) ? { ok: false, diagnostics } : { ok: true, value, diagnostics };
}

export function failure(diagnostics: readonly GenerationDiagnostic[]): StageResult<never> {
    return { ok: false, diagnostics };
}

/** One generation: its options with the paths resolved, progress reporting and the timings. */
export interface GenerationRun {
    readonly options: GenerateOptions;
    /** The application configuration file (absolute). */
    readonly appFile: string;
    /** The model root (absolute). */
    readonly modelRoot: string;
    /** The output folder (absolute): platform P is written to `<outRoot>/<P>`. */
    readonly outRoot: string;
    readonly progress: (progress: GenerationProgress) => void;
    /** How paths appear in messages about the output. */
    readonly shown: (absolutePath: string) => string;
    readonly timings: GenerationTimings;
}

export function createRun(options: GenerateOptions, appFile: string, modelRoot: string): GenerationRun {
    return {
        options,
        appFile,
        modelRoot,
        outRoot: path.resolve(options.outDir),
        progress: options.onProgress ?? (() => undefined),
        shown: options.displayPath ?? ((p: string) => p),
        timings: { discover: 0, load: 0, check: 0, instantiate: 0, generate: 0, trace: 0, write: 0 },
    };
}

/** Runs `body`, adding its time to the phase `phase` of the run's timings. */
export function timed<T>(run: GenerationRun, phase: keyof GenerationTimings, body: () => T): T {
    const t = performance.now();
    try {
        return body();
    } finally {
        run.timings[phase] += performance.now() - t;
    }
}

/** timed for an asynchronous body. */
export async function timedAsync<T>(run: GenerationRun, phase: keyof GenerationTimings, body: () => Promise<T>): Promise<T> {
    const t = performance.now();
    try {
        return await body();
    } finally {
        run.timings[phase] += performance.now() - t;
    }
}

/** A generator instantiated from its package (configure stage). */
export interface GeneratorInstance {
    readonly registered: RegisteredGenerator;
    readonly generator: Generator;
    readonly templates: TemplateRenderer;
}

/** The generated files of one platform, in memory (generate stage). */
export interface PlatformOutput {
    readonly platform: AppPlatform;
    readonly outDir: string;
    readonly files: readonly FinishedFile[];
    readonly generators: PlatformResult['generators'];
}
