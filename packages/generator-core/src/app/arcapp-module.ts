import type { LangiumSharedCoreServices, Module } from 'langium';
import type { AdlServices } from '@maa/language-adl';
import { GeneratorRegistryService } from '../registry/registry-service.js';
import { ApplicationAnalyzer } from './app-analysis.js';

/** The services the application configuration language adds to its own service container. */
export interface ArcAppAddedServices {
    generators: {
        /** Where the `.arcapp` documents of the family find their generators. */
        Registry: GeneratorRegistryService;
        /** The `app/*` checks of each application, with its architecture model (computed once per build). */
        Applications: ApplicationAnalyzer;
    };
}

export type ArcAppServices = AdlServices & ArcAppAddedServices;

/** Injected into the `.arcapp` language's container (ArcAppLanguage.module), after the host's modules. */
export const ArcAppModule: Module<ArcAppServices, ArcAppAddedServices> = {
    generators: {
        Registry: (s) => new GeneratorRegistryService(s.shared),
        Applications: (s) => new ApplicationAnalyzer(s.shared, s.generators.Registry),
    },
};

/**
 * The `.arcapp` language's services in a family (undefined when the family does not register
 * @maa/generator-core's ArcAppLanguage).
 */
export function arcAppServices(shared: LangiumSharedCoreServices): ArcAppServices | undefined {
    const services = shared.ServiceRegistry.all.find((s) => s.LanguageMetaData.fileExtensions.includes('.arcapp'));
    return services && 'generators' in services ? (services as ArcAppServices) : undefined;
}
