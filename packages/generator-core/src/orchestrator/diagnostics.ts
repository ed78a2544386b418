import { AstUtils, GrammarUtils, type AstNode } from 'langium';
import type { CheckDiagnostic, Severity } from '@maa/language-adl';
import type { AppFinding } from '../app/app-checks.js';
import type { AppPlatform } from '../generated/ast.js';
import type { GenerationDiagnostic } from './types.js';

type Range = { start: { line: number; character: number }; end: { line: number; character: number } };

/** A diagnostic at a range of a file (1-based lines and columns, the check command's convention). */
export function at(
    root: string,
    file: string,
    range: Range | undefined,
    severity: Severity,
    code: string,
    message: string,
): GenerationDiagnostic {
    return {
        root,
        file,
        line: (range?.start.line ?? 0) + 1,
        column: (range?.start.character ?? 0) + 1,
        endLine: (range?.end.line ?? 0) + 1,
        endColumn: (range?.end.character ?? 0) + 1,
        severity,
        code,
        message,
    };
}

export function nodeDiagnostic(
    modelRoot: string,
    node: AstNode,
    severity: Severity,
    code: string,
    message: string,
    property?: string,
): GenerationDiagnostic {
    const doc = AstUtils.getDocument(node);
    const cst = (property ? node.$cstNode && findProperty(node, property) : undefined) ?? node.$cstNode;
    return at(modelRoot, doc.uri.fsPath, cst?.range, severity, code, message);
}

function findProperty(node: AstNode, property: string): AstNode['$cstNode'] {
    const value = (node as unknown as Record<string, unknown>)[property];
    if (value && typeof value === 'object' && '$refNode' in value) return (value as { $refNode?: AstNode['$cstNode'] }).$refNode;
    return GrammarUtils.findNodeForProperty(node.$cstNode, property);
}

export function findingDiagnostic(modelRoot: string, f: AppFinding): GenerationDiagnostic {
    // A violated generator rule is reported on the model element that violates it.
    if (f.modelNode) return nodeDiagnostic(modelRoot, f.modelNode, f.severity, f.code, f.message);
    return nodeDiagnostic(modelRoot, f.node, f.severity, f.code, f.message, f.property);
}

/** Whether a diagnostic of the configuration file lies inside a platform block. */
export function inside(d: CheckDiagnostic, p: AppPlatform): boolean {
    const r = p.$cstNode?.range;
    if (!r) return false;
    const line = d.line - 1;
    const col = d.column - 1;
    const afterStart = line > r.start.line || (line === r.start.line && col >= r.start.character);
    const beforeEnd = line < r.end.line || (line === r.end.line && col <= r.end.character);
    return afterStart && beforeEnd;
}

/** Without duplicates, by file, line, column and code. */
export function sortDiagnostics(ds: readonly GenerationDiagnostic[]): GenerationDiagnostic[] {
    const seen = new Set<string>();
    return [...ds]
        .filter((d) => {
            const k = `${d.file}:${d.line}:${d.column}:${d.code}:${d.message}`;
            if (seen.has(k)) return false;
            seen.add(k);
            return true;
        })
        .sort(
            (a, b) =>
                (a.file < b.file ? -1 : a.file > b.file ? 1 : 0) ||
                a.line - b.line ||
                a.column - b.column ||
                (a.code < b.code ? -1 : a.code > b.code ? 1 : 0),
        );
}
