import { describe, expect, test } from 'vitest';
import { APP_DIAGNOSTICS, AppCodes } from '../src/index.js';
import { dump, validate } from './helpers.js';

// Every documented diagnostic is checked on its invalid and its valid example, so the catalog
// (and docs/diagnostics.md, generated from it) cannot drift from the checker.
describe.each(APP_DIAGNOSTICS.entries.map((e) => [e.code, e] as const))('%s', (code, entry) => {
    test('is reported on the invalid example', async () => {
        const found = await validate(entry.invalid.files);
        const hits = found.filter((f) => f.code === code);
        expect(hits, dump(found)).not.toHaveLength(0);
        expect(hits.map((h) => h.severity)).toContain(entry.severity);
        if (entry.invalid.at !== undefined) expect(hits.map((h) => h.text)).toContain(entry.invalid.at);
        for (const h of hits) expect(h.message.length).toBeGreaterThan(20);
        // The invalid example shows this one problem only.
        expect(
            found.filter((f) => f.code !== code),
            dump(found),
        ).toEqual([]);
    });
    test('is not reported on the valid example, which has no diagnostics at all', async () => {
        const found = await validate(entry.valid.files);
        expect(found, dump(found)).toEqual([]);
    });
});

test('every app code is documented', () => {
    const documented = new Set(APP_DIAGNOSTICS.entries.map((e) => e.code));
    for (const code of Object.values(AppCodes)) expect(documented).toContain(code);
});
