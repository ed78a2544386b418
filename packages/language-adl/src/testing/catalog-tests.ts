import { describe, expect, test } from 'vitest';
import type { DiagnosticCatalog } from '../diagnostic-catalog/catalog.js';
import { dump, type Finding } from './model-validation.js';

/**
 * Checks every documented diagnostic on its invalid and its valid example, so a catalog (and
 * docs/diagnostics.md, rendered from the catalogs) cannot drift from the checker.
 * `strict`: the invalid example shows only its own problem and the valid one has no diagnostic
 * at all; otherwise the valid example only has to be free of errors and of the code itself.
 */
export function describeCatalog(
    catalog: DiagnosticCatalog,
    validate: (files: Readonly<Record<string, string>>) => Promise<Finding[]>,
    /** `codes`: the codes the catalog must document (each catalog entry's code appears once). */
    options: { strict?: boolean; codes?: readonly string[] } = {},
): void {
    describe.each(catalog.entries.map((e) => [e.code, e] as const))('%s', (code, entry) => {
        test('is reported on the invalid example', async () => {
            const found = await validate(entry.invalid.files);
            const own = found.filter((f) => f.code === code);
            expect(own, dump(found)).not.toHaveLength(0);
            expect(own.map((h) => h.severity)).toContain(entry.severity);
            if (entry.invalid.at !== undefined) expect(own.map((h) => h.text)).toContain(entry.invalid.at);
            for (const h of own) expect(h.message.length).toBeGreaterThan(10);
            if (options.strict)
                expect(
                    found.filter((f) => f.code !== code),
                    dump(found),
                ).toEqual([]);
        });
        test(
            options.strict
                ? 'is not reported on the valid example, which has no diagnostics'
                : 'is not reported on the valid example, which has no errors',
            async () => {
                const found = await validate(entry.valid.files);
                const unwanted = options.strict ? found : found.filter((f) => f.code === code || f.severity === 'error');
                expect(unwanted, dump(found)).toEqual([]);
            },
        );
    });
    if (options.codes) {
        test(`every code of "${catalog.title}" is documented, once`, () => {
            const documented = catalog.entries.map((e) => e.code);
            expect(new Set(documented).size).toBe(documented.length);
            for (const code of options.codes!) expect(documented).toContain(code);
        });
    }
}
