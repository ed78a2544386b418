import path from 'node:path';
import { generatorForLanguage, type PlatformSelection } from '../../app/app-checks.js';
import type { AppPlatform } from '../../generated/ast.js';
import type {
    BehaviorGenerationContext,
    BehaviorGenerator,
    BehaviorResult,
    ComponentGenerator,
    DataTypeGenerator,
    DataTypeResult,
    DelegatedBehavior,
    PlatformInfo,
} from '../../generators/types.js';
import type { BehaviorView, ComponentView } from '../../model/architecture.js';
import { OutputCollector, OutputError, type FinishedFile } from '../../output/file-builder.js';
import { nodeDiagnostic } from '../diagnostics.js';
import { GenCodes } from '../gen-codes.js';
import {
    failure,
    hasErrors,
    outcome,
    timed,
    timedAsync,
    type GeneratorInstance,
    type GenerationRun,
    type PlatformOutput,
    type StageResult,
} from '../run.js';
import { GenerationError, type GenerationDiagnostic } from '../types.js';
import type { Checked } from './check.js';
import type { Configured } from './configure.js';
import type { Loaded } from './load.js';
import type { Selected } from './select.js';

/** The files of every platform, generated in memory. */
export interface Generated {
    readonly outputs: readonly PlatformOutput[];
}

/** What the generators of a platform learn about it. */
export function platformInfo(loaded: Loaded, checked: Checked, p: AppPlatform): PlatformInfo {
    return { application: loaded.app.name, platform: p.name, rootComponent: checked.architecture.root.qualifiedName };
}

/**
 * Generate: per platform, run the data type generator, then the component generator, which
 * hands each behavior to the behavior generator of its language (or translates it itself), and
 * collect the files in memory. A generator's failure stops generation (nothing is written).
 */
export async function generateFiles(
    run: GenerationRun,
    loaded: Loaded,
    checked: Checked,
    selected: Selected,
    configured: Configured,
): Promise<StageResult<Generated>> {
    const outputs: PlatformOutput[] = [];
    const diagnostics: GenerationDiagnostic[] = [];
    for (const [p, selection] of selected.selections) {
        const result = await generatePlatform(run, platformInfo(loaded, checked, p), checked, selection, configured.instances);
        diagnostics.push(...result.diagnostics);
        if (!result.ok) return failure(diagnostics);
        outputs.push(result.value);
    }
    return outcome({ outputs }, diagnostics);
}

async function generatePlatform(
    run: GenerationRun,
    info: PlatformInfo,
    checked: Checked,
    selection: PlatformSelection,
    instances: ReadonlyMap<string, GeneratorInstance>,
): Promise<StageResult<PlatformOutput>> {
    const { architecture } = checked;
    const p = selection.platform;
    const diagnostics: GenerationDiagnostic[] = [];
    const collector = new OutputCollector();
    const runGenerator = async <T>(inst: GeneratorInstance, body: () => Promise<T>): Promise<T | undefined> => {
        const name = inst.registered.manifest.name;
        run.progress({ phase: 'generate', message: `${p.name}: running ${name}`, platform: p.name, generator: name });
        try {
            return await body();
        } catch (e) {
            diagnostics.push(generatorFailure(run.modelRoot, selection, name, e));
            return undefined;
        }
    };
    const generated = await timedAsync(run, 'generate', async () => {
        const dt = instances.get(selection.datatype!.manifest.name)!;
        const datatypes = (await runGenerator(
            dt,
            async () =>
                (await (dt.generator as DataTypeGenerator).generate({
                    architecture,
                    platform: info,
                    out: collector.sink(dt.registered.manifest.name, dt.templates),
                    templates: dt.templates,
                    dataTypes: architecture.dataTypes,
                })) ?? {},
        )) as DataTypeResult | undefined;
        if (hasErrors(diagnostics)) return false;

        const comp = instances.get(selection.component!.manifest.name)!;
        const delegated = new Map<ComponentView, Promise<DelegatedBehavior | undefined>>();
        const delegate = (c: ComponentView): Promise<DelegatedBehavior | undefined> => {
            let d = delegated.get(c);
            if (!d) {
                d = delegateBehavior(c, selection, instances, info, datatypes ?? {}, collector);
                delegated.set(c, d);
            }
            return d;
        };
        await runGenerator(comp, async () =>
            (comp.generator as ComponentGenerator).generate({
                architecture,
                platform: info,
                out: collector.sink(comp.registered.manifest.name, comp.templates),
                templates: comp.templates,
                datatypes: datatypes ?? {},
                behavior: delegate,
            }),
        );
        // A component generator that does not wait for its behaviors must not lose their failures.
        for (const settled of await Promise.allSettled(delegated.values())) {
            if (settled.status === 'rejected')
                diagnostics.push(generatorFailure(run.modelRoot, selection, comp.registered.manifest.name, settled.reason));
        }
        return !hasErrors(diagnostics);
    });
    if (!generated) return failure(diagnostics);
    let files: FinishedFile[];
    try {
        files = timed(run, 'trace', () => collector.finish());
    } catch (e) {
        return failure([...diagnostics, generatorFailure(run.modelRoot, selection, undefined, e)]);
    }
    const counts = selection.references
        .filter((r, i, all) => all.findIndex((q) => q.generator === r.generator) === i)
        .map((r) => ({
            name: r.generator.manifest.name,
            kind: r.generator.manifest.kind,
            files: files.filter((f) => f.generator === r.generator.manifest.name).length,
        }));
    for (const c of counts) {
        run.progress({
            phase: 'generate',
            message: `${p.name}: ${c.name}: ${c.files} file${c.files === 1 ? '' : 's'}`,
            platform: p.name,
            generator: c.name,
            files: c.files,
        });
    }
    return outcome({ platform: p, outDir: path.join(run.outRoot, p.name), files, generators: counts }, diagnostics);
}

