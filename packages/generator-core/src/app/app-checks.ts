import type { AstNode } from 'langium';
import type { ast } from '@maa/language-adl';
import type { AppGeneratorRef, AppPlatform, Application } from '../generated/ast.js';
import type { WellFormednessRule } from '../generators/types.js';
import type { GeneratorManifest } from '../manifest/manifest.js';
import { buildArchitecture, type ArchitectureModel, type BehaviorView } from '../model/architecture.js';
import type { GeneratorRegistry, RegisteredGenerator } from '../registry/registry.js';
import { standardRule } from '../rules/standard-rules.js';
import { AppCodes, type AppCode } from './codes.js';
import { applicationVariant, type ApplicationVariant } from './app-variant.js';
import { withVariant } from '@maa/language-adl';

/**
 * A problem of an application configuration. `node`/`property` locate it in the `.arcapp`
 * file; a violated generator rule also names the model element (`modelNode`) that violates it.
 */
export interface AppFinding {
    readonly code: AppCode;
    readonly severity: 'error' | 'warning';
    readonly message: string;
    readonly node: AstNode;
    readonly property?: string;
    readonly modelNode?: AstNode;
    /** The generator a finding is about (rule violations, mismatches). */
    readonly generator?: string;
    readonly rule?: string;
}

/** The generators a platform selects, resolved and sorted into the three roles. */
export interface PlatformSelection {
    readonly platform: AppPlatform;
    readonly references: ReadonlyArray<{ readonly ref: AppGeneratorRef; readonly generator: RegisteredGenerator }>;
    readonly component?: RegisteredGenerator;
    readonly datatype?: RegisteredGenerator;
    /** The behavior generator of each language (the first one listed when there are several). */
    readonly behaviors: ReadonlyMap<string, RegisteredGenerator>;
}

export interface AppCheckOptions {
    /** Only this platform (all when undefined). */
    readonly platform?: string;
    /** Rules beyond the standard library (from generator code; the orchestrator passes them). */
    readonly rules?: (generator: string, rule: string) => WellFormednessRule | undefined;
    /** Called for a check name that no rule defines (the editor ignores them). */
    readonly onUnknownRule?: (generator: RegisteredGenerator, rule: string, ref: AppGeneratorRef) => void;
    /** The architecture, when the caller has built it already. */
    readonly architecture?: ArchitectureModel;
    /** The application's feature configuration, when the caller has computed it already (applicationVariant). */
    readonly variant?: ApplicationVariant;
}

/** The generators a platform names, resolved against the registry (unknown names are skipped). */
export function selectGenerators(platform: AppPlatform, registry: GeneratorRegistry): PlatformSelection {
    const references: Array<{ ref: AppGeneratorRef; generator: RegisteredGenerator }> = [];
    let component: RegisteredGenerator | undefined;
    let datatype: RegisteredGenerator | undefined;
    const behaviors = new Map<string, RegisteredGenerator>();
    for (const ref of platform.generators) {
        const generator = registry.get(ref.generator.$refText);
        if (!generator) continue;
        references.push({ ref, generator });
        const m = generator.manifest;
        if (m.kind === 'component') component ??= generator;
        else if (m.kind === 'datatype') datatype ??= generator;
        else if (!behaviors.has(m.language)) behaviors.set(m.language, generator);
    }
    return { platform, references, component, datatype, behaviors };
}

/** The generator that translates a behavior language on a platform, if any. */
export function generatorForLanguage(
    selection: PlatformSelection,
    language: string,
): { generator: RegisteredGenerator; role: 'behavior' | 'component' } | undefined {
    const b = selection.behaviors.get(language);
    if (b) return { generator: b, role: 'behavior' };
    const c = selection.component;
    if (c && c.manifest.kind === 'component' && c.manifest.supports.includes(language)) return { generator: c, role: 'component' };
    return undefined;
}

/** The architecture of an application, or undefined while its component does not resolve. */
export function applicationArchitecture(
    app: Application,
    variant: ApplicationVariant = applicationVariant(app),
): ArchitectureModel | undefined {
    const root = app.component?.ref as unknown as ast.ComponentType | undefined;
    // In the feature configuration the application selects (app-variant.ts).
    return root ? withVariant(variant.env, () => buildArchitecture(root)) : undefined;
}

