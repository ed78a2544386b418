import { AstUtils, GrammarUtils, type AstNode, type LangiumDocument } from 'langium';
import type { TextEdit } from 'vscode-languageserver-types';
import type { MCType } from '../generated/ast.js';
import type { NameResolver } from '../scoping/name-resolver.js';
import { importName, lineIndentation, nextLeaf, sourceText } from './node-info.js';

/** The indentation unit of the family's formatting style (MontiArc: two spaces). */
export const INDENT = '  ';

/**
 * Helpers for quick fixes that insert elements into `{ ... }` bodies (components, automata,
 * states): the new element goes on its own line, indented like its siblings.
 */

/** Inserts a line after `anchor` (after a comment trailing it on its line), indented like it. */
export function insertAfter(document: LangiumDocument, anchor: AstNode, text: string): TextEdit {
    const cst = anchor.$cstNode!;
    let end = cst.range.end;
    const next = nextLeaf(cst);
    if (next?.hidden && next.range.start.line === end.line) end = next.range.end;
    const indent = lineIndentation(document, cst.range.start.line);
    return { range: { start: end, end }, newText: `\n${indent}${text}` };
}

/**
 * Inserts a line into the body of `container` (the node owning the `{` and `}` keywords): after
 * `anchor` if given, else as the first element; an empty one-line body `{ }` is opened up.
 */
export function insertIntoBody(document: LangiumDocument, container: AstNode, text: string, anchor?: AstNode): TextEdit | undefined {
    if (anchor?.$cstNode) return insertAfter(document, anchor, text);
    const open = GrammarUtils.findNodeForKeyword(container.$cstNode, '{');
    const close = GrammarUtils.findNodeForKeyword(container.$cstNode, '}');
    if (!open || !close) return undefined;
    const outer = lineIndentation(document, open.range.start.line);
    const inner = outer + INDENT;
    if (open.range.start.line === close.range.start.line) {
        const between = document.textDocument.getText({ start: open.range.end, end: close.range.start });
        if (between.trim() === '') {
            return { range: { start: open.range.end, end: close.range.start }, newText: `\n${inner}${text}\n${outer}` };
        }
    }
    return { range: { start: open.range.end, end: open.range.end }, newText: `\n${inner}${text}` };
}

/**
 * The text of a type for use in another model element: as written if it denotes the same type
 * there, else with the type's qualified name.
 */
export function typeTextFor(type: MCType | undefined, context: AstNode, resolver: NameResolver): string | undefined {
    if (!type) return undefined;
    const text = sourceText(type);
    let base: AstNode | undefined = type;
    while (base && base.$type === 'ArrayType') base = (base as unknown as { component: AstNode }).component;
    if (base?.$type !== 'ReferenceType') return text;
    const ref = (base as unknown as { ref: { ref?: AstNode; $refText: string } }).ref;
    const target = ref.ref;
    if (!target) return text;
    if (AstUtils.getDocument(type) === AstUtils.getDocument(context)) return text;
    const there = resolver.resolveType(context, ref.$refText);
    if (there?.node === target) return text;
    const qn = importName(target);
    return qn ? text.replace(ref.$refText, qn) : text;
}

/** The edit that replaces a node's text. */
export function replaceNode(node: AstNode, text: string): TextEdit | undefined {
    const cst = node.$cstNode;
    return cst ? { range: cst.range, newText: text } : undefined;
}
