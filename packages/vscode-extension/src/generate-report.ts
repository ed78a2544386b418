/**
 * Reads `maa-gen generate --format json`'s report (docs/cli.md) into diagnostics per file and a
 * summary line. Pure: the extension turns the result into a DiagnosticCollection.
 */

/** One diagnostic of the report (1-based positions, absolute file). */
export interface ReportDiagnostic {
    readonly file: string;
    readonly line: number;
    readonly column: number;
    readonly endLine: number;
    readonly endColumn: number;
    readonly severity: 'error' | 'warning' | 'info' | 'hint';
    readonly code: string;
    readonly message: string;
}

export interface GenerateReport {
    readonly ok: boolean;
    /** Diagnostics grouped by absolute file. */
    readonly byFile: Map<string, ReportDiagnostic[]>;
    readonly errors: number;
    readonly warnings: number;
    readonly files: number;
    /** The platform folders written (`<out>/<platform>`). */
    readonly outDirs: string[];
}

function isRecord(v: unknown): v is Record<string, unknown> {
    return typeof v === 'object' && v !== null;
}

const SEVERITIES = new Set(['error', 'warning', 'info', 'hint']);

function diagnosticOf(d: unknown): ReportDiagnostic | undefined {
    if (!isRecord(d) || typeof d['file'] !== 'string' || typeof d['message'] !== 'string') return undefined;
    const num = (k: string, fallback: number): number => (typeof d[k] === 'number' ? (d[k] as number) : fallback);
    const line = num('line', 1);
    const column = num('column', 1);
    const severity = typeof d['severity'] === 'string' && SEVERITIES.has(d['severity']) ? d['severity'] : 'error';
    return {
        file: d['file'],
        line,
        column,
        endLine: num('endLine', line),
        endColumn: num('endColumn', column),
        severity: severity as ReportDiagnostic['severity'],
        code: typeof d['code'] === 'string' ? d['code'] : '',
        message: d['message'],
    };
}

/**
 * Parses the JSON report from the CLI's stdout. A report that is not JSON (a CLI too old, a crash)
 * throws with the CLI's stderr, so the user sees why instead of an empty result.
 */
export function parseGenerateReport(stdout: string, stderr = ''): GenerateReport {
    let json: unknown;
    try {
        json = JSON.parse(stdout);
    } catch {
        throw new Error(`maa-gen did not print a JSON report${stderr.trim() ? `: ${stderr.trim()}` : ''}`);
    }
    if (!isRecord(json) || !Array.isArray(json['diagnostics'])) throw new Error('maa-gen printed JSON without diagnostics');
    const byFile = new Map<string, ReportDiagnostic[]>();
    for (const raw of json['diagnostics']) {
        const d = diagnosticOf(raw);
        if (!d) continue;
        const list = byFile.get(d.file) ?? [];
        list.push(d);
        byFile.set(d.file, list);
    }
    const summary = isRecord(json['summary']) ? json['summary'] : {};
    const platforms = Array.isArray(json['platforms']) ? json['platforms'] : [];
    const count = (k: string): number => (typeof summary[k] === 'number' ? (summary[k] as number) : 0);
    return {
        ok: summary['ok'] === true,
        byFile,
        errors: count('errors'),
        warnings: count('warnings'),
        files: count('files'),
        outDirs: platforms.flatMap((p) => (isRecord(p) && typeof p['outDir'] === 'string' ? [p['outDir']] : [])),
    };
}

/** The notification after a run (`generated 12 files for timesync (0 errors, 1 warning)`). */
export function summaryMessage(platform: string, report: GenerateReport): string {
    const plural = (n: number, w: string): string => `${n} ${w}${n === 1 ? '' : 's'}`;
    const counts = `${plural(report.errors, 'error')}, ${plural(report.warnings, 'warning')}`;
    return report.ok
        ? `MontiArc: generated ${plural(report.files, 'file')} for ${platform} (${counts})`
        : `MontiArc: nothing generated for ${platform} (${counts}; see Problems)`;
}
