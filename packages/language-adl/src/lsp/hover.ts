import type { AstNode, LangiumDocument, MaybePromise, ServiceRegistry } from 'langium';
import type { Hover, HoverParams } from 'vscode-languageserver-protocol';
import { AstNodeHoverProvider } from 'langium/lsp';
import type { AdlLspServices } from './lsp-module.js';
import { autoConnectHover } from './autoconnect-hover.js';
import { describe } from './descriptions.js';
import { documentation, documentOf } from './node-info.js';

/**
 * Hover text for a declaration, in Markdown (a fenced signature and a sentence or two); the
 * element's documentation comment is appended by the provider.
 */
export type HoverContribution = (node: AstNode) => string | undefined;

/**
 * Hover: the type and role of the element a name denotes (ports with direction, type and
 * timing; components with their parameters and ports; ...) and the comments written before the
 * element (or after it on its line) as its documentation. Behavior languages describe their own
 * node types through `contributions` (keyed by AST `$type`).
 */
export class AdlHoverProvider extends AstNodeHoverProvider {
    readonly contributions = new Map<string, HoverContribution>();
    private readonly registry: ServiceRegistry;

    constructor(services: AdlLspServices) {
        super(services);
        this.registry = services.shared.ServiceRegistry;
    }

    /** The Markdown describing an element (also used for completion documentation). */
    describeNode(node: AstNode): string | undefined {
        try {
            const contributed = this.contributions.get(node.$type);
            const body = contributed ? contributed(node) : describe(node, (n) => this.languageOf(n));
            const doc = documentation(node);
            const parts = [body, doc].filter((p): p is string => !!p);
            return parts.length > 0 ? parts.join('\n\n---\n\n') : undefined;
        } catch {
            // A model being typed may be partial; a description is never worth an error.
            return undefined;
        }
    }

    /** The language id of the document a node is in (for fenced code; `arc` for declarations outside the model files). */
    languageOf(node: AstNode): string {
        const uri = documentOf(node)?.uri;
        return uri && this.registry.hasServices(uri) ? this.registry.getServices(uri).LanguageMetaData.languageId : 'arc';
    }

    override async getHoverContent(document: LangiumDocument, params: HoverParams): Promise<Hover | undefined> {
        return autoConnectHover(document, params) ?? super.getHoverContent(document, params);
    }

    protected override getAstNodeHoverContent(node: AstNode): MaybePromise<string | undefined> {
        return this.describeNode(node);
    }
}
