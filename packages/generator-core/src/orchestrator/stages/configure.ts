import { existsSync } from 'node:fs';
import path from 'node:path';
import { pathToFileURL } from 'node:url';
import { checkGeneratorRules } from '../../app/app-checks.js';
import type { Generator, WellFormednessRule } from '../../generators/types.js';
import type { RegisteredGenerator } from '../../registry/registry.js';
import { standardRule } from '../../rules/standard-rules.js';
import { createTemplateRenderer } from '../../templates/environment.js';
import { findingDiagnostic, nodeDiagnostic } from '../diagnostics.js';
import { GenCodes } from '../gen-codes.js';
import { failure, hasErrors, outcome, timed, timedAsync, type GeneratorInstance, type GenerationRun, type StageResult } from '../run.js';
import type { GenerationDiagnostic } from '../types.js';
import type { Checked } from './check.js';
import type { Selected } from './select.js';

/** The generators of every platform, instantiated (each once, by name). */
export interface Configured {
    readonly instances: ReadonlyMap<string, GeneratorInstance>;
}

/**
 * Configure: load and instantiate the selected generators (each once), then check the
 * well-formedness rules that only their code defines (the standard rules were checked with the
 * application, in the check stage) and report checks that nobody defines.
 */
export async function configure(run: GenerationRun, checked: Checked, selected: Selected): Promise<StageResult<Configured>> {
    const { modelRoot } = run;
    const diagnostics: GenerationDiagnostic[] = [];
    const instances = new Map<string, GeneratorInstance>();
    await timedAsync(run, 'instantiate', async () => {
        for (const [p, selection] of selected.selections) {
            for (const { ref, generator } of selection.references) {
                if (instances.has(generator.manifest.name)) continue;
                run.progress({
                    phase: 'instantiate',
                    message: `loading ${generator.manifest.name}`,
                    platform: p.name,
                    generator: generator.manifest.name,
                });
                try {
                    instances.set(generator.manifest.name, await instantiate(generator, run.options.loadModule));
                } catch (e) {
                    diagnostics.push(
                        nodeDiagnostic(
                            modelRoot,
                            ref,
                            'error',
                            GenCodes.LoadFailed,
                            `Generator '${generator.manifest.name}' (package ${generator.source.packageName}) cannot be loaded: ${(e as Error).message}`,
                        ),
                    );
                }
            }
        }
    });
    if (hasErrors(diagnostics)) return failure(diagnostics);
    timed(run, 'check', () => {
        const rule = (generator: string, name: string): WellFormednessRule | undefined =>
            instances.get(generator)?.generator.rules?.find((r) => r.name === name);
        for (const selection of selected.selections.values()) {
            const findings = checkGeneratorRules(selection, checked.architecture, {
                rule,
                only: (name) => !standardRule(name),
                onUnknownRule: (g, name, ref) =>
                    diagnostics.push(
                        nodeDiagnostic(
                            modelRoot,
                            ref,
                            'error',
                            GenCodes.UnknownCheck,
                            `Generator '${g.manifest.name}' declares the check '${name}', which neither the standard rules nor the generator define.`,
                        ),
                    ),
            });
            for (const f of findings) diagnostics.push(findingDiagnostic(modelRoot, f));
        }
    });
    return outcome({ instances }, diagnostics);
}

/** Loads a generator's entry module and instantiates its export with the manifest and a template renderer. */
export async function instantiate(
    g: RegisteredGenerator,
    load: ((url: string) => Promise<unknown>) | undefined,
): Promise<GeneratorInstance> {
    const m = g.manifest;
    const entry = path.resolve(g.source.packageDir, m.entry);
    if (!load && !existsSync(entry)) throw new Error(`its entry module ${m.entry} does not exist (${entry})`);
    const mod = (await (load ?? ((u: string) => import(u)))(pathToFileURL(entry).href)) as Record<string, unknown>;
    const exported = mod[m.export ?? 'default'];
    if (exported === undefined) throw new Error(`its entry module ${m.entry} has no export '${m.export ?? 'default'}'`);
    const templates = createTemplateRenderer(m.templates ? path.resolve(g.source.packageDir, m.templates) : undefined);
    const generator = (
        typeof exported === 'function'
            ? await (exported as (i: object) => unknown)({ manifest: m, packageDir: g.source.packageDir, templates })
            : exported
    ) as Generator;
    if (!generator || typeof (generator as { generate?: unknown }).generate !== 'function') {
        throw new Error(
            `its export '${m.export ?? 'default'}' is not a generator (an object with a generate function, or a function returning one)`,
        );
    }
    if (generator.kind !== undefined && generator.kind !== m.kind) {
        throw new Error(`its code implements a ${generator.kind} generator, but its manifest declares kind '${m.kind}'`);
    }
    return { registered: g, generator, templates };
}
