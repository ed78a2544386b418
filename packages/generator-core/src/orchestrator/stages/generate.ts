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

/** One platform's generation under way: what its generators are given, and what they have produced. */
interface PlatformGeneration {
    readonly run: GenerationRun;
    readonly info: PlatformInfo;
    readonly architecture: Checked['architecture'];
    readonly selection: PlatformSelection;
    readonly instances: ReadonlyMap<string, GeneratorInstance>;
    readonly collector: OutputCollector;
    readonly diagnostics: GenerationDiagnostic[];
}

/** A platform's files: its generators run, their files finished (traced), the files per generator reported. */
async function generatePlatform(
    run: GenerationRun,
    info: PlatformInfo,
    checked: Checked,
    selection: PlatformSelection,
    instances: ReadonlyMap<string, GeneratorInstance>,
): Promise<StageResult<PlatformOutput>> {
    const p = selection.platform;
    const g: PlatformGeneration = {
        run,
        info,
        architecture: checked.architecture,
        selection,
        instances,
        collector: new OutputCollector(),
        diagnostics: [],
    };
    const generated = await timedAsync(run, 'generate', () => runGenerators(g));
    if (!generated) return failure(g.diagnostics);
    let files: FinishedFile[];
    try {
        files = timed(run, 'trace', () => g.collector.finish());
    } catch (e) {
        return failure([...g.diagnostics, generatorFailure(run.modelRoot, selection, undefined, e)]);
    }
    const counts = filesPerGenerator(selection, files);
    reportFileCounts(run, p, counts);
    return outcome({ platform: p, outDir: path.join(run.outRoot, p.name), files, generators: counts }, g.diagnostics);
}

/** The data type generator, then (unless it failed) the component generator; true if no generator failed. */
async function runGenerators(g: PlatformGeneration): Promise<boolean> {
    const datatypes = await generateDataTypes(g);
    if (hasErrors(g.diagnostics)) return false;
    await generateComponents(g, datatypes);
    return !hasErrors(g.diagnostics);
}

/** Runs one generator's `body`, reporting progress; a failure becomes a diagnostic and `undefined`. */
async function runGenerator<T>(g: PlatformGeneration, inst: GeneratorInstance, body: () => Promise<T>): Promise<T | undefined> {
    const name = inst.registered.manifest.name;
    const p = g.selection.platform;
    g.run.progress({ phase: 'generate', message: `${p.name}: running ${name}`, platform: p.name, generator: name });
    try {
        return await body();
    } catch (e) {
        g.diagnostics.push(generatorFailure(g.run.modelRoot, g.selection, name, e));
        return undefined;
    }
}

async function generateDataTypes(g: PlatformGeneration): Promise<DataTypeResult | undefined> {
    const { architecture, collector } = g;
    const dt = g.instances.get(g.selection.datatype!.manifest.name)!;
    return (await runGenerator(
        g,
        dt,
        async () =>
            (await (dt.generator as DataTypeGenerator).generate({
                architecture,
                platform: g.info,
                out: collector.sink(dt.registered.manifest.name, dt.templates),
                templates: dt.templates,
                dataTypes: architecture.dataTypes,
            })) ?? {},
    )) as DataTypeResult | undefined;
}

/**
 * The component generator, which asks for each component's behavior (delegated once per
 * component to the behavior generator of its language), then the failures of those behaviors.
 */
async function generateComponents(g: PlatformGeneration, datatypes: DataTypeResult | undefined): Promise<void> {
    const { architecture, collector, selection, instances, info } = g;
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
    await runGenerator(g, comp, async () =>
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
            g.diagnostics.push(generatorFailure(g.run.modelRoot, selection, comp.registered.manifest.name, settled.reason));
    }
}

/** How many files each generator of the platform wrote, once per generator in the order the platform names them. */
function filesPerGenerator(selection: PlatformSelection, files: readonly FinishedFile[]): PlatformOutput['generators'] {
    return selection.references
        .filter((r, i, all) => all.findIndex((q) => q.generator === r.generator) === i)
        .map((r) => ({
            name: r.generator.manifest.name,
            kind: r.generator.manifest.kind,
            files: files.filter((f) => f.generator === r.generator.manifest.name).length,
        }));
}

function reportFileCounts(run: GenerationRun, p: AppPlatform, counts: PlatformOutput['generators']): void {
    for (const c of counts) {
        run.progress({
            phase: 'generate',
            message: `${p.name}: ${c.name}: ${c.files} file${c.files === 1 ? '' : 's'}`,
            platform: p.name,
            generator: c.name,
            files: c.files,
        });
    }
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
