import { DefaultScopeComputation, type AstNodeDescription, type LangiumDocument, type LocalSymbols, MultiMap } from 'langium';
import { cdExportedNames, cdModelOf, cdTypesOf } from '@maa/language-cd';
import { isArcModel } from '../generated/ast.js';

/**
 * Exports of a model file: its top-level component as `package.Name`, and every class-diagram
 * type under the names @maa/language-cd gives it (`package.Diagram.Type` and `package.Type`).
 * Everything below the top level is resolved by the scope provider directly from the AST.
 */
export class AdlScopeComputation extends DefaultScopeComputation {
    override async collectExportedSymbols(document: LangiumDocument): Promise<AstNodeDescription[]> {
        const root = document.parseResult.value;
        const out: AstNodeDescription[] = [];
        const cd = cdModelOf(root);
        if (isArcModel(root) && root.component?.name) {
            const name = qualify(root.package, root.component.name);
            out.push(this.descriptions.createDescription(root.component, name, document));
        } else if (cd) {
            for (const type of cdTypesOf(cd)) {
                for (const name of cdExportedNames(cd, type)) out.push(this.descriptions.createDescription(type, name, document));
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