/**
 * The `app/*` rules of ARCHITECTURE.md section 6 on one application configuration: generator
 * roles per platform, behavior language coverage, GPL/RTE compatibility, and the generators'
 * own well-formedness rules on the models they will translate. Unknown generators and an
 * unresolved component are linking errors, reported by the document validator.
 */
export function checkApplication(app: Application, registry: GeneratorRegistry, options: AppCheckOptions = {}): AppFinding[] {
    const findings: AppFinding[] = [];
    const seenPlatforms = new Set<string>();
    let architecture: ArchitectureModel | undefined | null = options.architecture ?? null;
    let variant = options.variant;
    const arch = (): ArchitectureModel | undefined => {
        if (architecture === null) architecture = applicationArchitecture(app, (variant ??= applicationVariant(app)));
        return architecture;
    };
    // The feature configuration concerns every platform: reported once, in the check of the
    // whole configuration (generation reports it before the platforms' findings).
    if (options.platform === undefined) findings.push(...(variant ??= applicationVariant(app)).findings);
    for (const platform of app.platforms) {
        if (seenPlatforms.has(platform.name)) {
            findings.push({
                code: AppCodes.DuplicatePlatform,
                severity: 'error',
                node: platform,
                property: 'name',
                message: `Platform '${platform.name}' is configured twice in application '${app.name}'.`,
            });
            continue;
        }
        seenPlatforms.add(platform.name);
        if (options.platform !== undefined && platform.name !== options.platform) continue;
        findings.push(...checkPlatform(platform, registry, arch, options));
    }
    return findings;
}

/** A generator as a platform lists it: the reference in the `.arcapp` file and what it resolved to. */
type ListedGenerator = PlatformSelection['references'][number];

/** Records a finding; its severity is 'error' unless given. */
type Report = (finding: Omit<AppFinding, 'severity'> & { severity?: 'error' | 'warning' }) => void;

/** What the checks of one platform share. */
interface PlatformContext {
    readonly platform: AppPlatform;
    readonly registry: GeneratorRegistry;
    readonly selection: PlatformSelection;
    /** `platform 'P'`, as the messages name it. */
    readonly where: string;
    /**
     * Every listed generator is known. An unknown one (reported by linking) may be the one that
     * fills a role or covers a language: no follow-up findings about missing ones then.
     */
    readonly complete: boolean;
}

/** The checks of one platform, in the order their findings are reported. */
function checkPlatform(
    platform: AppPlatform,
    registry: GeneratorRegistry,
    arch: () => ArchitectureModel | undefined,
    options: AppCheckOptions,
): AppFinding[] {
    const findings: AppFinding[] = [];
    const report: Report = (f) => {
        findings.push({ severity: 'error', ...f });
    };
    const selection = selectGenerators(platform, registry);
    const context: PlatformContext = {
        platform,
        registry,
        selection,
        where: `platform '${platform.name}'`,
        complete: selection.references.length === platform.generators.length,
    };
    const distinct = distinctGenerators(context, report);
    checkSingleRoles(context, distinct, report);
    checkBehaviorRoles(context, distinct, report);
    checkCompatibility(context, distinct, report);

    // The model-dependent checks need the architecture (built on first use, once per application).
    const architecture = arch();
    if (!architecture) return findings;
    checkCoverage(context, ofKind(distinct, 'component')[0], architecture, report);
    findings.push(
        ...checkGeneratorRules(selection, architecture, {
            rule: (generator, name) => standardRule(name) ?? options.rules?.(generator, name),
            onUnknownRule: options.onUnknownRule,
        }),
    );
    return findings;
}

/** Each generator once: a repeated one is a warning, and the rest of the checks see it once. */
function distinctGenerators({ selection, where }: PlatformContext, report: Report): ListedGenerator[] {
    const distinct: ListedGenerator[] = [];
    const seen = new Set<string>();
    for (const r of selection.references) {
        const name = r.generator.manifest.name;
        if (seen.has(name)) {
            report({
                code: AppCodes.RepeatedGenerator,
                severity: 'warning',
                node: r.ref,
                property: 'generator',
                message: `Generator '${name}' is listed more than once in ${where}.`,
            });
            continue;
        }
        seen.add(name);
        distinct.push(r);
    }
    return distinct;
}

