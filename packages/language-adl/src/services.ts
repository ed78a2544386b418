import {
    createDefaultCoreModule, createDefaultSharedCoreModule, inject, type DefaultSharedCoreModuleContext,
    type LangiumCoreServices, type LangiumGeneratedCoreServices, type LangiumGeneratedSharedCoreServices,
    type LangiumSharedCoreServices, type Module
} from 'langium';
import { AdlGeneratedSharedModule, ArcGeneratedModule, CdGeneratedModule } from './generated/module.js';
import { AdlModule, AdlSharedModule, type AdlServices, type AdlSharedServices } from './adl-module.js';
import type { BehaviorLanguage } from './behavior-language.js';
import { registerAdlChecks } from './validation/adl-validator.js';
import { registerCdChecks } from './validation/cd-validator.js';

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
 * Creates the services of the host languages (`arc`, `cd`) for a composed grammar build and
 * installs the given behavior languages. Front ends with LSP pass the LSP default modules.
 */
export function createHostServices(
    context: DefaultSharedCoreModuleContext,
    generated: GeneratedModules,
    behaviors: readonly BehaviorLanguage[],
    languages: readonly FamilyLanguage[] = [],
    defaults: {
        shared: (ctx: DefaultSharedCoreModuleContext) => Module<LangiumSharedCoreServices, object>;
        language: (ctx: { shared: LangiumSharedCoreServices }) => Module<LangiumCoreServices, object>;
    } = { shared: createDefaultSharedCoreModule, language: createDefaultCoreModule }
): HostLanguageServices {
    const shared = inject(defaults.shared(context) as Module<AdlSharedServices, object>, generated.shared, AdlSharedModule) as AdlSharedServices;
    const Arc = inject(defaults.language({ shared }) as Module<AdlServices, object>, generated.arc, AdlModule) as AdlServices;
    const Cd = inject(defaults.language({ shared }) as Module<AdlServices, object>, generated.cd, AdlModule) as AdlServices;
    shared.ServiceRegistry.register(Arc);
    shared.ServiceRegistry.register(Cd);
    registerAdlChecks(Arc);
    registerCdChecks(Cd);
    for (const b of behaviors) b.register(Arc);
    const others = new Map<string, AdlServices>();
    for (const l of languages) {
        const services = inject(defaults.language({ shared }) as Module<AdlServices, object>, l.generated, AdlModule) as AdlServices;
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
