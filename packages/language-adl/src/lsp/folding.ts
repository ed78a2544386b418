import { CstUtils, type CstNode, type LangiumDocument } from 'langium';
import { DefaultFoldingRangeProvider, type FoldingRangeAcceptor } from 'langium/lsp';
import type { FoldingRangeParams } from 'vscode-languageserver-protocol';
import { FoldingRange, FoldingRangeKind } from 'vscode-languageserver-types';
import { isArcModel, isCDModel } from '../generated/ast.js';

/**
 * Folding: every element spanning three or more lines (components, automata, states, blocks,
 * class-diagram types, long port lists), at most one region per start line, plus the import
 * list and runs of `//` comments.
 */
export class AdlFoldingRangeProvider extends DefaultFoldingRangeProvider {
    override getFoldingRanges(document: LangiumDocument, params: FoldingRangeParams): FoldingRange[] {
        const ranges = super.getFoldingRanges(document, params) as FoldingRange[];
        const byLine = new Map<number, FoldingRange>();
        for (const r of ranges) {
            const existing = byLine.get(r.startLine);
            if (!existing || existing.endLine < r.endLine) byLine.set(r.startLine, r);
        }
        return [...byLine.values()].sort((a, b) => a.startLine - b.startLine);
    }

    /** A region ends before the line of its closing `}` (also `};` of a state). */
    protected override includeLastFoldingLine(node: CstNode, kind?: FoldingRangeKind): boolean {
        if (/[)}\]];?$/.test(node.text.trimEnd())) return false;
        return super.includeLastFoldingLine(node, kind);
    }

    protected override collectFolding(document: LangiumDocument, acceptor: FoldingRangeAcceptor): void {
        super.collectFolding(document, acceptor);
        const root = document.parseResult.value;
        if ((isArcModel(root) || isCDModel(root)) && root.imports.length > 1) {
            const first = root.imports[0]!.$cstNode;
            const last = root.imports[root.imports.length - 1]!.$cstNode;
            if (first && last && last.range.end.line > first.range.start.line) {
                acceptor(FoldingRange.create(first.range.start.line, last.range.end.line, undefined, undefined, FoldingRangeKind.Imports));
            }
        }
        this.collectLineComments(document, acceptor);
    }

    /** Consecutive `//` comment lines fold as one comment. */
    private collectLineComments(document: LangiumDocument, acceptor: FoldingRangeAcceptor): void {
        const cst = document.parseResult.value.$cstNode;
        if (!cst) return;
        let start: number | undefined;
        let end = -1;
        const flush = (): void => {
            if (start !== undefined && end - start >= 1)
                acceptor(FoldingRange.create(start, end, undefined, undefined, FoldingRangeKind.Comment));
            start = undefined;
        };
        for (const leaf of CstUtils.flattenCst(cst)) {
            if (leaf.hidden && leaf.text.startsWith('//')) {
                const line = leaf.range.start.line;
                const alone = document.textDocument.getText({ start: { line, character: 0 }, end: leaf.range.start }).trim() === '';
                if (alone && start !== undefined && line === end + 1) {
                    end = line;
                    continue;
                }
                flush();
                if (alone) {
                    start = line;
                    end = line;
                }
            } else if (!leaf.hidden || !leaf.text.startsWith('//')) {
                flush();
            }
        }
        flush();
    }
}