function ofKind(listed: readonly ListedGenerator[], kind: GeneratorManifest['kind']): ListedGenerator[] {
    return listed.filter((r) => r.generator.manifest.kind === kind);
}

/** The roles a platform fills exactly once, in the order they are checked. */
const SINGLE_ROLES = [
    {
        kind: 'component',
        label: 'component generator',
        missing: AppCodes.MissingComponentGenerator,
        duplicate: AppCodes.DuplicateComponentGenerator,
    },
    {
        kind: 'datatype',
        label: 'data type generator',
        missing: AppCodes.MissingDataTypeGenerator,
        duplicate: AppCodes.DuplicateDataTypeGenerator,
    },
] as const;

/** Exactly one component generator and one data type generator. */
function checkSingleRoles(
    { platform, registry, where, complete }: PlatformContext,
    distinct: readonly ListedGenerator[],
    report: Report,
): void {
    for (const role of SINGLE_ROLES) {
        const filling = ofKind(distinct, role.kind);
        if (filling.length === 0 && complete) {
            report({
                code: role.missing,
                node: platform,
                property: 'name',
                message: `${capital(where)} has no ${role.label}: add one (e.g. '${suggest(registry, role.kind)}').`,
            });
        }
        for (const extra of filling.slice(1)) {
            report({
                code: role.duplicate,
                node: extra.ref,
                property: 'generator',
                message: `${capital(where)} has more than one ${role.label} ('${names(filling)}'); keep exactly one.`,
            });
        }
    }
}

/** One behavior generator per behavior language. */
function checkBehaviorRoles({ where }: PlatformContext, distinct: readonly ListedGenerator[], report: Report): void {
    const byLanguage = new Map<string, ListedGenerator[]>();
    for (const r of ofKind(distinct, 'behavior')) {
        const m = r.generator.manifest;
        if (m.kind !== 'behavior') continue;
        const list = byLanguage.get(m.language) ?? [];
        list.push(r);
        byLanguage.set(m.language, list);
    }
    for (const [language, list] of byLanguage) {
        for (const extra of list.slice(1)) {
            report({
                code: AppCodes.DuplicateBehaviorGenerator,
                node: extra.ref,
                property: 'generator',
                message: `${capital(where)} has more than one behavior generator for '${language}' ('${names(list)}'); keep exactly one.`,
            });
        }
    }
}

/** One GPL for the family, one RTE for the component generator and the behavior generators. */
function checkCompatibility({ where }: PlatformContext, distinct: readonly ListedGenerator[], report: Report): void {
    const component = ofKind(distinct, 'component')[0];
    // The GPL is the component generator's; without one, the first generator's.
    const reference = component ?? distinct[0];
    if (reference) {
        const gpl = reference.generator.manifest.output.gpl;
        for (const r of distinct) {
            if (r === reference || r.generator.manifest.output.gpl === gpl) continue;
            report({
                code: AppCodes.GplMismatch,
                node: r.ref,
                property: 'generator',
                generator: r.generator.manifest.name,
                message: `Generator '${r.generator.manifest.name}' produces ${r.generator.manifest.output.gpl}, but '${reference.generator.manifest.name}' produces ${gpl}: all generators of ${where} must produce the same language.`,
            });
        }
    }
    if (component) {
        const rte = component.generator.manifest.output.rte;
        for (const r of distinct) {
            const m = r.generator.manifest;
            // A behavior generator of another GPL has its GPL mismatch already.
            if (m.kind !== 'behavior' || m.output.rte === rte || m.output.gpl !== component.generator.manifest.output.gpl) continue;
            report({
                code: AppCodes.RteMismatch,
                node: r.ref,
                property: 'generator',
                generator: m.name,
                message: `Behavior generator '${m.name}' writes against the run-time environment '${m.output.rte}', but component generator '${component.generator.manifest.name}' wraps '${rte}'.`,
            });
        }
    }
}

