/**
 * A documented diagnostic: its rule and one invalid and one valid example. Each language
 * package exports its catalog; the tests check every example (so the documentation cannot drift
 * from the checker) and `docs/diagnostics.md` is generated from the catalogs.
 */
export interface DiagnosticExample {
    /** Model files by path relative to the model root. */
    readonly files: Readonly<Record<string, string>>;
    /** For invalid examples: the source text the diagnostic must cover. */
    readonly at?: string;
}

export interface CatalogEntry {
    readonly code: string;
    readonly severity: 'error' | 'warning';
    readonly rule: string;
    readonly invalid: DiagnosticExample;
    readonly valid: DiagnosticExample;
}

export interface DiagnosticCatalog {
    readonly title: string;
    readonly intro: string;
    readonly entries: readonly CatalogEntry[];
}
