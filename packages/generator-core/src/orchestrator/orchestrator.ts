import { existsSync, statSync } from 'node:fs';
import path from 'node:path';
import { setVariant } from '@maa/language-adl';
import { TRACE_FILE } from '../output/writer.js';
import { sortDiagnostics } from './diagnostics.js';
import { createRun, type GenerationRun, type StageResult } from './run.js';
import { check } from './stages/check.js';
import { configure } from './stages/configure.js';
import { generateFiles } from './stages/generate.js';
import { arcAppOf, load } from './stages/load.js';
import { select } from './stages/select.js';
import { write } from './stages/write.js';
import { GenerateInputError, type GenerateOptions, type GenerateResult, type GenerationDiagnostic, type PlatformResult } from './types.js';

export * from './types.js';
export type { StageResult } from './run.js';

/**
 * The generation pipeline of ARCHITECTURE.md section 6, as stages (./stages/), each returning
 * its product or the diagnostics that stop generation:
 * load (the model root and the generators) → check (the application, once; its architecture
 * model, built once) → select (the generators of each platform) → configure (instantiate them,
 * check the rules their code defines) → generate (in memory) → write (trace files, one
 * transaction over all platform folders). Nothing is written when any stage fails.
 */
export async function generate(options: GenerateOptions): Promise<GenerateResult> {
    const previous = setVariant(undefined);
    try {
        return await pipeline(prepare(options));
    } finally {
        setVariant(previous);
    }
}

/** The run of the given options, or GenerateInputError for a missing file or a family without `.arcapp`. */
function prepare(options: GenerateOptions): GenerationRun {
    const appFile = path.resolve(options.appFile);
    if (!existsSync(appFile) || !statSync(appFile).isFile()) throw new GenerateInputError(`no such file: ${options.appFile}`);
    const modelRoot = path.resolve(options.modelRoot ?? path.dirname(appFile));
    if (!appFile.startsWith(modelRoot + path.sep))
        throw new GenerateInputError(`${options.appFile} lies outside the model root ${modelRoot}`);
    const run = createRun(options, appFile, modelRoot);
    arcAppOf(run);
    return run;
}

async function pipeline(run: GenerationRun): Promise<GenerateResult> {
    const diagnostics: GenerationDiagnostic[] = [];
    const done = (platforms?: PlatformResult[]): GenerateResult => ({
        ok: platforms !== undefined,
        diagnostics: sortDiagnostics(diagnostics),
        platforms: platforms ?? [],
        timings: run.timings,
    });
    const take = <T>(result: StageResult<T>): T | undefined => {
        diagnostics.push(...result.diagnostics);
        return result.ok ? result.value : undefined;
    };

    const loaded = take(await load(run));
    if (!loaded) return done();
    const checked = take(check(run, loaded));
    if (!checked) return done();
    // The generators read the model in the application's feature configuration (restored by generate()).
    setVariant(checked.variant.env);
    const selected = take(select(loaded, checked));
    if (!selected) return done();
    const configured = take(await configure(run, checked, selected));
    if (!configured) return done();
    const generated = take(await generateFiles(run, loaded, checked, selected, configured));
    if (!generated) return done();
    return done(take(write(run, loaded, checked, selected, configured, generated)));
}

export { TRACE_FILE };
