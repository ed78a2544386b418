import { existsSync, statSync } from 'node:fs';
import path from 'node:path';
import { pathToFileURL } from 'node:url';
import { performance } from 'node:perf_hooks';
import { AstUtils, GrammarUtils, URI, type AstNode, type LangiumDocument } from 'langium';
import { checkRoots, CheckInputError, type CheckDiagnostic, type HostLanguageServices, type Severity } from '@maa/language-adl';
import { applicationVariant } from '../app/app-variant.js';
import { setVariant } from '@maa/language-adl';
import { applicationArchitecture, checkApplication, generatorForLanguage, selectGenerators, type AppFinding, type PlatformSelection } from '../app/app-checks.js';
import { configureGeneratorRegistry } from '../app/registry-provider.js';
import type { AppPlatform, Application, ArcAppModel } from '../generated/ast.js';
import type {
    BehaviorGenerationContext, BehaviorGenerator, ComponentGenerator, DataTypeGenerator, DataTypeResult, DelegatedBehavior,
    Generator, PlatformInfo, TemplateRenderer, WellFormednessRule
} from '../generators/types.js';
import type { GeneratorManifest } from '../manifest/manifest.js';
import type { ArchitectureModel, BehaviorView, ComponentView } from '../model/architecture.js';
import { OutputCollector, OutputError, type FinishedFile } from '../output/file-builder.js';
import { OutputWriteError } from '../output/layout.js';
import { OutputTransaction } from '../output/transaction.js';
import { planOutput, sha256, TRACE_FILE, type WritePlan } from '../output/writer.js';
import { discoverGenerators, installationRoot } from '../registry/discovery.js';
import type { GeneratorRegistry, RegisteredGenerator } from '../registry/registry.js';
import { standardRule } from '../rules/standard-rules.js';
import { createTemplateRenderer } from '../templates/environment.js';
import { GenCodes } from './gen-codes.js';

/** A problem found while generating: a model diagnostic, an `app/` finding or a `gen/` error. */
export type GenerationDiagnostic = CheckDiagnostic;

/** Thrown by a generator to report a problem on a model element (reported as `gen/generator-failed`). */
export class GenerationError extends Error {
    constructor(message: string, readonly node?: AstNode) {
        super(message);
        this.name = 'GenerationError';
    }
}

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

export interface GenerateResult {
    /** No errors: every platform was generated and written. */
    readonly ok: boolean;
    readonly diagnostics: readonly GenerationDiagnostic[];
    readonly platforms: readonly PlatformResult[];
    /** Milliseconds per phase (for the benchmark). */
    readonly timings: Readonly<Record<'discover' | 'load' | 'check' | 'instantiate' | 'generate' | 'trace' | 'write', number>>;
}

/** A problem with the input itself (missing file, unknown platform): a message for the user. */
export class GenerateInputError extends Error {}

interface Instance {
    readonly registered: RegisteredGenerator;
    readonly generator: Generator;
    readonly templates: TemplateRenderer;
}

/**
 * The generation pipeline of ARCHITECTURE.md section 6: load the configuration and the
 * architecture, run the languages' checks, the compatibility checks and the generators' rules,
 * instantiate the generators, run the data type generator, then the component generator (which
 * hands each behavior to the behavior generator of its language), and write every platform's
 * files with a trace file (output/transaction.ts: staged beside the current output, then each
 * platform folder switched in one rename). Nothing is written when any step fails.
 */
export async function generate(options: GenerateOptions): Promise<GenerateResult> {
    const previous = setVariant(undefined);
    try {
        return await generateInConfiguration(options);
    } finally {
        setVariant(previous);
    }
}

