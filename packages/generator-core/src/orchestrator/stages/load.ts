import path from 'node:path';
import { URI } from 'langium';
import { checkRoots, CheckInputError, type CheckDiagnostic } from '@maa/language-adl';
import { arcAppServices, type ArcAppServices } from '../../app/arcapp-module.js';
import type { Application, ArcAppModel } from '../../generated/ast.js';
import { discoverGenerators, installationRoot } from '../../registry/discovery.js';
import type { GeneratorRegistry } from '../../registry/registry.js';
import { at } from '../diagnostics.js';
import { GenCodes } from '../gen-codes.js';
import { failure, outcome, timed, timedAsync, type GenerationRun, type StageResult } from '../run.js';
import { GenerateInputError } from '../types.js';

/** The loaded model root: the application, the generators it can name, the languages' diagnostics. */
export interface Loaded {
    readonly app: Application;
    readonly registry: GeneratorRegistry;
    /** The `.arcapp` language's services (its generator registry and application analysis). */
    readonly arcApp: ArcAppServices;
    /** Every diagnostic of the model root's files (the languages' checks, the editor's `app/` checks). */
    readonly found: readonly CheckDiagnostic[];
}

/** The family's `.arcapp` services, or an input error naming what is missing. */
export function arcAppOf(run: GenerationRun): ArcAppServices {
    const services = arcAppServices(run.options.services.shared);
    if (!services)
        throw new GenerateInputError('the language family has no .arcapp language (register @maa/generator-core in its maa.family)');
    return services;
}

/**
 * Load: discover the generators (unless given), configure the family's registry service with
 * them, load and check the model root (the configuration is one of its files) and find the
 * application the configuration declares. Throws GenerateInputError for an unreadable root.
 */
export async function load(run: GenerationRun): Promise<StageResult<Loaded>> {
    const { options, modelRoot, appFile } = run;
    const arcApp = arcAppOf(run);
    const shared = options.services.shared;
    const registry = timed(run, 'discover', () => {
        run.progress({ phase: 'load', message: 'discovering generators' });
        const installed = installationRoot();
        const found =
            options.registry ??
            discoverGenerators(shared.workspace.FileSystemProvider, URI.file(modelRoot), {
                extraRoots: [...(installed ? [installed] : []), ...(options.discoveryRoots ?? []).map((d) => URI.file(path.resolve(d)))],
            });
        arcApp.generators.Registry.configure(found);
        return found;
    });
    const found = await timedAsync(run, 'load', async () => {
        try {
            return await checkRoots(options.services, [{ root: modelRoot }], {
                onProgress: (m) => run.progress({ phase: 'load', message: m }),
            });
        } catch (e) {
            if (e instanceof CheckInputError) throw new GenerateInputError(e.message);
            throw e;
        }
    });
    const doc = shared.workspace.LangiumDocuments.getDocument(URI.file(appFile));
    const app = (doc?.parseResult.value as ArcAppModel | undefined)?.application;
    if (!doc || !app) {
        const diagnostics = found.filter((d) => d.file === appFile);
        if (!diagnostics.some((d) => d.severity === 'error')) {
            diagnostics.push(
                at(
                    modelRoot,
                    appFile,
                    undefined,
                    'error',
                    GenCodes.NoApplication,
                    'The file declares no application (`application NAME for COMPONENT { platform P { ... } }`).',
                ),
            );
        }
        return failure(diagnostics);
    }
    return outcome({ app, registry, arcApp, found });
}
