// The lab load benchmark's figures (packages/lab-server/bench/stats.mjs).
import { describe, expect, it } from 'vitest';
import { median, percentile, summarize } from '../bench/stats.mjs';

describe('lab bench figures', () => {
    it('takes percentiles by nearest rank', () => {
        const values = Array.from({ length: 100 }, (_, i) => 100 - i); // 100 .. 1, unsorted
        expect(percentile(values, 50)).toBe(50);
        expect(percentile(values, 90)).toBe(90);
        expect(percentile(values, 99)).toBe(99);
        expect(percentile(values, 100)).toBe(100);
        expect(percentile([7], 99)).toBe(7);
        expect(percentile([3, 1, 2], 50)).toBe(2);
        expect(percentile([], 50)).toBeNaN();
    });

    it('takes the median of odd and even counts', () => {
        expect(median([3, 1, 2])).toBe(2);
        expect(median([4, 1, 3, 2])).toBe(2.5);
        expect(median([])).toBeNaN();
    });

    it('summarizes per kind and overall', () => {
        const samples = [
            { kind: 'save', ms: 10, ok: true },
            { kind: 'save', ms: 30, ok: false },
            { kind: 'generate', ms: 500, ok: true },
        ];
        const rows = summarize(samples, 2);
        expect(rows.map((r: { kind: string }) => r.kind)).toEqual(['save', 'generate', 'overall']);
        expect(rows[0]).toMatchObject({ count: 2, perSecond: 1, p50: 10, p99: 30, errors: 1 });
        expect(rows[2]).toMatchObject({ count: 3, perSecond: 1.5, p50: 30, p99: 500, errors: 1 });
    });
});
