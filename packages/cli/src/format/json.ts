import type { CheckDiagnostic } from '@maa/language-server';
import type { CheckSummary } from '../summary.js';

/** The JSON report of `check`: exactly one object, documented in docs/cli.md. */
export interface JsonReport {
    diagnostics: CheckDiagnostic[];
    summary: CheckSummary;
}

export function formatJson(diagnostics: readonly CheckDiagnostic[], summary: CheckSummary): string {
    const report: JsonReport = {
        // Pick the documented fields explicitly so the shape stays stable.
        diagnostics: diagnostics.map((d) => ({
            root: d.root,
            file: d.file,
            line: d.line,
            column: d.column,
            endLine: d.endLine,
            endColumn: d.endColumn,
            severity: d.severity,
            code: d.code,
            message: d.message,
        })),
        summary: {
            errors: summary.errors,
            warnings: summary.warnings,
            infos: summary.infos,
            files: summary.files,
            roots: summary.roots,
        },
    };
    return `${JSON.stringify(report, null, 2)}\n`;
}
