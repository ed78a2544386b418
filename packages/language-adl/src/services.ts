import {
    createDefaultCoreModule,
    createDefaultSharedCoreModule,
    inject,
    type DefaultSharedCoreModuleContext,
    type LangiumCoreServices,
    type LangiumGeneratedCoreServices,
    type LangiumGeneratedSharedCoreServices,
    type LangiumSharedCoreServices,
    type Module,
} from 'langium';
import { registerCdChecks } from '@maa/language-cd';
import { AdlGeneratedSharedModule, ArcGeneratedModule, CdGeneratedModule } from './generated/module.js';
import { AdlModule, AdlSharedModule, type AdlServices, type AdlSharedServices } from './adl-module.js';
import type { BehaviorLanguage } from './behavior-language.js';
import type { AdlLspServices } from './lsp/lsp-module.js';
import { registerAdlChecks } from './validation/adl-validator.js';

export interface HostLanguageServices {
    shared: AdlSharedServices;
    Arc: AdlServices;
    Cd: AdlServices;
    /** The services of every further language of the family (e.g. `ra`), by language id. */
    languages: ReadonlyMap<string, AdlServices>;
}

/**
 * A further language of a family with its own files (e.g. standalone RobotArm `.ra`): it gets a
 * service container of its own, with the host's scoping and typing, plus what `register` adds.
 */
export interface LanguageRegistration {
    readonly languageId: string;
    register(services: AdlServices): void;
    /** The language's diagnostics with tested examples (rendered into docs/diagnostics.md). */
    readonly diagnostics?: import('./diagnostic-catalog/catalog.js').DiagnosticCatalog;
    /**
     * Installs the language's LSP contributions into its own service container (called only by
     * language servers, after `register`); see `BehaviorLanguage.registerLsp` for the registries.
     */
    registerLsp?(services: AdlLspServices): void;
    /**
     * Further services of the language's own service container (a Langium module, injected after
     * the host's modules; only for languages with their own files, see FamilyLanguage).
     */
    readonly module?: Module<AdlServices, object>;
}

export interface FamilyLanguage extends LanguageRegistration {
    readonly generated: Module<LangiumCoreServices, LangiumGeneratedCoreServices>;
}

/** The Langium modules a composed grammar build generated (see @maa/grammar-composer). */
export interface GeneratedModules {
    shared: Module<LangiumSharedCoreServices, LangiumGeneratedSharedCoreServices>;
    arc: Module<LangiumCoreServices, LangiumGeneratedCoreServices>;
    cd: Module<LangiumCoreServices, LangiumGeneratedCoreServices>;
}

/**
 * The Langium modules a family's services start from (core defaults for tools, LSP defaults for
 * language servers) and further modules injected after the host's own ones.
 */
export interface HostServiceDefaults {
    shared: (ctx: DefaultSharedCoreModuleContext) => Module<LangiumSharedCoreServices, object>;
    language: (ctx: { shared: LangiumSharedCoreServices }) => Module<LangiumCoreServices, object>;
    /** Injected after AdlSharedModule (e.g. language-adl's AdlLspSharedModule). */
    sharedModules?: ReadonlyArray<Module<AdlSharedServices, object>>;
    /** Injected after AdlModule into every language of the family (e.g. AdlLspModule). */
    languageModules?: ReadonlyArray<Module<AdlServices, object>>;
}

/**
 * Creates the services of the host languages (`arc`, `cd`) for a composed grammar build and
 * installs the given behavior languages. Language servers use createHostLspServices (lsp/),
 * which passes Langium's LSP defaults and the host's LSP modules.
 */
export function createHostServices(
    context: DefaultSharedCoreModuleContext,
    generated: GeneratedModules,
    behaviors: readonly BehaviorLanguage[],
    languages: readonly FamilyLanguage[] = [],
    defaults: HostServiceDefaults = { shared: createDefaultSharedCoreModule, language: createDefaultCoreModule },
): HostLanguageServices {
    const sharedExtra = defaults.sharedModules ?? [];
    const languageExtra = defaults.languageModules ?? [];
    const shared = inject(
        defaults.shared(context) as Module<AdlSharedServices, object>,
        generated.shared,
        AdlSharedModule,
        ...sharedExtra,
    ) as AdlSharedServices;
    const Arc = inject(
        defaults.language({ shared }) as Module<AdlServices, object>,
        generated.arc,
        AdlModule,
        ...languageExtra,
    ) as AdlServices;
    const Cd = inject(
        defaults.language({ shared }) as Module<AdlServices, object>,
        generated.cd,
        AdlModule,
        ...languageExtra,
    ) as AdlServices;
    shared.ServiceRegistry.register(Arc);
    shared.ServiceRegistry.register(Cd);
    registerAdlChecks(Arc);
    registerCdChecks(Cd.validation.ValidationRegistry, shared.maa.ModelRoots);
    for (const b of behaviors) b.register(Arc);
    const others = new Map<string, AdlServices>();
    for (const l of languages) {
        const services = inject(
            defaults.language({ shared }) as Module<AdlServices, object>,
            l.generated,
            AdlModule,
            ...languageExtra,
            ...(l.module ? [l.module] : []),
        ) as AdlServices;
        shared.ServiceRegistry.register(services);
        l.register(services);
        others.set(l.languageId, services);
    }
    return { shared, Arc, Cd, languages: others };
}

/** The host language alone (`compute`/`init` as the only behaviors): for this package's tests. */
export function createAdlServices(context: DefaultSharedCoreModuleContext): HostLanguageServices {
    return createHostServices(context, { shared: AdlGeneratedSharedModule, arc: ArcGeneratedModule, cd: CdGeneratedModule }, []);
}
