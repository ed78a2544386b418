import { DefaultScopeComputation, type AstNodeDescription, type LangiumDocument, type LocalSymbols, MultiMap } from 'langium';
import { isArcModel, isCDModel } from '../generated/ast.js';

/**
 * Exports of a model file: its top-level component as `package.Name`, and every class-diagram
 * type both as `package.Diagram.Type` and `package.Type` (MontiArc accepts both import forms).
 * Everything below the top level is resolved by the scope provider directly from the AST.
 */
export class AdlScopeComputation extends DefaultScopeComputation {
    override async collectExportedSymbols(document: LangiumDocument): Promise<AstNodeDescription[]> {
        const root = document.parseResult.value;
        const out: AstNodeDescription[] = [];
        if (isArcModel(root) && root.component?.name) {
            const name = qualify(root.package, root.component.name);
            out.push(this.descriptions.createDescription(root.component, name, document));
        } else if (isCDModel(root) && root.diagram) {
            for (const element of root.diagram.elements) {
                if (element.$type === 'CDAssociation' || !element.name) continue;
                const diagramQualified = qualify(qualify(root.package, root.diagram.name), element.name);
                out.push(this.descriptions.createDescription(element, diagramQualified, document));
                out.push(this.descriptions.createDescription(element, qualify(root.package, element.name), document));
            }
        }
        return out;
    }

    // Local scopes are computed on demand by AdlScopeProvider; nothing to precompute.
    override async collectLocalSymbols(): Promise<LocalSymbols> {
        return new MultiMap<never, AstNodeDescription>();
    }
}

export function qualify(prefix: string | undefined, name: string): string {
    return prefix ? `${prefix}.${name}` : name;
}
