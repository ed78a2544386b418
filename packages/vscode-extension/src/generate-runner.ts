/**
 * What **MontiArc: Generate** runs, behind one small interface: on the desktop the `maa-gen` CLI
 * (extension.ts), in the browser the IDE backend's `POST /api/generate` (web/backend.ts). Both
 * answer a GenerateReport, so the command (generate-command.ts) is the same code in both hosts.
 * Pure: no `vscode`, no Node built-ins.
 */
import type { GenerateAnswer } from '@maa/protocol';
import type { GenerateReport, ReportDiagnostic } from './generate-report.js';

/** One generation: the application configuration and the platform picked. */
export interface GenerateRequest {
    /** The `.arcapp` file: an absolute path (desktop) or a path below the workspace root (web). */
    readonly appFile: string;
    readonly platform: string;
}

/** Runs a generation; `signal` aborts it (the progress notification's Cancel). */
export interface GenerateRunner {
    run(request: GenerateRequest, signal: AbortSignal): Promise<GenerateReport>;
}

const SEVERITIES = new Set<ReportDiagnostic['severity']>(['error', 'warning', 'info', 'hint']);

function severityOf(s: string): ReportDiagnostic['severity'] {
    return SEVERITIES.has(s as ReportDiagnostic['severity']) ? (s as ReportDiagnostic['severity']) : 'error';
}

/** `root` + `/` + `file`, one slash between them. */
function joinPath(root: string, file: string): string {
    return `${root.replace(/\/+$/, '')}/${file.replace(/^\/+/, '')}`;
}

/**
 * The backend's answer as the CLI report: its diagnostics carry 0-based LSP ranges and paths
 * relative to the workspace, the report 1-based positions and absolute paths below `root`
 * (the workspace folder's path, `/workspace` in the browser IDE).
 */
export function reportFromAnswer(answer: GenerateAnswer, root: string): GenerateReport {
    const byFile = new Map<string, ReportDiagnostic[]>();
    let errors = 0;
    let warnings = 0;
    for (const d of answer.diagnostics) {
        const severity = severityOf(d.severity);
        if (severity === 'error') errors++;
        if (severity === 'warning') warnings++;
        const file = joinPath(root, d.file);
        const list = byFile.get(file) ?? [];
        list.push({
            file,
            line: d.range.start.line + 1,
            column: d.range.start.character + 1,
            endLine: d.range.end.line + 1,
            endColumn: d.range.end.character + 1,
            severity,
            code: d.code,
            message: d.message,
        });
        byFile.set(file, list);
    }
    return { ok: answer.ok, byFile, errors, warnings, files: answer.files.length, outDirs: [] };
}
