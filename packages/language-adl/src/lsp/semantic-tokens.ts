import { AstUtils, GrammarUtils, type AstNode, type CstNode, type Reference } from 'langium';
import { AbstractSemanticTokenProvider, type SemanticTokenAcceptor } from 'langium/lsp';
import { SemanticTokenModifiers, SemanticTokenTypes } from 'vscode-languageserver-types';
import type { AdlLspServices } from './lsp-module.js';
import type { Port } from '../generated/ast.js';
import { isFieldAccessExpression } from '../generated/ast.js';
import { portHeader } from '../components/component-model.js';
import type { ModelRoots } from '../model-roots.js';
import { lastLeaf, resolveMember } from './node-info.js';

/** The semantic token of a kind of element (its declaration and every reference to it). */
export interface TokenStyle {
    readonly type: string;
    readonly modifiers?: readonly string[];
}

/** The token style of a declaration node, by its `$type` (a function for styles that depend on the node). */
export type TokenStyleContribution = TokenStyle | ((node: AstNode) => TokenStyle | undefined);

/**
 * Highlights a node beyond the generic rules (e.g. keywords that are names elsewhere); may return
 * `'prune'` to skip the node's content.
 */
export type HighlightContribution = (node: AstNode, acceptor: SemanticTokenAcceptor) => void | 'prune';

/**
 * Semantic highlighting for the whole family. Names are colored by what they denote, at the
 * declaration and at every use, in every language of the family (a port in a connector, a guard
 * or a RobotArm `move` looks the same):
 *
 * | element | token |
 * |---|---|
 * | component type | `class` |
 * | port | `property` (`readonly` when incoming) |
 * | field | `variable` |
 * | configuration parameter | `parameter` |
 * | subcomponent | `variable` + `readonly` |
 * | class-diagram class / interface / enum | `type` / `interface` / `enum` |
 * | enum constant | `enumMember` |
 * | type parameter | `typeParameter` |
 * | automaton state (contributed) | `namespace` |
 * | stereotype | `decorator` |
 *
 * Declarations carry the `declaration` modifier, elements of the built-in library `defaultLibrary`.
 * Behavior languages add styles for their node types (`styles`) and special cases (`highlighters`).
 */
export class AdlSemanticTokenProvider extends AbstractSemanticTokenProvider {
    readonly styles = new Map<string, TokenStyleContribution>([
        ['ComponentType', { type: SemanticTokenTypes.class }],
        [
            'Port',
            (n) => ({
                type: SemanticTokenTypes.property,
                modifiers: portHeader(n as Port).direction === 'in' ? [SemanticTokenModifiers.readonly] : [],
            }),
        ],
        ['Field', { type: SemanticTokenTypes.variable }],
        ['Feature', { type: SemanticTokenTypes.variable, modifiers: [SemanticTokenModifiers.readonly] }],
        ['Parameter', { type: SemanticTokenTypes.parameter }],
        ['Subcomponent', { type: SemanticTokenTypes.variable, modifiers: [SemanticTokenModifiers.readonly] }],
        ['LocalVariable', { type: SemanticTokenTypes.variable }],
        ['TypeParameter', { type: SemanticTokenTypes.typeParameter }],
        ['ClassDiagram', { type: SemanticTokenTypes.namespace }],
        [
            'CDClass',
            (n) => ({ type: (n as { kind?: string }).kind === 'interface' ? SemanticTokenTypes.interface : SemanticTokenTypes.type }),
        ],
        ['CDEnum', { type: SemanticTokenTypes.enum }],
        ['CDEnumConstant', { type: SemanticTokenTypes.enumMember }],
        ['CDAttribute', { type: SemanticTokenTypes.property }],
        ['CDMethod', { type: SemanticTokenTypes.method }],
        ['CDMethodParameter', { type: SemanticTokenTypes.parameter }],
    ]);
    readonly highlighters = new Map<string, HighlightContribution>();
    private readonly services: AdlLspServices;
    private readonly roots: ModelRoots;

    constructor(services: AdlLspServices) {
        super(services);
        this.services = services;
        this.roots = services.shared.maa.ModelRoots;
    }

    /** The style of an element, if it has one. */
    styleOf(node: AstNode): TokenStyle | undefined {
        const s = this.styles.get(node.$type);
        return typeof s === 'function' ? s(node) : s;
    }

    protected override highlightElement(node: AstNode, acceptor: SemanticTokenAcceptor): void | 'prune' {
        const contributed = this.highlighters.get(node.$type)?.(node, acceptor);
        if (contributed === 'prune') return 'prune';
        // Declarations.
        const own = this.styleOf(node);
        const name = own && GrammarUtils.findNodeForProperty(node.$cstNode, 'name');
        if (own && name) this.accept(acceptor, name, own, node, [SemanticTokenModifiers.declaration]);
        // References: colored like what they denote; qualified names on their last segment.
        for (const { reference } of AstUtils.streamReferences(node)) this.highlightReference(reference as Reference, acceptor);
        if (node.$type === 'StereoValue') {
            acceptor({ node, property: 'name' as never, type: SemanticTokenTypes.decorator });
        } else if (node.$type === 'AutoConnect') {
            // `port`, `type`, `off` after `autoconnect` (`type` and `off` are names elsewhere).
            acceptor({ node, property: 'kind' as never, type: SemanticTokenTypes.keyword });
        } else if (node.$type === 'YieldStatement') {
            // `yield` is a name elsewhere (a soft keyword).
            acceptor({ node, keyword: 'yield', type: SemanticTokenTypes.keyword });
        } else if (node.$type === 'PrimitiveType') {
            acceptor({ node, property: 'name' as never, type: SemanticTokenTypes.type, modifier: SemanticTokenModifiers.defaultLibrary });
        } else if (isFieldAccessExpression(node)) {
            const member = GrammarUtils.findNodeForProperty(node.$cstNode, 'member');
            const target = member && resolveMember(node, this.services.maa.ExpressionTyper, this.services.maa.TypeRelations);
            const style = target && this.styleOf(target);
            if (member && target && style) this.accept(acceptor, member, style, target);
        }
    }

    private highlightReference(reference: Reference, acceptor: SemanticTokenAcceptor): void {
        const target = reference.ref;
        const cst = reference.$refNode;
        if (!target || !cst) return;
        const style = this.styleOf(target);
        if (style) this.accept(acceptor, lastLeaf(cst), style, target);
    }

    private accept(acceptor: SemanticTokenAcceptor, cst: CstNode, style: TokenStyle, target: AstNode, extra: string[] = []): void {
        const modifiers = [...(style.modifiers ?? []), ...extra];
        const doc = target.$cstNode ? AstUtils.getDocument(target) : undefined;
        if (doc && this.roots.isBuiltin(doc.uri)) modifiers.push(SemanticTokenModifiers.defaultLibrary);
        acceptor({ cst, type: style.type, modifier: modifiers });
    }
}
