import { type Dirent, readdirSync } from 'node:fs';
import path from 'node:path';
import type { CheckDiagnostic, RootSpec } from '@maa/language-server';
import { isModelFile } from './roots.js';

export interface CheckSummary {
    errors: number;
    warnings: number;
    infos: number;
    /** Model files checked (a file argument counts only itself). */
    files: number;
    roots: number;
}

export function summarize(diagnostics: readonly CheckDiagnostic[], roots: readonly RootSpec[]): CheckSummary {
    const checked = new Set<string>();
    for (const spec of roots) {
        for (const file of spec.files ?? listModelFiles(spec.root)) checked.add(`${spec.root}\0${file}`);
    }
    // Never report fewer files than have diagnostics, whatever the discovery above missed.
    for (const d of diagnostics) checked.add(`${d.root}\0${d.file}`);
    return {
        errors: diagnostics.filter((d) => d.severity === 'error').length,
        warnings: diagnostics.filter((d) => d.severity === 'warning').length,
        infos: diagnostics.filter((d) => d.severity === 'info').length,
        files: checked.size,
        roots: roots.length,
    };
}

/** Model files below a root, recursively; folders that cannot be read are skipped. */
export function listModelFiles(root: string): string[] {
    const files: string[] = [];
    const walk = (dir: string): void => {
        let entries: Dirent[];
        try {
            entries = readdirSync(dir, { withFileTypes: true });
        } catch {
            return;
        }
        for (const entry of entries) {
            // Same rules as the checker's discovery: hidden folders and node_modules are not models.
            if (entry.name.startsWith('.') || entry.name === 'node_modules') continue;
            const full = path.join(dir, entry.name);
            if (entry.isDirectory()) walk(full);
            else if (entry.isFile() && isModelFile(entry.name)) files.push(full);
        }
    };
    walk(root);
    return files;
}

/** Orders diagnostics by root (argument order), then file, position and code. */
export function sortDiagnostics(diagnostics: readonly CheckDiagnostic[], roots: readonly RootSpec[]): CheckDiagnostic[] {
    const rootIndex = new Map(roots.map((r, i) => [r.root, i]));
    return [...diagnostics].sort(
        (a, b) =>
            (rootIndex.get(a.root) ?? Infinity) - (rootIndex.get(b.root) ?? Infinity) ||
            compare(a.file, b.file) ||
            a.line - b.line ||
            a.column - b.column ||
            compare(a.code, b.code) ||
            compare(a.message, b.message),
    );
}

function compare(a: string, b: string): number {
    return a < b ? -1 : a > b ? 1 : 0;
}
