import type { LangiumSharedCoreServices, URI } from 'langium';
import type { DiscoveryOptions } from '../registry/discovery.js';
import type { GeneratorRegistry } from '../registry/registry.js';
import type { GeneratorRegistryService, RegistryProvider } from '../registry/registry-service.js';
import { arcAppServices } from './arcapp-module.js';

/** The generator registry service of a family's `.arcapp` language (app/arcapp-module.ts). */
export function generatorRegistryService(shared: LangiumSharedCoreServices): GeneratorRegistryService {
    const services = arcAppServices(shared);
    if (!services) throw new Error('the language family has no .arcapp language (register @maa/generator-core in its maa.family)');
    return services.generators.Registry;
}

/**
 * Sets where the `.arcapp` documents of a language family find their generators (see
 * GeneratorRegistryService.configure): a fixed registry (tests, the orchestrator, a browser IDE
 * with a bundled list) or a provider per document; undefined: discovery from installed packages.
 */
export function configureGeneratorRegistry(
    shared: LangiumSharedCoreServices,
    registry: GeneratorRegistry | RegistryProvider | undefined,
    options: DiscoveryOptions = {},
): void {
    generatorRegistryService(shared).configure(registry, options);
}

/** The registry for a document of the family (discovered and cached per folder unless configured). */
export function generatorRegistryFor(shared: LangiumSharedCoreServices, documentUri: URI): GeneratorRegistry {
    return generatorRegistryService(shared).registryFor(documentUri);
}