async function generateInConfiguration(options: GenerateOptions): Promise<GenerateResult> {
    const timings = { discover: 0, load: 0, check: 0, instantiate: 0, generate: 0, trace: 0, write: 0 };
    const progress = options.onProgress ?? (() => undefined);
    const appFile = path.resolve(options.appFile);
    if (!existsSync(appFile) || !statSync(appFile).isFile()) throw new GenerateInputError(`no such file: ${options.appFile}`);
    const modelRoot = path.resolve(options.modelRoot ?? path.dirname(appFile));
    if (!(appFile.startsWith(modelRoot + path.sep))) throw new GenerateInputError(`${options.appFile} lies outside the model root ${modelRoot}`);
    const shared = options.services.shared;
    if (!shared.ServiceRegistry.all.some((s) => s.LanguageMetaData.fileExtensions.includes('.arcapp'))) {
        throw new GenerateInputError('the language family has no .arcapp language (register @maa/generator-core in its maa.family)');
    }

    let t = performance.now();
    progress({ phase: 'load', message: 'discovering generators' });
    const installed = installationRoot();
    const registry = options.registry ?? discoverGenerators(shared.workspace.FileSystemProvider, URI.file(modelRoot), {
        extraRoots: [...(installed ? [installed] : []), ...(options.discoveryRoots ?? []).map((d) => URI.file(path.resolve(d)))]
    });
    configureGeneratorRegistry(shared, registry);
    timings.discover = performance.now() - t;

    // Load and check the model root (the configuration is one of its files).
    t = performance.now();
    let found: CheckDiagnostic[];
    try {
        found = await checkRoots(options.services, [{ root: modelRoot }], { onProgress: (m) => progress({ phase: 'load', message: m }) });
    } catch (e) {
        if (e instanceof CheckInputError) throw new GenerateInputError(e.message);
        throw e;
    }
    timings.load = performance.now() - t;
    t = performance.now();
    progress({ phase: 'check', message: 'checking the configuration and the architecture' });
    const doc = shared.workspace.LangiumDocuments.getDocument(URI.file(appFile));
    const app = (doc?.parseResult.value as ArcAppModel | undefined)?.application;
    const diagnostics: GenerationDiagnostic[] = [];
    const fail = (): GenerateResult => ({ ok: false, diagnostics: sortDiagnostics(diagnostics), platforms: [], timings });
    if (!doc || !app) {
        diagnostics.push(...found.filter((d) => d.file === appFile));
        if (!diagnostics.some((d) => d.severity === 'error')) {
            diagnostics.push(at(modelRoot, appFile, undefined, 'error', GenCodes.NoApplication, 'The file declares no application (`application NAME for COMPONENT { platform P { ... } }`).'));
        }
        return fail();
    }

    const platforms = selectPlatforms(app, options.platforms);
    // The generators read the model in the application's feature configuration (restored by generate()).
    const variant = applicationVariant(app);
    setVariant(variant.env);
    const architecture = applicationArchitecture(app);
    // Diagnostics of the files generation reads: the configuration (except what concerns other
    // platforms, and the app/ checks, which run below per platform) and the architecture's files.
    const relevant = new Set<string>([appFile, ...(architecture ? architectureFiles(architecture) : [])]);
    const otherPlatforms = app.platforms.filter((p) => !platforms.includes(p));
    for (const d of found) {
        if (!relevant.has(d.file)) continue;
        if (d.file === appFile && (d.code.startsWith('app/') && d.code !== 'app/unknown-component' && d.code !== 'app/unknown-generator')) continue;
        if (d.file === appFile && otherPlatforms.some((p) => inside(d, p))) continue;
        diagnostics.push(d);
    }
    // The feature configuration concerns every platform (checkApplication reports it in the editor only).
    for (const f of variant.findings) diagnostics.push(findingDiagnostic(modelRoot, f));
    if (!architecture || diagnostics.some((d) => d.severity === 'error')) return fail();

    const infoOf = (p: AppPlatform): PlatformInfo => ({ application: app.name, platform: p.name, rootComponent: architecture.root.qualifiedName });
    const selections = new Map<AppPlatform, PlatformSelection>();
    for (const p of platforms) {
        selections.set(p, selectGenerators(p, registry));
        for (const f of checkApplication(app, registry, { platform: p.name, architecture })) diagnostics.push(findingDiagnostic(modelRoot, f));
    }
    timings.check = performance.now() - t;
    if (diagnostics.some((d) => d.severity === 'error')) return fail();

    // Instantiate the generators of every selected platform (each once).
    t = performance.now();
    const instances = new Map<string, Instance>();
    for (const p of platforms) {
        for (const { ref, generator } of selections.get(p)!.references) {
            if (instances.has(generator.manifest.name)) continue;
            progress({ phase: 'instantiate', message: `loading ${generator.manifest.name}`, platform: p.name, generator: generator.manifest.name });
            try {
                instances.set(generator.manifest.name, await instantiate(generator, options.loadModule));
            } catch (e) {
                diagnostics.push(nodeDiagnostic(modelRoot, ref, 'error', GenCodes.LoadFailed,
                    `Generator '${generator.manifest.name}' (package ${generator.source.packageName}) cannot be loaded: ${(e as Error).message}`));
            }
        }
    }
    timings.instantiate = performance.now() - t;
    if (diagnostics.some((d) => d.severity === 'error')) return fail();

    // Rules that only the generators' code defines.
    t = performance.now();
    for (const p of platforms) {
        const rules = (generator: string, rule: string): WellFormednessRule | undefined =>
            instances.get(generator)?.generator.rules?.find((r) => r.name === rule);
        const unknown: AppFinding[] = [];
        const findings = checkApplication(app, registry, {
            platform: p.name, architecture, rules,
            onUnknownRule: (g, rule, ref) => unknown.push({ code: 'app/generator-rule-violated', severity: 'error', node: ref, message: '', generator: g.manifest.name, rule })
        });
        for (const f of findings) {
            if (f.code === 'app/generator-rule-violated' && f.rule && !standardRule(f.rule)) diagnostics.push(findingDiagnostic(modelRoot, f));
        }
        for (const u of unknown) {
            diagnostics.push(nodeDiagnostic(modelRoot, u.node, 'error', GenCodes.UnknownCheck,
                `Generator '${u.generator}' declares the check '${u.rule}', which neither the standard rules nor the generator define.`));
        }
    }
    timings.check += performance.now() - t;
    if (diagnostics.some((d) => d.severity === 'error')) return fail();

    // Generate every platform in memory.
    const plans: Array<{ platform: AppPlatform; outDir: string; files: FinishedFile[]; generators: PlatformResult['generators'] }> = [];
    for (const p of platforms) {
        t = performance.now();
        const selection = selections.get(p)!;
        const collector = new OutputCollector();
        const run = async <T>(inst: Instance, body: () => Promise<T>): Promise<T | undefined> => {
            const name = inst.registered.manifest.name;
            progress({ phase: 'generate', message: `${p.name}: running ${name}`, platform: p.name, generator: name });
            try {
                return await body();
            } catch (e) {
                diagnostics.push(generatorFailure(modelRoot, selection, name, e));
                return undefined;
            }
        };
        const info = infoOf(p);
        const dt = instances.get(selection.datatype!.manifest.name)!;
        const datatypes = (await run(dt, async () => (await (dt.generator as DataTypeGenerator).generate({
            architecture, platform: info, out: collector.sink(dt.registered.manifest.name, dt.templates),
            templates: dt.templates, dataTypes: architecture.dataTypes
        })) ?? {})) as DataTypeResult | undefined;
        if (diagnostics.some((d) => d.severity === 'error')) return fail();

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
        await run(comp, async () => (comp.generator as ComponentGenerator).generate({
            architecture, platform: info, out: collector.sink(comp.registered.manifest.name, comp.templates),
            templates: comp.templates, datatypes: datatypes ?? {}, behavior: delegate
        }));
        // A component generator that does not wait for its behaviors must not lose their failures.
        for (const settled of await Promise.allSettled(delegated.values())) {
            if (settled.status === 'rejected') diagnostics.push(generatorFailure(modelRoot, selection, comp.registered.manifest.name, settled.reason));
        }
        timings.generate += performance.now() - t;
        if (diagnostics.some((d) => d.severity === 'error')) return fail();
        let files: FinishedFile[];
        t = performance.now();
        try {
            files = collector.finish();
        } catch (e) {
            diagnostics.push(generatorFailure(modelRoot, selection, undefined, e));
            return fail();
        }
        timings.trace += performance.now() - t;
        const counts = selection.references
            .filter((r, i, all) => all.findIndex((q) => q.generator === r.generator) === i)
            .map((r) => ({ name: r.generator.manifest.name, kind: r.generator.manifest.kind, files: files.filter((f) => f.generator === r.generator.manifest.name).length }));
        for (const c of counts) {
            progress({ phase: 'generate', message: `${p.name}: ${c.name}: ${c.files} file${c.files === 1 ? '' : 's'}`, platform: p.name, generator: c.name, files: c.files });
        }
        plans.push({ platform: p, outDir: path.join(path.resolve(options.outDir), p.name), files, generators: counts });
    }

    // Trace files, then one transaction over all output folders. The output root is locked and
    // cleaned up after killed runs before anything of it is read.
    const outRoot = path.resolve(options.outDir);
    const written: Array<{ plan: WritePlan; entry: (typeof plans)[number] }> = [];
    const shown = options.displayPath ?? ((p: string) => p);
    const writeFailed = (e: unknown): GenerateResult => {
        const problem = e instanceof OutputWriteError ? `${shown(e.path)}: ${e.reason}` : (e as Error).message;
        diagnostics.push(at(modelRoot, appFile, undefined, 'error', GenCodes.WriteFailed, `Cannot write the output: ${problem}. Nothing was changed.`));
        return fail();
    };
    t = performance.now();
    let tx: OutputTransaction;
    try {
        tx = OutputTransaction.open(outRoot);
    } catch (e) {
        timings.write += performance.now() - t;
        return writeFailed(e);
    }
    timings.write += performance.now() - t;
    try {
        for (const entry of plans) {
            t = performance.now();
            const trace = traceFile(options.services, modelRoot, entry.outDir, infoOf(entry.platform), entry.files, selections.get(entry.platform)!, instances);
            timings.trace += performance.now() - t;
            t = performance.now();
            written.push({ plan: planOutput(entry.outDir, entry.files, trace), entry });
            timings.write += performance.now() - t;
        }
        for (const { plan, entry } of written) {
            for (const d of plan.droppedRegions) {
                diagnostics.push(at(modelRoot, appFile, entry.platform.$cstNode?.range, 'error', GenCodes.ProtectedRegionDropped,
                    `Platform '${entry.platform.name}': ${shown(path.join(entry.outDir, d.path))} has user content in protected region${d.regions.length > 1 ? 's' : ''} ${d.regions.map((r) => `'${r}'`).join(', ')}, which the regenerated file no longer has; move that content and run again (nothing was written).`));
            }
            for (const stale of plan.keptStale) {
                diagnostics.push(at(modelRoot, appFile, entry.platform.$cstNode?.range, 'warning', GenCodes.StaleFileKept,
                    `Platform '${entry.platform.name}': ${shown(path.join(entry.outDir, stale))} is no longer generated but holds user content in protected regions; it was kept (delete it when done).`));
            }
        }
        if (diagnostics.some((d) => d.severity === 'error')) return fail();
        t = performance.now();
        progress({ phase: 'write', message: `writing ${written.reduce((n, w) => n + w.plan.write.length, 0)} files` });
        try {
            for (const w of written) tx.stage(w.plan);
            tx.commit();
        } catch (e) {
            timings.write += performance.now() - t;
            return writeFailed(e);
        }
    } finally {
        tx.close();
    }
    timings.write += performance.now() - t;
    return {
        ok: true,
        diagnostics: sortDiagnostics(diagnostics),
        platforms: written.map(({ plan, entry }) => ({
            platform: entry.platform.name,
            outDir: entry.outDir,
            files: entry.files.map((f) => f.path),
            generators: entry.generators,
            // The trace file is written with every generation; the lists name the generated files.
            written: plan.write.map((f) => f.path).filter((p) => p !== TRACE_FILE),
            unchanged: plan.unchanged.filter((p) => p !== TRACE_FILE),
            kept: plan.kept,
            removed: plan.remove,
            preservedRegions: plan.preservedRegions,
            keptStale: plan.keptStale
        })),
        timings
    };
}

