import {
    AstUtils,
    CstUtils,
    GrammarUtils,
    isCompositeCstNode,
    type AstNode,
    type CstNode,
    type LangiumDocument,
    type LangiumSharedCoreServices,
} from 'langium';
import { cdExportedNamesOf } from '@maa/language-cd';
import type { CDEnum, CDType, FieldAccessExpression } from '../generated/ast.js';
import { isArcModel, isComponentType } from '../generated/ast.js';
import type { AdlSharedServices } from '../adl-module.js';
import type { ExpressionTyper } from '../types/expression-typer.js';
import type { TypeRelations } from '../types/type-relations.js';
import type { SymType } from '../types/sym-type.js';
import { qualify } from '../scoping/adl-scope-computation.js';

/**
 * Facts about AST and CST nodes that several LSP providers share: source text, documentation
 * comments, qualified names, member accesses (`Type.CONSTANT`) and the documents of a model root.
 */

/** The source text of a node with runs of whitespace (and comments) collapsed to one space. */
export function sourceText(node: AstNode | CstNode | undefined): string {
    const cst = node && ('$cstNode' in node ? (node as AstNode).$cstNode : (node as CstNode));
    if (!cst) return '';
    const leaves = CstUtils.flattenCst(cst)
        .filter((l) => !l.hidden)
        .toArray();
    let out = '';
    for (let i = 0; i < leaves.length; i++) {
        const leaf = leaves[i]!;
        const prev = leaves[i - 1];
        if (prev && prev.end < leaf.offset) out += ' ';
        out += leaf.text;
    }
    return out;
}

/** The last leaf of a CST node that is not hidden (e.g. the last segment of a qualified name). */
export function lastLeaf(cst: CstNode): CstNode {
    let last: CstNode = cst;
    for (const leaf of CstUtils.flattenCst(cst)) if (!leaf.hidden) last = leaf;
    return last;
}

/** The leaf before a CST node in document order, hidden leaves (comments) included. */
export function previousLeaf(cst: CstNode): CstNode | undefined {
    for (let n: CstNode | undefined = cst; n; n = n.container) {
        const parent = n.container;
        if (!parent) return undefined;
        const i = parent.content.indexOf(n);
        for (let j = i - 1; j >= 0; j--) {
            const leaf = lastLeafIncludingHidden(parent.content[j]!);
            if (leaf) return leaf;
        }
    }
    return undefined;
}

/** The leaf after a CST node in document order, hidden leaves included. */
export function nextLeaf(cst: CstNode): CstNode | undefined {
    for (let n: CstNode | undefined = cst; n; n = n.container) {
        const parent = n.container;
        if (!parent) return undefined;
        const i = parent.content.indexOf(n);
        for (let j = i + 1; j < parent.content.length; j++) {
            const leaf = firstLeafIncludingHidden(parent.content[j]!);
            if (leaf) return leaf;
        }
    }
    return undefined;
}

function lastLeafIncludingHidden(cst: CstNode): CstNode | undefined {
    if (!isCompositeCstNode(cst)) return cst;
    for (let i = cst.content.length - 1; i >= 0; i--) {
        const leaf = lastLeafIncludingHidden(cst.content[i]!);
        if (leaf) return leaf;
    }
    return undefined;
}

function firstLeafIncludingHidden(cst: CstNode): CstNode | undefined {
    if (!isCompositeCstNode(cst)) return cst;
    for (const c of cst.content) {
        const leaf = firstLeafIncludingHidden(c);
        if (leaf) return leaf;
    }
    return undefined;
}

