import { WorkspaceCache, type AstNodeDescription, type IndexManager, type LangiumSharedCoreServices } from 'langium';
import type { ModelRoots } from '../model-roots.js';

type Table = Map<string, AstNodeDescription[]>;

/**
 * The exported symbols of each model root (plus the built-in library) by qualified name.
 * Built in one pass over the index after every workspace change, so lookups stay O(1) even
 * when hundreds of roots are checked together.
 */
export class RootIndex {
    private readonly cache: WorkspaceCache<'tables', Map<string, Table>>;

    constructor(
        shared: LangiumSharedCoreServices,
        private readonly indexManager: IndexManager,
        private readonly roots: ModelRoots,
    ) {
        this.cache = new WorkspaceCache(shared);
    }

    /** All symbols named `qualifiedName` visible from documents of `root`. */
    lookup(root: string, qualifiedName: string): readonly AstNodeDescription[] {
        const tables = this.tables();
        const own = tables.get(root)?.get(qualifiedName);
        const builtin = tables.get(this.builtinRoot())?.get(qualifiedName);
        if (own && builtin && root !== this.builtinRoot()) return [...own, ...builtin];
        return own ?? builtin ?? [];
    }

    /** All symbols visible from documents of `root`. */
    all(root: string): AstNodeDescription[] {
        const tables = this.tables();
        const own = [...(tables.get(root)?.values() ?? [])].flat();
        if (root === this.builtinRoot()) return own;
        return [...own, ...[...(tables.get(this.builtinRoot())?.values() ?? [])].flat()];
    }

    /** Whether some visible symbol's qualified name starts with `prefix.` (a package prefix). */
    isPackagePrefix(root: string, prefix: string): boolean {
        const p = `${prefix}.`;
        const tables = this.tables();
        for (const t of [tables.get(root), tables.get(this.builtinRoot())]) {
            for (const key of t?.keys() ?? []) if (key.startsWith(p)) return true;
        }
        return false;
    }

    private builtinRoot(): string {
        return this.roots.rootOf('builtin:/x');
    }

    private tables(): Map<string, Table> {
        return this.cache.get('tables', () => {
            const tables = new Map<string, Table>();
            const rootOfDoc = new Map<string, string>();
            for (const d of this.indexManager.allElements()) {
                const uri = d.documentUri.toString();
                let root = rootOfDoc.get(uri);
                if (root === undefined) {
                    root = this.roots.rootOf(d.documentUri);
                    rootOfDoc.set(uri, root);
                }
                let table = tables.get(root);
                if (!table) tables.set(root, (table = new Map()));
                const list = table.get(d.name);
                if (list) list.push(d);
                else table.set(d.name, [d]);
            }
            return tables;
        });
    }
}
