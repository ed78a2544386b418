import { DocumentState, WorkspaceCache, type LangiumSharedCoreServices } from 'langium';
import type { ComponentType, Subcomponent } from '../../generated/ast.js';
import { allPorts, type PortInfo } from '../../components/component-model.js';
import { currentVariant, inSubcomponent } from '../../components/variant-context.js';
import type { Substitution } from '../../types/sym-type.js';

/**
 * Facts about component types that the connector checks need once per subcomponent (the ports
 * of its type, the instantaneous paths through it), computed once per component type instead:
 * a top component with 1,000 subcomponents listed the ports of each type three times and the
 * paths of each composed type again for every component that instantiates it (issue 18).
 *
 * Only what does not depend on the variant being checked is kept: without a configuration
 * (`currentVariant()` undefined, every check of a component without variability) and without
 * type arguments (a generic instantiation's substitution is a new map each time). In a
 * configuration, or with type arguments, every call computes afresh, as before.
 * The cache is cleared whenever documents are (re)linked and when documents are deleted
 * (a WorkspaceCache on DocumentState.Linked): ports hold types resolved through references.
 */
export class ComponentFacts {
    private readonly ports: WorkspaceCache<ComponentType, readonly PortInfo[]>;
    private readonly paths: WorkspaceCache<ComponentType, ReadonlyArray<readonly [string, string]>>;

    constructor(shared: LangiumSharedCoreServices) {
        this.ports = new WorkspaceCache(shared, DocumentState.Linked);
        this.paths = new WorkspaceCache(shared, DocumentState.Linked);
    }

    /** allPorts(decl, subst) as subcomponent `sub` sees it (in its configuration). Do not mutate the result. */
    portsOfSub(sub: Subcomponent, decl: ComponentType, subst: Substitution): readonly PortInfo[] {
        if (currentVariant() || subst.size > 0) return inSubcomponent(sub, () => allPorts(decl, subst));
        return this.ports.get(decl, () => allPorts(decl));
    }

    /** allPorts(c) of a component read in the current configuration. Do not mutate the result. */
    portsOf(c: ComponentType): readonly PortInfo[] {
        if (currentVariant()) return allPorts(c);
        return this.ports.get(c, () => allPorts(c));
    }

    /** The instantaneous paths of a component type kept by storePaths, outside configurations. */
    cachedPaths(decl: ComponentType): ReadonlyArray<readonly [string, string]> | undefined {
        return currentVariant() ? undefined : this.paths.get(decl);
    }

    /** Keeps the instantaneous paths of a component type (outside configurations; only results that do not depend on where the walk began). */
    storePaths(decl: ComponentType, paths: ReadonlyArray<readonly [string, string]>): void {
        if (!currentVariant()) this.paths.set(decl, paths);
    }
}
