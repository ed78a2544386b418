import type { AstNode, AstNodeDescription } from 'langium';
import type { NodeKindProvider } from 'langium/lsp';
import { CompletionItemKind, SymbolKind } from 'vscode-languageserver-types';

export interface NodeKind {
    readonly symbol: SymbolKind;
    readonly completion: CompletionItemKind;
}

/**
 * Symbol and completion kinds (the icons in outline and completion lists) by AST `$type`, shared
 * by every language of the family. Behavior languages add their node types to `kinds`.
 */
export class AdlNodeKindProvider implements NodeKindProvider {
    readonly kinds = new Map<string, NodeKind>([
        ['ComponentType', { symbol: SymbolKind.Class, completion: CompletionItemKind.Class }],
        // Ports are the interface of a component.
        ['Port', { symbol: SymbolKind.Interface, completion: CompletionItemKind.Interface }],
        ['Field', { symbol: SymbolKind.Field, completion: CompletionItemKind.Field }],
        ['Feature', { symbol: SymbolKind.Boolean, completion: CompletionItemKind.Value }],
        ['Parameter', { symbol: SymbolKind.Constant, completion: CompletionItemKind.Constant }],
        ['Subcomponent', { symbol: SymbolKind.Object, completion: CompletionItemKind.Module }],
        ['TypeParameter', { symbol: SymbolKind.TypeParameter, completion: CompletionItemKind.TypeParameter }],
        ['LocalVariable', { symbol: SymbolKind.Variable, completion: CompletionItemKind.Variable }],
        ['ClassDiagram', { symbol: SymbolKind.Namespace, completion: CompletionItemKind.Module }],
        ['CDClass', { symbol: SymbolKind.Class, completion: CompletionItemKind.Struct }],
        ['CDEnum', { symbol: SymbolKind.Enum, completion: CompletionItemKind.Enum }],
        ['CDEnumConstant', { symbol: SymbolKind.EnumMember, completion: CompletionItemKind.EnumMember }],
        ['CDAttribute', { symbol: SymbolKind.Field, completion: CompletionItemKind.Field }],
        ['CDMethod', { symbol: SymbolKind.Method, completion: CompletionItemKind.Method }],
        ['CDMethodParameter', { symbol: SymbolKind.Variable, completion: CompletionItemKind.Variable }],
        ['CDAssociation', { symbol: SymbolKind.Property, completion: CompletionItemKind.Reference }],
    ]);

    getSymbolKind(node: AstNode | AstNodeDescription): SymbolKind {
        const type = typeOf(node);
        if (type === 'CDClass' && isInterface(node)) return SymbolKind.Interface;
        return this.kinds.get(type)?.symbol ?? SymbolKind.Field;
    }

    getCompletionItemKind(node: AstNode | AstNodeDescription): CompletionItemKind {
        const type = typeOf(node);
        if (type === 'CDClass' && isInterface(node)) return CompletionItemKind.Interface;
        return this.kinds.get(type)?.completion ?? CompletionItemKind.Reference;
    }
}

function typeOf(node: AstNode | AstNodeDescription): string {
    return '$type' in node ? node.$type : node.type;
}

function isInterface(node: AstNode | AstNodeDescription): boolean {
    const n = '$type' in node ? node : node.node;
    return (n as { kind?: string } | undefined)?.kind === 'interface';
}