/** Every behavior language of the architecture has a translator (checked once a component generator is listed). */
function checkCoverage(
    { platform, registry, selection, where, complete }: PlatformContext,
    component: ListedGenerator | undefined,
    architecture: ArchitectureModel,
    report: Report,
): void {
    if (!component || !complete) return;
    for (const language of architecture.languages) {
        if (generatorForLanguage(selection, language)) continue;
        const users = architecture.components.filter((c) => c.behavior?.language === language || (language === 'compute' && c.init));
        const shown =
            users
                .slice(0, 3)
                .map((c) => c.qualifiedName)
                .join(', ') + (users.length > 3 ? ', ...' : '');
        report({
            code: AppCodes.UncoveredBehaviorLanguage,
            node: platform,
            property: 'name',
            message: `${capital(where)} has no generator for the behavior language '${language}' (used by ${shown}): add a behavior generator for '${language}'${suggestBehavior(registry, language)}.`,
        });
    }
}

export interface GeneratorRuleOptions {
    /** The rule a generator's manifest names in its `checks` (undefined: unknown). */
    readonly rule: (generator: string, rule: string) => WellFormednessRule | undefined;
    /** Which of the named checks to run (default: all). */
    readonly only?: (rule: string) => boolean;
    /** Called for a check name that `rule` does not define. */
    readonly onUnknownRule?: (generator: RegisteredGenerator, rule: string, ref: AppGeneratorRef) => void;
}

/**
 * The well-formedness rules the generators of a platform name in their manifests (`checks`), on
 * the models each will translate: the data types for the data type generator, the components and
 * the behaviors it translates itself for the component generator, the behaviors of its language
 * for a behavior generator. A generator listed twice is checked once.
 */
export function checkGeneratorRules(
    selection: PlatformSelection,
    architecture: ArchitectureModel,
    options: GeneratorRuleOptions,
): AppFinding[] {
    const findings: AppFinding[] = [];
    const seen = new Set<string>();
    for (const { ref, generator } of selection.references) {
        const m = generator.manifest;
        if (seen.has(m.name)) continue;
        seen.add(m.name);
        const behaviors: BehaviorView[] =
            m.kind === 'behavior'
                ? architecture.behaviors.filter((b) => b.language === m.language)
                : m.kind === 'component'
                  ? architecture.behaviors.filter((b) => m.supports.includes(b.language) && !selection.behaviors.has(b.language))
                  : [];
        const scope = {
            architecture,
            components: m.kind === 'component' ? architecture.components : [],
            behaviors,
            dataTypes: m.kind === 'datatype' ? architecture.dataTypes : [],
        };
        for (const name of m.checks) {
            if (options.only && !options.only(name)) continue;
            const rule = options.rule(m.name, name);
            if (!rule) {
                options.onUnknownRule?.(generator, name, ref);
                continue;
            }
            for (const v of rule.check(scope)) {
                findings.push({
                    code: AppCodes.GeneratorRuleViolated,
                    severity: 'error',
                    node: ref,
                    property: 'generator',
                    modelNode: v.node,
                    generator: m.name,
                    rule: name,
                    message: `Generator '${m.name}' requires ${name} (${lowerFirst(rule.description)}), but ${v.message}.`,
                });
            }
        }
    }
    return findings;
}

function suggest(registry: GeneratorRegistry, kind: GeneratorManifest['kind']): string {
    return registry.all().find((g) => g.manifest.kind === kind)?.manifest.name ?? `a ${kind} generator`;
}

function suggestBehavior(registry: GeneratorRegistry, language: string): string {
    const found = registry
        .all()
        .filter((g) => g.manifest.kind === 'behavior' && g.manifest.language === language)
        .map((g) => `'${g.manifest.name}'`);
    return found.length > 0 ? ` (installed: ${found.join(', ')})` : '';
}

/** The generators' names as a message lists them: `a', 'b` (the message adds the outer quotes). */
function names(listed: readonly ListedGenerator[]): string {
    return listed.map((c) => c.generator.manifest.name).join("', '");
}

function capital(s: string): string {
    return s.charAt(0).toUpperCase() + s.slice(1);
}

function lowerFirst(s: string): string {
    const t = s.replace(/\.$/, '');
    return t.charAt(0).toLowerCase() + t.slice(1);
}
