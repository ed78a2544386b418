import { cdTypeNamed } from '@maa/language-cd';
import { AstUtils, type AstNode, type AstNodeDescription, type AstNodeDescriptionProvider, type LangiumDocument } from 'langium';
import type { ArcModel, CDModel, ComponentType, TypeParameter } from '../generated/ast.js';
import { isArcModel, isCDClass, isCDMethod, isCDModel, isComponentType } from '../generated/ast.js';
import { elementsOf } from '../components/component-model.js';
import type { ModelRoots } from '../model-roots.js';
import type { RootIndex } from './root-index.js';
import { qualify } from './adl-scope-computation.js';

type Kind = 'type' | 'component';
const TYPE_KINDS = new Set(['CDClass', 'CDEnum']);
const COMPONENT_KINDS = new Set(['ComponentType']);

/**
 * Resolution of (qualified) type and component names in the context of a model element:
 * type parameters, inner components, imports (`a.b.X`, `a.b.*`, `a.b.Diagram.*`), the file's own
 * package, `java.lang`, and fully qualified names, restricted to the element's model root.
 */
export class NameResolver {
    constructor(
        private readonly index: RootIndex,
        private readonly roots: ModelRoots,
        private readonly descriptions: AstNodeDescriptionProvider,
    ) {}

    resolveType(context: AstNode, name: string): AstNodeDescription | undefined {
        if (!name.includes('.')) {
            const tp = this.typeParameter(context, name);
            if (tp) return this.descriptions.createDescription(tp, tp.name);
            const local = this.sameDiagramType(context, name);
            if (local) return local;
        }
        return this.resolveGlobal(context, name, 'type');
    }

    resolveComponent(context: AstNode, name: string): AstNodeDescription | undefined {
        if (!name.includes('.')) {
            for (
                let c = AstUtils.getContainerOfType(context, isComponentType);
                c;
                c = AstUtils.getContainerOfType(c.$container, isComponentType)
            ) {
                const inner = elementsOf(c).find((e): e is ComponentType => isComponentType(e) && e.name === name);
                if (inner) return this.descriptions.createDescription(inner, inner.name);
            }
            const top = AstUtils.getDocument(context).parseResult.value;
            if (isArcModel(top) && top.component?.name === name) {
                return this.descriptions.createDescription(top.component, name);
            }
        }
        return this.resolveGlobal(context, name, 'component');
    }

    /** Visible type and component names for completion. */
    visible(context: AstNode, kind: Kind): AstNodeDescription[] {
        const doc = AstUtils.getDocument(context);
        const kinds = kind === 'type' ? TYPE_KINDS : COMPONENT_KINDS;
        return [...this.index.all(this.roots.rootOf(doc.uri))].filter((d) => kinds.has(d.type));
    }

    isPackagePrefix(context: AstNode, prefix: string): boolean {
        return this.index.isPackagePrefix(this.roots.rootOf(AstUtils.getDocument(context).uri), prefix);
    }

    private typeParameter(context: AstNode, name: string): TypeParameter | undefined {
        for (let n: AstNode | undefined = context; n; n = n.$container) {
            if (isCDMethod(n) || isCDClass(n)) {
                const tp = n.typeParams.find((p) => p.name === name);
                if (tp) return tp;
            }
            // Inner component types do not see the type parameters of the enclosing one.
            if (isComponentType(n)) return n.typeParams.find((p) => p.name === name);
        }
        return undefined;
    }

    private sameDiagramType(context: AstNode, name: string): AstNodeDescription | undefined {
        const t = cdTypeNamed(AstUtils.getDocument(context).parseResult.value, name);
        return t ? this.descriptions.createDescription(t, name) : undefined;
    }

    private resolveGlobal(context: AstNode, name: string, kind: Kind): AstNodeDescription | undefined {
        const doc = AstUtils.getDocument(context);
        const root = this.roots.rootOf(doc.uri);
        const kinds = kind === 'type' ? TYPE_KINDS : COMPONENT_KINDS;
        const find = (qn: string): AstNodeDescription | undefined => this.index.lookup(root, qn).find((d) => kinds.has(d.type));
        const { pkg, imports } = fileHeader(doc);
        if (name.includes('.')) {
            return find(name);
        }
        for (const imp of imports) {
            if (!imp.endsWith('.*') && (imp === name || imp.endsWith(`.${name}`))) {
                const d = find(imp);
                if (d) return d;
            }
        }
        const samePackage = find(qualify(pkg, name));
        if (samePackage) return samePackage;
        for (const imp of imports) {
            if (imp.endsWith('.*')) {
                const d = find(`${imp.slice(0, -2)}.${name}`);
                if (d) return d;
            }
        }
        return find(`java.lang.${name}`) ?? find(name);
    }
}

function fileHeader(doc: LangiumDocument): { pkg: string | undefined; imports: string[] } {
    const top = doc.parseResult.value as ArcModel | CDModel;
    if (isArcModel(top) || isCDModel(top)) {
        return { pkg: top.package, imports: top.imports.flatMap((i) => (i.importedNamespace ? [i.importedNamespace] : [])) }; // partially parsed imports have no name
    }
    return { pkg: undefined, imports: [] };
}
