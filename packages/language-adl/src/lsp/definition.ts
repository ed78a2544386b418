import type { AstNode, CstNode, MaybePromise } from 'langium';
import { DefaultDefinitionProvider, type LangiumServices } from 'langium/lsp';
import { LocationLink, type Range } from 'vscode-languageserver-types';
import type { DefinitionParams } from 'vscode-languageserver-protocol';

/** Where a declaration that lives outside the model documents is (e.g. a generator manifest). */
export type DefinitionTarget = (target: AstNode) => MaybePromise<{ uri: string; range: Range } | undefined>;

/**
 * Go to definition for every language of the family. Declarations inside model documents are
 * Langium's default; `targets` lets a language resolve declarations that live elsewhere, such
 * as the generator names of `.arcapp` files, which point into `package.json` manifests.
 */
export class AdlDefinitionProvider extends DefaultDefinitionProvider {
    readonly targets: DefinitionTarget[] = [];

    constructor(services: LangiumServices) {
        super(services);
    }

    protected override async collectLocationLinks(sourceCstNode: CstNode, params: DefinitionParams): Promise<LocationLink[] | undefined> {
        const links = await super.collectLocationLinks(sourceCstNode, params);
        if (links && links.length > 0) return links;
        const out: LocationLink[] = [];
        for (const target of this.references.findDeclarations(sourceCstNode)) {
            for (const resolve of this.targets) {
                const found = await resolve(target);
                if (found) {
                    out.push(LocationLink.create(found.uri, found.range, found.range, sourceCstNode.range));
                    break;
                }
            }
        }
        return out.length > 0 ? out : undefined;
    }
}