function selectPlatforms(app: Application, names: readonly string[] | undefined): AppPlatform[] {
    if (!names || names.length === 0) {
        if (app.platforms.length === 0) throw new GenerateInputError(`application '${app.name}' configures no platform`);
        const seen = new Set<string>();
        return app.platforms.filter((p) => (seen.has(p.name) ? false : (seen.add(p.name), true)));
    }
    return names.map((n) => {
        const p = app.platforms.find((q) => q.name === n);
        if (!p) {
            throw new GenerateInputError(`application '${app.name}' has no platform '${n}' (platforms: ${app.platforms.map((q) => q.name).join(', ') || 'none'})`);
        }
        return p;
    });
}

async function instantiate(g: RegisteredGenerator, load: ((url: string) => Promise<unknown>) | undefined): Promise<Instance> {
    const m = g.manifest;
    const entry = path.resolve(g.source.packageDir, m.entry);
    if (!load && !existsSync(entry)) throw new Error(`its entry module ${m.entry} does not exist (${entry})`);
    const mod = (await (load ?? ((u: string) => import(u)))(pathToFileURL(entry).href)) as Record<string, unknown>;
    const exported = mod[m.export ?? 'default'];
    if (exported === undefined) throw new Error(`its entry module ${m.entry} has no export '${m.export ?? 'default'}'`);
    const templates = createTemplateRenderer(m.templates ? path.resolve(g.source.packageDir, m.templates) : undefined);
    const generator = (typeof exported === 'function'
        ? await (exported as (i: object) => unknown)({ manifest: m, packageDir: g.source.packageDir, templates })
        : exported) as Generator;
    if (!generator || typeof (generator as { generate?: unknown }).generate !== 'function') {
        throw new Error(`its export '${m.export ?? 'default'}' is not a generator (an object with a generate function, or a function returning one)`);
    }
    if (generator.kind !== undefined && generator.kind !== m.kind) {
        throw new Error(`its code implements a ${generator.kind} generator, but its manifest declares kind '${m.kind}'`);
    }
    return { registered: g, generator, templates };
}

