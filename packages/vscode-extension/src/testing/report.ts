/**
 * The JSON report of `maa-gen test --format json` (and of the IDE backend's `POST /api/test`,
 * which answers the same shape) and how each result becomes a test outcome: passed, failed (an
 * expected stream, state or `empty` that did not hold, with expected and produced values for a
 * diff at the failing statement) or errored (the case could not run as written: a port the
 * component does not have, a crash of the component, a file that does not parse). Pure.
 */
import type { Span, StreamCase } from './stream-file.js';

/** One test's result: `test` is null for a file whose tests did not run (the problem says why). */
export interface StreamTestResult {
    readonly file: string;
    readonly test: string | null;
    /** The 1-based line of the `test` keyword (0 for a file-level result). */
    readonly line: number;
    readonly passed: boolean;
    readonly problems: readonly string[];
}

export interface StreamTestReport {
    readonly results: readonly StreamTestResult[];
    readonly summary: { readonly passed: number; readonly failed: number };
}

function isResult(x: unknown): x is StreamTestResult {
    if (typeof x !== 'object' || x === null) return false;
    const r = x as Record<string, unknown>;
    return (
        typeof r['file'] === 'string' &&
        (typeof r['test'] === 'string' || r['test'] === null) &&
        typeof r['line'] === 'number' &&
        typeof r['passed'] === 'boolean' &&
        Array.isArray(r['problems']) &&
        r['problems'].every((p) => typeof p === 'string')
    );
}

/** A diagnostic of the CLI's JSON report (docs/cli.md), as far as a failed generation's message needs it. */
interface ReportDiagnostic {
    readonly file: string;
    readonly line: number;
    readonly column: number;
    readonly severity: string;
    readonly message: string;
}

/** The Error of a report whose models did not generate: its errors, one a line (`file:line:column: message`). */
function generationFailed(diagnostics: readonly ReportDiagnostic[]): Error {
    const errors = diagnostics.filter((d) => d.severity === 'error').map((d) => `${d.file}:${d.line}:${d.column}: ${d.message}`);
    return new Error(['generation failed; no stream test was run', ...errors].join('\n'));
}

/**
 * The report in a run's stdout. A report whose models did not generate (`summary.generated`
 * false), or no report at all (usage errors, no Python), is an Error saying why.
 */
export function parseTestReport(stdout: string, stderr: string): StreamTestReport {
    let parsed: unknown;
    try {
        parsed = JSON.parse(stdout);
    } catch {
        parsed = undefined;
    }
    const report = parsed as
        | { results?: unknown; diagnostics?: unknown; summary?: { generated?: unknown; passed?: unknown; failed?: unknown } }
        | undefined;
    if (report?.summary?.generated === false && Array.isArray(report.diagnostics)) {
        throw generationFailed(report.diagnostics as ReportDiagnostic[]);
    }
    if (
        report &&
        Array.isArray(report.results) &&
        report.results.every(isResult) &&
        typeof report.summary?.passed === 'number' &&
        typeof report.summary.failed === 'number'
    ) {
        return report as StreamTestReport;
    }
    const said = [stdout.trim(), stderr.trim()].filter((s) => s !== '').join('\n');
    throw new Error(said === '' ? 'maa-gen test gave no report' : said);
}

/** One message of an outcome: a diff when the problem compares an expected with a produced value. */
export interface OutcomeMessage {
    readonly text: string;
    readonly expected?: string;
    readonly actual?: string;
    /** Where in the file (0-based); undefined: the case's (or file's) own range. */
    readonly span?: Span;
}

export interface Outcome {
    readonly state: 'passed' | 'failed' | 'errored';
    readonly messages: readonly OutcomeMessage[];
}

const PORT_DIFF = /^([A-Za-z_]\w*): expected (.*); got (.*)$/s;
const STATE_DIFF = /^state \(line (\d+)\): expected (.*); got (.*)$/s;
const EMPTY = /^empty ([A-Za-z_]\w*): /;

/** A 0-based span covering the whole of 1-based `line`. */
function lineSpan(line: number): Span {
    return { line: line - 1, character: 0, endLine: line - 1, endCharacter: Number.MAX_SAFE_INTEGER };
}

/** One problem of a case as a message, and whether it is a comparison that failed (else the case errored). */
export function problemMessage(problem: string, kase: StreamCase | undefined): { message: OutcomeMessage; comparison: boolean } {
    const state = STATE_DIFF.exec(problem);
    if (state) {
        const line = Number(state[1]);
        return { message: { text: problem, expected: state[2]!, actual: state[3]!, span: lineSpan(line) }, comparison: true };
    }
    const port = PORT_DIFF.exec(problem);
    if (port) {
        const span = kase?.expected[port[1]!];
        return {
            message: { text: problem, expected: port[2]!, actual: port[3]!, ...(span ? { span } : {}) },
            comparison: true,
        };
    }
    if (EMPTY.test(problem)) {
        const span = kase?.empties[0];
        return { message: { text: problem, ...(span ? { span } : {}) }, comparison: true };
    }
    return { message: { text: problem }, comparison: false };
}

/** The outcome of one case's result. */
export function caseOutcome(result: StreamTestResult, kase: StreamCase | undefined): Outcome {
    if (result.passed) return { state: 'passed', messages: [] };
    const mapped = result.problems.map((p) => problemMessage(p, kase));
    const messages = mapped.length > 0 ? mapped.map((m) => m.message) : [{ text: 'the test failed' }];
    return { state: mapped.length > 0 && mapped.every((m) => m.comparison) ? 'failed' : 'errored', messages };
}

/** The outcome of a file whose tests did not run (`test` null): errored, at the line the problem names. */
export function fileOutcome(result: StreamTestResult): Outcome {
    return {
        state: 'errored',
        messages: result.problems.map((p) => {
            const line = /\.stream:(\d+):/.exec(p)?.[1];
            return line ? { text: p, span: lineSpan(Number(line)) } : { text: p };
        }),
    };
}

/** The result of a case in a file's results: the one at its line, else the first of its name. */
export function resultOfCase(results: readonly StreamTestResult[], kase: StreamCase): StreamTestResult | undefined {
    return results.find((r) => r.test === kase.name && r.line === kase.range.line + 1) ?? results.find((r) => r.test === kase.name);
}