async function delegateBehavior(
    c: ComponentView,
    selection: PlatformSelection,
    instances: ReadonlyMap<string, GeneratorInstance>,
    platform: PlatformInfo,
    datatypes: DataTypeResult,
    collector: OutputCollector,
): Promise<DelegatedBehavior | undefined> {
    const behavior: BehaviorView | undefined =
        c.behavior ?? (c.init ? { language: 'compute', node: c.init, component: c.qualifiedName } : undefined);
    if (!behavior) return undefined;
    const target = generatorForLanguage(selection, behavior.language);
    if (!target)
        throw new GenerationError(
            `no generator of platform '${platform.platform}' translates the '${behavior.language}' behavior of '${c.qualifiedName}'`,
            behavior.node,
        );
    if (target.role === 'component') return { handledBy: 'component-generator', language: behavior.language, behavior };
    const inst = instances.get(target.generator.manifest.name)!;
    const m = inst.registered.manifest;
    const requires = new Set(m.requires);
    const ctx: BehaviorGenerationContext = {
        out: collector.sink(m.name, inst.templates),
        templates: inst.templates,
        ...(requires.has('ports') ? { ports: c.ports } : {}),
        ...(requires.has('parameters') ? { parameters: c.parameters } : {}),
        ...(requires.has('fields') ? { fields: c.fields } : {}),
        ...(requires.has('component') ? { component: c } : {}),
        ...(requires.has('package') ? { packageName: c.packageName } : {}),
        ...(requires.has('platform') ? { platform } : {}),
        ...(requires.has('datatypes') ? { datatypes } : {}),
    };
    let result: BehaviorResult;
    try {
        result = (await (inst.generator as BehaviorGenerator).generate(behavior, ctx)) ?? {};
    } catch (e) {
        throw new DelegatedFailure(m.name, e);
    }
    return { handledBy: 'behavior-generator', generator: m.name, language: behavior.language, behavior, result };
}

/** A behavior generator failed while the component generator waited for it. */
class DelegatedFailure extends Error {
    constructor(
        readonly generator: string,
        readonly error: unknown,
    ) {
        super(error instanceof Error ? error.message : String(error));
    }
}

function generatorFailure(
    modelRoot: string,
    selection: PlatformSelection,
    generator: string | undefined,
    e: unknown,
): GenerationDiagnostic {
    let name = generator;
    let error = e;
    if (e instanceof DelegatedFailure) {
        name = e.generator;
        error = e.error;
    }
    const ref = selection.references.find((r) => r.generator.manifest.name === name)?.ref ?? selection.platform;
    const message = error instanceof Error ? error.message : String(error);
    if (error instanceof OutputError) return nodeDiagnostic(modelRoot, ref, 'error', GenCodes.InvalidOutput, `${message}.`);
    if (error instanceof GenerationError || (error instanceof Error && error.name === 'GenerationError')) {
        const node = (error as GenerationError).node;
        return nodeDiagnostic(modelRoot, node ?? ref, 'error', GenCodes.GeneratorFailed, `Generator '${name}': ${message}`);
    }
    const where = error instanceof Error && error.stack ? ` (${firstFrame(error.stack)})` : '';
    return nodeDiagnostic(modelRoot, ref, 'error', GenCodes.GeneratorFailed, `Generator '${name}' failed: ${message}${where}`);
}

function firstFrame(stack: string): string {
    return /\n\s+at (.+)/.exec(stack)?.[1]?.trim() ?? 'no stack';
}