function isComment(cst: CstNode): boolean {
    return cst.hidden && /^\/[/*]/.test(cst.text);
}

/** The text of a comment without its markers (`//`, `/*`, `*&#47;`, leading `*` of each line). */
export function commentText(comment: string): string {
    if (comment.startsWith('//')) return comment.replace(/^\/\/+\s?/, '').trimEnd();
    const body = comment.replace(/^\/\*+/, '').replace(/\*+\/$/, '');
    const lines = body.split(/\r?\n/).map((l) => l.replace(/^\s*\*(?!\/)\s?/, '').trimEnd());
    while (lines.length > 0 && lines[0]!.trim() === '') lines.shift();
    while (lines.length > 0 && lines[lines.length - 1]!.trim() === '') lines.pop();
    const indent = Math.min(...lines.filter((l) => l.trim()).map((l) => /^\s*/.exec(l)![0].length));
    return lines.map((l) => l.substring(Number.isFinite(indent) ? indent : 0)).join('\n');
}

/**
 * The comments directly before a node (no blank line in between, none of them trailing a
 * previous element on its line), and a comment after it on the same line: MontiArc models
 * document elements with `//` and `/* *&#47;` comments either way.
 */
export function documentationComments(node: AstNode): string[] {
    const cst = node.$cstNode;
    if (!cst) return [];
    const out: string[] = [];
    let anchorLine = cst.range.start.line;
    for (let prev = previousLeaf(cst); prev && isComment(prev); prev = previousLeaf(prev)) {
        if (anchorLine - prev.range.end.line > 1) break;
        const before = previousLeaf(prev);
        if (before && !before.hidden && before.range.end.line === prev.range.start.line) break; // trails another element
        out.unshift(commentText(prev.text));
        anchorLine = prev.range.start.line;
    }
    const endLine = cst.range.end.line;
    for (let next = nextLeaf(cst); next && next.range.start.line === endLine; next = nextLeaf(next)) {
        if (isComment(next)) {
            if (next.range.end.line === endLine || next.text.startsWith('//')) out.push(commentText(next.text));
            break;
        }
        if (!/^[,;]$/.test(next.text)) break;
    }
    return out.filter((c) => c.length > 0);
}

/**
 * The documentation of a node: its own comments, else (for the elements of a comma list such as
 * `port in int a, in int b;`) the comments of the declaration when the node is its first element.
 */
export function documentation(node: AstNode): string | undefined {
    const own = documentationComments(node);
    if (own.length > 0) return own.join('\n\n');
    const container = node.$container;
    const property = node.$containerProperty;
    if (container && property && !isComponentType(node)) {
        const list = (container as unknown as Record<string, unknown>)[property];
        if (
            Array.isArray(list) &&
            list[0] === node &&
            list.length >= 1 &&
            ['PortDeclaration', 'FieldDeclaration', 'ComponentInstantiation'].includes(container.$type)
        ) {
            const outer = documentationComments(container);
            if (outer.length > 0) return outer.join('\n\n');
        }
    }
    return undefined;
}

/** The qualified names under which a top-level element is exported (see AdlScopeComputation). */
export function exportedNames(node: AstNode): string[] {
    const container = node.$container;
    if (isComponentType(node) && isArcModel(container)) return [qualify(container.package, node.name)];
    return cdExportedNamesOf(node);
}

/** The shortest qualified name of an exported element (the one to import). */
export function importName(node: AstNode): string | undefined {
    const names = exportedNames(node);
    return names.sort((a, b) => a.length - b.length)[0];
}

/** The documents of the model root a document belongs to (built-in library excluded). */
export function rootDocuments(shared: AdlSharedServices | LangiumSharedCoreServices, uri: LangiumDocument['uri']): LangiumDocument[] {
    const roots = (shared as AdlSharedServices).maa.ModelRoots;
    return shared.workspace.LangiumDocuments.all.filter((d) => !roots.isBuiltin(d.uri) && roots.visible(uri, d.uri)).toArray();
}

/** Whether a node belongs to the built-in library (never renamed or edited). */
export function isBuiltinNode(shared: AdlSharedServices, node: AstNode): boolean {
    const document = documentOf(node);
    return document !== undefined && shared.maa.ModelRoots.isBuiltin(document.uri);
}

/**
 * The document a node belongs to, or undefined for a declaration that lives outside the model
 * documents: scopes may resolve names to synthetic nodes (the generators of an `.arcapp` stand
 * for registry entries), and `AstUtils.getDocument` throws "AST node has no document" on them.
 */
export function documentOf(node: AstNode): LangiumDocument | undefined {
    return AstUtils.findRootNode(node).$document;
}

/**
 * The element a member access names, e.g. the enum constant in `ToasterCmd.STOP` or the
 * attribute in `target.speed`: member names are not cross-references (they depend on the type
 * of the receiver), so the LSP providers resolve them through the expression typer.
 */
export function resolveMember(fa: FieldAccessExpression, typer: ExpressionTyper, rel: TypeRelations): AstNode | undefined {
    if (!fa.receiver || !fa.member) return undefined;
    return membersOf(typer.typeOf(fa.receiver, []), rel).find((m) => m.name === fa.member)?.node;
}

export interface MemberInfo {
    readonly name: string;
    readonly node: AstNode;
    readonly kind: 'constant' | 'attribute' | 'method';
}

/** The members a value or a type qualifier offers after `.`. */
export function membersOf(type: SymType, rel: TypeRelations): MemberInfo[] {
    if (type.kind === 'qualifier') {
        const decl = type.typeDecl;
        if (!decl) return [];
        if (decl.$type === 'CDEnum')
            return [
                ...(decl as CDEnum).constants.map((c) => ({ name: c.name, node: c, kind: 'constant' as const })),
                ...classMembers(decl),
            ];
        return classMembers(decl);
    }
    const obj = type.kind === 'typevar' ? undefined : rel.box(type);
    if (obj?.kind !== 'object') return [];
    const out: MemberInfo[] = [];
    const seen = new Set<AstNode>();
    const queue: SymType[] = [obj];
    while (queue.length > 0) {
        const t = queue.shift()!;
        if (t.kind !== 'object' || seen.has(t.decl)) continue;
        seen.add(t.decl);
        for (const m of classMembers(t.decl)) if (!out.some((o) => o.name === m.name)) out.push(m);
        queue.push(...rel.directSupertypes(t));
    }
    return out;
}

function classMembers(decl: CDType): MemberInfo[] {
    return decl.members.map((m) => ({
        name: m.name,
        node: m,
        kind: m.$type === 'CDMethod' ? ('method' as const) : ('attribute' as const),
    }));
}

/** The CST node of a named node's name, if any. */
export function nameNode(node: AstNode): CstNode | undefined {
    return GrammarUtils.findNodeForProperty(node.$cstNode, 'name');
}

/** The indentation (leading whitespace) of the line a position is on. */
export function lineIndentation(document: LangiumDocument, line: number): string {
    const text = document.textDocument.getText({ start: { line, character: 0 }, end: { line: line + 1, character: 0 } });
    return /^[ \t]*/.exec(text)![0];
}

/** Whether a string is a valid identifier of the family (`Name` without keywords). */
export function isIdentifier(name: string): boolean {
    return /^[_a-zA-Z$][\w$]*$/.test(name);
}
