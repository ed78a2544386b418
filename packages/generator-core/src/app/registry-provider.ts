import { UriUtils, type LangiumSharedCoreServices, type URI } from 'langium';
import { discoverGenerators, type DiscoveryOptions } from '../registry/discovery.js';
import { GeneratorRegistry } from '../registry/registry.js';

/** The registry an application configuration document resolves its generator names against. */
export type RegistryProvider = (documentUri: URI) => GeneratorRegistry;

interface Slot {
    provider?: RegistryProvider;
    options: DiscoveryOptions;
    cache: Map<string, GeneratorRegistry>;
    listening: boolean;
}

const slots = new WeakMap<LangiumSharedCoreServices, Slot>();

function slot(shared: LangiumSharedCoreServices): Slot {
    let s = slots.get(shared);
    if (!s) slots.set(shared, (s = { options: {}, cache: new Map(), listening: false }));
    return s;
}

/**
 * Sets where the `.arcapp` documents of a language family find their generators: a fixed
 * registry (tests, the orchestrator, a browser IDE with a bundled list) or a provider per
 * document. Without it, generators are discovered from installed packages (see
 * discoverGenerators) from each document's folder, through the family's file system provider
 * (nothing in a browser without files), plus generator-core's own installation (or
 * `options.extraRoots`).
 */
export function configureGeneratorRegistry(
    shared: LangiumSharedCoreServices,
    registry: GeneratorRegistry | RegistryProvider | undefined,
    options: DiscoveryOptions = {}
): void {
    const s = slot(shared);
    s.provider = registry instanceof GeneratorRegistry ? () => registry : registry;
    s.options = options;
    s.cache.clear();
}

/** The registry for a document of the family (discovered and cached per folder unless configured). */
export function generatorRegistryFor(shared: LangiumSharedCoreServices, documentUri: URI): GeneratorRegistry {
    const s = slot(shared);
    if (s.provider) return s.provider(documentUri);
    if (!s.listening) {
        // Installed packages may change between builds (npm install): discover afresh after
        // every workspace change, at most once per folder and build.
        shared.workspace.DocumentBuilder.onUpdate(() => s.cache.clear());
        s.listening = true;
    }
    const dir = UriUtils.dirname(documentUri);
    const key = dir.toString();
    let registry = s.cache.get(key);
    if (!registry) {
        registry = dir.scheme === 'file'
            ? discoverGenerators(shared.workspace.FileSystemProvider, dir, s.options)
            : GeneratorRegistry.EMPTY;
        s.cache.set(key, registry);
    }
    return registry;
}
