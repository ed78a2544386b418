import { describe, expect, test } from 'vitest';
import { validate } from './helpers.js';
import { ARM_TYPES, LISTING_1, LISTING_2 } from './fixtures.js';

// While a model is typed, the checks see partial ASTs: they must report syntax errors and the
// like, never fail (a failing check shows up as `internal/check-failed`).
describe('partial models yield diagnostics, never a failing check', () => {
    test('every truncation of Listing 1 (.ra)', async () => {
        for (let n = 0; n < LISTING_1.length; n += 3) {
            const found = await validate({ 'ToastService.ra': LISTING_1.substring(0, n) });
            for (const f of found) expect(f.code, `cut at ${n}: ${f.message}`).toMatch(/^(syntax|robotarm|arc|link)\//);
            if (n > 10)
                expect(
                    found.some((f) => f.code.startsWith('syntax/')),
                    `cut at ${n}`,
                ).toBe(true);
        }
    });

    test('every truncation of Listing 2 (embedded)', async () => {
        for (let n = 0; n < LISTING_2.length; n += 3) {
            const found = await validate({ 'ArmTypes.cd': ARM_TYPES, 'ArmController.arc': LISTING_2.substring(0, n) });
            for (const f of found) expect(f.code, `cut at ${n}: ${f.message}`).toMatch(/^(syntax|robotarm|arc|link)\//);
        }
    });
});
