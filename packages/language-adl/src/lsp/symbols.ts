import type { AstNode, CstNode, LangiumDocument } from 'langium';
import { DefaultDocumentSymbolProvider } from 'langium/lsp';
import type { DocumentSymbol, SymbolKind } from 'vscode-languageserver-types';
import type { AdlLspServices } from './lsp-module.js';
import { detail } from './descriptions.js';

/** How a node appears in the outline. */
export interface SymbolDescription {
    readonly name: string;
    /** Defaults to the node kind provider's kind for the node's `$type`. */
    readonly kind?: SymbolKind;
    readonly detail?: string;
    /** The part selected when the symbol is revealed (defaults to the node's name). */
    readonly selection?: CstNode;
}

/**
 * The outline entry of a node: a description, `'skip'` (the node and everything inside it is
 * left out) or undefined (the default: named nodes appear, with their children).
 */
export type SymbolContribution = (node: AstNode) => SymbolDescription | 'skip' | undefined;

/** Named elements that are no structure of a model (they would only clutter the outline). */
const HIDDEN = new Set(['StereoValue', 'LocalVariable', 'CDMethodParameter', 'PrimitiveType']);

/**
 * Document symbols (outline, breadcrumbs): components with their parameters, ports, fields,
 * subcomponents and inner components, class-diagram types with their members, and whatever
 * behavior languages contribute (states, transitions, ...) through `contributions`.
 */
export class AdlDocumentSymbolProvider extends DefaultDocumentSymbolProvider {
    readonly contributions = new Map<string, SymbolContribution>();

    constructor(services: AdlLspServices) {
        super(services);
    }

    protected override getSymbol(document: LangiumDocument, astNode: AstNode): DocumentSymbol[] {
        if (HIDDEN.has(astNode.$type)) return [];
        const contributed = this.contributions.get(astNode.$type)?.(astNode);
        if (contributed === 'skip') return [];
        const cst = astNode.$cstNode;
        if (contributed && cst) {
            return [
                {
                    name: contributed.name,
                    kind: contributed.kind ?? this.nodeKindProvider.getSymbolKind(astNode),
                    detail: contributed.detail,
                    range: cst.range,
                    selectionRange: (contributed.selection ?? this.nameProvider.getNameNode(astNode) ?? cst).range,
                    children: this.getChildSymbols(document, astNode),
                },
            ];
        }
        return super.getSymbol(document, astNode);
    }

    protected override createSymbol(
        document: LangiumDocument,
        astNode: AstNode,
        cstNode: CstNode,
        nameNode: CstNode,
        computedName?: string,
    ): DocumentSymbol {
        const symbol = super.createSymbol(document, astNode, cstNode, nameNode, computedName);
        const d = detail(astNode);
        return d ? { ...symbol, detail: d } : symbol;
    }
}