async function delegateBehavior(
    c: ComponentView, selection: PlatformSelection, instances: ReadonlyMap<string, Instance>, platform: PlatformInfo,
    datatypes: DataTypeResult, collector: OutputCollector
): Promise<DelegatedBehavior | undefined> {
    const behavior: BehaviorView | undefined = c.behavior ?? (c.init ? { language: 'compute', node: c.init, component: c.qualifiedName } : undefined);
    if (!behavior) return undefined;
    const target = generatorForLanguage(selection, behavior.language);
    if (!target) throw new GenerationError(`no generator of platform '${platform.platform}' translates the '${behavior.language}' behavior of '${c.qualifiedName}'`, behavior.node);
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
        ...(requires.has('datatypes') ? { datatypes } : {})
    };
    let result;
    try {
        result = (await (inst.generator as BehaviorGenerator).generate(behavior, ctx)) ?? {};
    } catch (e) {
        throw new DelegatedFailure(m.name, e);
    }
    return { handledBy: 'behavior-generator', generator: m.name, language: behavior.language, behavior, result };
}

/** A behavior generator failed while the component generator waited for it. */
class DelegatedFailure extends Error {
    constructor(readonly generator: string, readonly error: unknown) {
        super(error instanceof Error ? error.message : String(error));
    }
}

