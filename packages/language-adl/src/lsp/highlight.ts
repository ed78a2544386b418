import { CstUtils, UriUtils, type LangiumDocument, type MaybePromise } from 'langium';
import { DefaultDocumentHighlightProvider } from 'langium/lsp';
import type { DocumentHighlight, DocumentHighlightParams } from 'vscode-languageserver-protocol';
import { documentOf } from './node-info.js';

/**
 * Document highlight as Langium does it, for declarations outside the model documents too (the
 * generators of an `.arcapp`): Langium's provider asks for the target's document, which such a
 * declaration does not have; its uses in this document are highlighted without a declaration.
 */
export class AdlDocumentHighlightProvider extends DefaultDocumentHighlightProvider {
    override getDocumentHighlight(
        document: LangiumDocument,
        params: DocumentHighlightParams,
    ): MaybePromise<DocumentHighlight[] | undefined> {
        const root = document.parseResult.value.$cstNode;
        if (!root) return undefined;
        const selected = CstUtils.findDeclarationNodeAtOffset(
            root,
            document.textDocument.offsetAt(params.position),
            this.grammarConfig.nameRegexp,
        );
        if (!selected) return undefined;
        const highlights: DocumentHighlight[] = [];
        for (const target of this.references.findDeclarations(selected)) {
            const targetDocument = documentOf(target);
            const includeDeclaration = targetDocument !== undefined && UriUtils.equals(targetDocument.uri, document.uri);
            const references = this.references.findReferences(target, { documentUri: document.uri, includeDeclaration });
            highlights.push(...references.map((ref) => this.createDocumentHighlight(ref)).toArray());
        }
        return highlights;
    }
}
