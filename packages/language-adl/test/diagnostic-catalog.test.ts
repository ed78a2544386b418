import { describe, expect, test } from 'vitest';
import { ADL_DIAGNOSTICS } from '../src/index.js';
import { validate } from './helpers.js';

// Every documented diagnostic is checked on its invalid and its valid example, so the catalog
// (and docs/diagnostics.md, generated from it) cannot drift from the checker.
describe.each(ADL_DIAGNOSTICS.entries.map((e) => [e.code, e] as const))('%s', (code, entry) => {
    test('is reported on the invalid example', async () => {
        const found = await validate(entry.invalid.files);
        const hits = found.filter((f) => f.code === code);
        expect(hits, JSON.stringify(found, null, 1)).not.toHaveLength(0);
        expect(hits.map((h) => h.severity)).toContain(entry.severity);
        if (entry.invalid.at !== undefined) expect(hits.map((h) => h.text)).toContain(entry.invalid.at);
        for (const h of hits) expect(h.message.length).toBeGreaterThan(10);
    });
    test('is not reported on the valid example, which has no errors', async () => {
        const found = await validate(entry.valid.files);
        expect(found.filter((f) => f.code === code || f.severity === 'error'), JSON.stringify(found, null, 1)).toEqual([]);
    });
});
