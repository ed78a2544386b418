/**
 * Codes of problems met while generating (`maa-gen generate`), beyond the models' and the
 * configuration's diagnostics. Documented in docs/generating.md. Never rename one.
 */
export const GenCodes = {
    /** The configuration file declares no application. */
    NoApplication: 'gen/no-application',
    /** A generator's entry module cannot be loaded or does not export a generator of the declared kind. */
    LoadFailed: 'gen/load-failed',
    /** A manifest names a check that neither the standard rules nor the generator's code define. */
    UnknownCheck: 'gen/unknown-check',
    /** A generator threw (reported on the model element when it names one, else on the generator). */
    GeneratorFailed: 'gen/generator-failed',
    /** A generator wrote an invalid path, or a path another generator wrote. */
    InvalidOutput: 'gen/invalid-output',
    /** A regenerated file no longer has a protected region that holds user content (nothing is written). */
    ProtectedRegionDropped: 'gen/protected-region-dropped',
    /** (warning) A file no longer generated was kept because it holds user content in protected regions. */
    StaleFileKept: 'gen/stale-file-kept',
    /** The output could not be written (nothing was changed). */
    WriteFailed: 'gen/write-failed',
} as const;

export type GenCode = (typeof GenCodes)[keyof typeof GenCodes];
