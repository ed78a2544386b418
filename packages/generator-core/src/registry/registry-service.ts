import { UriUtils, type AstNode, type LangiumSharedCoreServices, type URI } from 'langium';
import { discoverGenerators, type DiscoveryOptions } from './discovery.js';
import { GeneratorRegistry, type RegisteredGenerator } from './registry.js';

/**
 * How old a discovery must be before a workspace change discards it. Discovery reads the
 * package.json of every installed package (hundreds in a development checkout, about 20 ms):
 * after each keystroke that was most of a small re-validation. Packages are installed by hand
 * (npm install), so a generator installed meanwhile is found at the first change made this long
 * after the last discovery.
 */
export const REDISCOVER_AFTER_MS = 2000;

/** Where the service finds generators when not configured with a registry. */
export interface RegistryServiceOptions extends DiscoveryOptions {
    /** How old a discovery must be before a workspace change discards it (default REDISCOVER_AFTER_MS). */
    readonly rediscoverAfterMs?: number;
}

/** The registry an application configuration document resolves its generator names against. */
export type RegistryProvider = (documentUri: URI) => GeneratorRegistry;

/**
 * What a generator reference (`ros2.Components;`) resolves to: a node standing for the
 * registry entry (generators are described by manifests, not by model files). Its description
 * points at the manifest's file (`documentUri`) and JSON field (`path`), so references,
 * completion and hover work like for model elements; go-to-definition can use
 * `generatorDefinition` (app/arcapp-language.ts) to jump into the manifest.
 */
export interface GeneratorDeclarationNode extends AstNode {
    readonly $type: 'GeneratorDeclaration';
    readonly name: string;
    readonly generator: RegisteredGenerator;
}

/**
 * The generator registry of a language family's `.arcapp` language: a service of its service
 * container (`services.generators.Registry`, see app/arcapp-module.ts), constructed with the
 * family's shared services. Where generators come from is set with `configure` (a fixed
 * registry for tests, the orchestrator and a browser IDE with a bundled list, or a provider per
 * document); without it, generators are discovered from installed packages (discoverGenerators)
 * from each document's folder, through the family's file system provider (nothing in a browser
 * without files), plus generator-core's own installation (or the configured `extraRoots`).
 */
export class GeneratorRegistryService {
    private provider: RegistryProvider | undefined;
    private options: RegistryServiceOptions = {};
    /** The discovered registries by folder, with when they were discovered (Date.now()). */
    private readonly discovered = new Map<string, { readonly registry: GeneratorRegistry; readonly at: number }>();
    private readonly declarations = new WeakMap<RegisteredGenerator, GeneratorDeclarationNode>();

    constructor(private readonly shared: LangiumSharedCoreServices) {
        // Installed packages may change between builds (npm install): discover afresh after a
        // workspace change, at most once per folder and REDISCOVER_AFTER_MS.
        shared.workspace.DocumentBuilder.onUpdate(() => this.discardOld());
    }

    private discardOld(): void {
        const oldest = Date.now() - (this.options.rediscoverAfterMs ?? REDISCOVER_AFTER_MS);
        for (const [key, entry] of this.discovered) if (entry.at <= oldest) this.discovered.delete(key);
    }

    /** Sets where the family's `.arcapp` documents find their generators (undefined: discovery). */
    configure(registry: GeneratorRegistry | RegistryProvider | undefined, options: RegistryServiceOptions = {}): void {
        this.provider = registry instanceof GeneratorRegistry ? () => registry : registry;
        this.options = options;
        this.discovered.clear();
    }

    /** The registry for a document of the family (discovered and cached per folder unless configured). */
    registryFor(documentUri: URI): GeneratorRegistry {
        if (this.provider) return this.provider(documentUri);
        const dir = UriUtils.dirname(documentUri);
        const key = dir.toString();
        const known = this.discovered.get(key);
        if (known) return known.registry;
        const registry =
            dir.scheme === 'file'
                ? discoverGenerators(this.shared.workspace.FileSystemProvider, dir, this.options)
                : GeneratorRegistry.EMPTY;
        this.discovered.set(key, { registry, at: Date.now() });
        return registry;
    }

    /** The one declaration node of a registered generator (references to it resolve to the same node). */
    declaration(g: RegisteredGenerator, create: (g: RegisteredGenerator) => GeneratorDeclarationNode): GeneratorDeclarationNode {
        const known = this.declarations.get(g);
        if (known) return known;
        const node = create(g);
        this.declarations.set(g, node);
        return node;
    }
}
