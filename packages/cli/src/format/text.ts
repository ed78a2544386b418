import path from 'node:path';
import type { CheckDiagnostic, Severity } from '@maa/language-server';
import type { CheckSummary } from '../summary.js';

export interface TextFormatOptions {
    /** Paths are printed relative to this folder. */
    cwd: string;
    /** Colour the severity (only when writing to a terminal). */
    color: boolean;
}

const COLORS: Record<Severity, string> = { error: '31', warning: '33', info: '36', hint: '90' };

/** One line per diagnostic: `file:line:col: severity code message`. */
export function formatDiagnosticText(d: CheckDiagnostic, options: TextFormatOptions): string {
    const severity = options.color ? `\x1b[${COLORS[d.severity] ?? '0'}m${d.severity}\x1b[0m` : d.severity;
    const message = oneLine(d.message);
    return `${displayPath(d.file, options.cwd)}:${d.line}:${d.column}: ${severity} ${d.code} ${message}`;
}

export function formatDiagnosticsText(diagnostics: readonly CheckDiagnostic[], options: TextFormatOptions): string {
    return diagnostics.map((d) => `${formatDiagnosticText(d, options)}\n`).join('');
}

/**
 * Keeps a message on one line and harmless for terminals: line breaks become spaces, other
 * control characters (e.g. from a file of random bytes quoted in a syntax error) become `\xNN`.
 */
function oneLine(message: string): string {
    return (
        message
            .replace(/\s*[\r\n\u2028\u2029]+\s*/g, ' ')
            // biome-ignore lint/suspicious/noControlCharactersInRegex: control characters are what this escapes
            .replace(/[\u0000-\u0008\u000b-\u001f\u007f-\u009f]/g, (c) => `\\x${c.charCodeAt(0).toString(16).padStart(2, '0')}`)
    );
}

/** `N errors, M warnings in K files (R roots)`; infos are mentioned only when there are some. */
export function formatSummaryText(s: CheckSummary): string {
    const counts = [plural(s.errors, 'error'), plural(s.warnings, 'warning')];
    if (s.infos > 0) counts.push(plural(s.infos, 'info'));
    return `${counts.join(', ')} in ${plural(s.files, 'file')} (${plural(s.roots, 'root')})`;
}

function plural(n: number, word: string): string {
    return `${n} ${word}${n === 1 ? '' : 's'}`;
}

/** A path relative to cwd with forward slashes; absolute when the file lies outside cwd. */
export function displayPath(file: string, cwd: string): string {
    const rel = path.relative(cwd, file);
    if (rel === '' || path.isAbsolute(rel) || rel === '..' || rel.startsWith(`..${path.sep}`)) return file;
    return rel.split(path.sep).join('/');
}
