import { ManifestError, validateManifest, type GeneratorManifest, type ManifestSource } from '../manifest/manifest.js';
import { compare } from '../model/architecture.js';

/** A generator known to the registry: its validated manifest and where it was declared. */
export interface RegisteredGenerator {
    readonly manifest: GeneratorManifest;
    readonly source: ManifestSource;
}

/**
 * The generators available to application configurations, by qualified name. Built from the
 * manifests of installed packages (see discoverGenerators) or given directly (tests, a browser
 * IDE with a bundled list). Invalid manifests do not stop the registry: they are kept as
 * problems, reported by `maa-gen generators` and by generation when a configuration needs them.
 */
export class GeneratorRegistry {
    private readonly byName = new Map<string, RegisteredGenerator>();
    readonly problems: readonly ManifestError[];

    constructor(generators: readonly RegisteredGenerator[], problems: readonly ManifestError[] = []) {
        const found: ManifestError[] = [...problems];
        for (const g of generators) {
            const other = this.byName.get(g.manifest.name);
            if (other) {
                found.push(
                    new ManifestError(
                        g.source.packageName,
                        g.source.file,
                        `${g.source.field}.name`,
                        `generator '${g.manifest.name}' is already declared by package ${other.source.packageName}; this declaration is ignored`,
                    ),
                );
                continue;
            }
            this.byName.set(g.manifest.name, g);
        }
        this.problems = found;
    }

    static readonly EMPTY = new GeneratorRegistry([]);

    /**
     * A registry from manifests given as JSON (validated like discovered ones), e.g. for tests or
     * for a bundled registry. `packageDir` is the folder entry and template paths are relative to.
     */
    static fromManifests(manifests: readonly unknown[], packageName = 'inline', packageDir = '/'): GeneratorRegistry {
        const generators: RegisteredGenerator[] = [];
        const problems: ManifestError[] = [];
        manifests.forEach((json, i) => {
            const field = `generators[${i}]`;
            try {
                const manifest = validateManifest(json, { packageName, file: '(inline)', field });
                generators.push({ manifest, source: { packageName, packageVersion: '0.0.0', packageDir, file: '(inline)', field } });
            } catch (e) {
                if (e instanceof ManifestError) problems.push(e);
                else throw e;
            }
        });
        return new GeneratorRegistry(generators, problems);
    }

    get(name: string): RegisteredGenerator | undefined {
        return this.byName.get(name);
    }

    /** Every generator, sorted by name. */
    all(): RegisteredGenerator[] {
        return [...this.byName.values()].sort((a, b) => compare(a.manifest.name, b.manifest.name));
    }

    /** Problems with the manifests of one package. */
    problemsOf(packageName: string): ManifestError[] {
        return this.problems.filter((p) => p.packageName === packageName);
    }
}