function generatorFailure(modelRoot: string, selection: PlatformSelection, generator: string | undefined, e: unknown): GenerationDiagnostic {
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

function architectureFiles(a: ArchitectureModel): string[] {
    const nodes: AstNode[] = [...a.components.map((c) => c.node), ...a.dataTypes.map((t) => t.node)];
    return [...new Set(nodes.map((n) => AstUtils.getDocument(n).uri).filter((u) => u.scheme === 'file').map((u) => u.fsPath))];
}

function inside(d: CheckDiagnostic, p: AppPlatform): boolean {
    const r = p.$cstNode?.range;
    if (!r) return false;
    const line = d.line - 1;
    const col = d.column - 1;
    const afterStart = line > r.start.line || (line === r.start.line && col >= r.start.character);
    const beforeEnd = line < r.end.line || (line === r.end.line && col <= r.end.character);
    return afterStart && beforeEnd;
}

function findingDiagnostic(modelRoot: string, f: AppFinding): GenerationDiagnostic {
    // A violated generator rule is reported on the model element that violates it.
    if (f.modelNode) return nodeDiagnostic(modelRoot, f.modelNode, f.severity, f.code, f.message);
    return nodeDiagnostic(modelRoot, f.node, f.severity, f.code, f.message, f.property);
}

function nodeDiagnostic(modelRoot: string, node: AstNode, severity: Severity, code: string, message: string, property?: string): GenerationDiagnostic {
    const doc = AstUtils.getDocument(node);
    const cst = (property ? (node.$cstNode && findProperty(node, property)) : undefined) ?? node.$cstNode;
    return at(modelRoot, doc.uri.fsPath, cst?.range, severity, code, message);
}

function findProperty(node: AstNode, property: string): AstNode['$cstNode'] {
    const value = (node as unknown as Record<string, unknown>)[property];
    if (value && typeof value === 'object' && '$refNode' in value) return (value as { $refNode?: AstNode['$cstNode'] }).$refNode;
    return GrammarUtils.findNodeForProperty(node.$cstNode, property);
}

function at(root: string, file: string, range: { start: { line: number; character: number }; end: { line: number; character: number } } | undefined,
    severity: Severity, code: string, message: string): GenerationDiagnostic {
    return {
        root,
        file,
        line: (range?.start.line ?? 0) + 1,
        column: (range?.start.character ?? 0) + 1,
        endLine: (range?.end.line ?? 0) + 1,
        endColumn: (range?.end.character ?? 0) + 1,
        severity,
        code,
        message
    };
}

function sortDiagnostics(ds: readonly GenerationDiagnostic[]): GenerationDiagnostic[] {
    const seen = new Set<string>();
    return [...ds]
        .filter((d) => {
            const k = `${d.file}:${d.line}:${d.column}:${d.code}:${d.message}`;
            return seen.has(k) ? false : (seen.add(k), true);
        })
        .sort((a, b) => (a.file < b.file ? -1 : a.file > b.file ? 1 : 0) || a.line - b.line || a.column - b.column || (a.code < b.code ? -1 : a.code > b.code ? 1 : 0));
}

/** The trace file: generated line ranges -> model elements (file relative to the model root, range, AST path). */
function traceFile(
    services: HostLanguageServices, modelRoot: string, outDir: string, platform: PlatformInfo, files: readonly FinishedFile[],
    selection: PlatformSelection, instances: ReadonlyMap<string, Instance>
): string {
    const locator = services.Arc.workspace.AstNodeLocator;
    const relRoot = path.relative(outDir, modelRoot).split(path.sep).join('/') || '.';
    const docs = new Map<AstNode, LangiumDocument>();
    const element = (node: AstNode) => {
        const root = AstUtils.findRootNode(node);
        let doc = docs.get(root);
        if (!doc) docs.set(root, (doc = AstUtils.getDocument(node)));
        const r = node.$cstNode?.range;
        const name = (node as { name?: unknown }).name;
        return {
            file: doc.uri.scheme === 'file' ? path.relative(modelRoot, doc.uri.fsPath).split(path.sep).join('/') : doc.uri.toString(),
            range: r ? [r.start.line + 1, r.start.character + 1, r.end.line + 1, r.end.character + 1] : null,
            path: locator.getAstNodePath(node),
            type: node.$type,
            ...(typeof name === 'string' ? { name } : {})
        };
    };
    const generators = selection.references
        .filter((r, i, all) => all.findIndex((q) => q.generator === r.generator) === i && instances.has(r.generator.manifest.name))
        .map((r) => ({
            name: r.generator.manifest.name,
            kind: r.generator.manifest.kind,
            package: r.generator.source.packageName,
            version: r.generator.source.packageVersion
        }));
    const trace = {
        version: 1,
        application: platform.application,
        platform: platform.platform,
        rootComponent: platform.rootComponent,
        modelRoot: relRoot,
        generators,
        files: files.map((f) => ({
            path: f.path,
            generator: f.generator,
            userFile: f.userFile,
            sha256: sha256(f.content),
            lines: f.content.length === 0 ? 0 : f.content.split('\n').length - (f.content.endsWith('\n') ? 1 : 0),
            traces: f.traces.map((t) => ({ lines: [t.startLine, t.endLine], generator: t.generator, element: element(t.element) }))
        }))
    };
    return `${JSON.stringify(trace, null, 1)}\n`;
}

export { TRACE_FILE };
