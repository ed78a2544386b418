import type { CheckDiagnostic } from '@maa/language-server';
import type { CheckSummary } from '../summary.js';

/** The JSON report of `check`: exactly one object, documented in docs/cli.md. */
export interface JsonReport {
    diagnostics: CheckDiagnostic[];
    summary: CheckSummary;
}

/** A diagnostic in the JSON reports of `check` and `generate`: the documented fields, picked explicitly so the shape stays stable. */
export function jsonDiagnostic(d: CheckDiagnostic): CheckDiagnostic {
    return {
        root: d.root,
        file: d.file,
        line: d.line,
        column: d.column,
        endLine: d.endLine,
        endColumn: d.endColumn,
        severity: d.severity,
        code: d.code,
        message: d.message,
    };
}

export function formatJson(diagnostics: readonly CheckDiagnostic[], summary: CheckSummary): string {
    const report: JsonReport = {
        diagnostics: diagnostics.map(jsonDiagnostic),
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
