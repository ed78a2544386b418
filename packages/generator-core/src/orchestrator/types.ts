import type { AstNode } from 'langium';
import type { CheckDiagnostic, HostLanguageServices } from '@maa/language-adl';
import type { GeneratorManifest } from '../manifest/manifest.js';
import type { GeneratorRegistry } from '../registry/registry.js';

/** A problem found while generating: a model diagnostic, an `app/` finding or a `gen/` error. */
export type GenerationDiagnostic = CheckDiagnostic;

/** Thrown by a generator to report a problem on a model element (reported as `gen/generator-failed`). */
export class GenerationError extends Error {
    constructor(
        message: string,
        readonly node?: AstNode,
    ) {
        super(message);
        this.name = 'GenerationError';
    }
}

/** A problem with the input itself (missing file, unknown platform): a message for the user. */
export class GenerateInputError extends Error {}

export interface GenerationProgress {
    readonly phase: 'load' | 'check' | 'instantiate' | 'generate' | 'write';
    readonly message: string;
    readonly platform?: string;
    readonly generator?: string;
    /** Files a generator produced (phase `generate`, once the generator is done). */
    readonly files?: number;
}

export interface GenerateOptions {
    /** The services of a language family that registers the `.arcapp` language. */
    readonly services: HostLanguageServices;
    /** The application configuration file. */
    readonly appFile: string;
    /** The model root the configuration's names resolve in (default: the configuration's folder). */
    readonly modelRoot?: string;
    /** The platforms to generate (default: every platform of the configuration). */
    readonly platforms?: readonly string[];
    /** Output folder: platform P is written to `<outDir>/<P>`. */
    readonly outDir: string;
    /** The generators (default: discovered from installed packages, from the model root upwards). */
    readonly registry?: GeneratorRegistry;
    /** Further folders to discover generators from (generator-core's own installation always is one). */
    readonly discoveryRoots?: readonly string[];
    /** Loads a generator's entry module (default: dynamic import). */
    readonly loadModule?: (url: string) => Promise<unknown>;
    readonly onProgress?: (progress: GenerationProgress) => void;
    /** How paths appear in messages about the output (default: absolute), e.g. relative to the current folder. */
    readonly displayPath?: (absolutePath: string) => string;
}

export interface PlatformResult {
    readonly platform: string;
    readonly outDir: string;
    readonly files: readonly string[];
    readonly generators: ReadonlyArray<{ readonly name: string; readonly kind: GeneratorManifest['kind']; readonly files: number }>;
    readonly written: readonly string[];
    readonly unchanged: readonly string[];
    readonly kept: readonly string[];
    readonly removed: readonly string[];
    readonly preservedRegions: number;
    /** No longer generated, but kept because of user content in protected regions. */
    readonly keptStale: readonly string[];
}

/** Milliseconds per phase (for the benchmark). */
export type GenerationTimings = Record<'discover' | 'load' | 'check' | 'instantiate' | 'generate' | 'trace' | 'write', number>;

export interface GenerateResult {
    /** No errors: every platform was generated and written. */
    readonly ok: boolean;
    readonly diagnostics: readonly GenerationDiagnostic[];
    readonly platforms: readonly PlatformResult[];
    /** Milliseconds per phase (for the benchmark). */
    readonly timings: Readonly<GenerationTimings>;
}
