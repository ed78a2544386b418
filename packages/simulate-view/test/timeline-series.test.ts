import { describe, expect, it } from 'vitest';
import { fieldValue, numericFields, parseField, seriesPath, seriesPoints, valueRange } from '../src/timeline/series.js';
import { TimelineStore } from '../src/timeline/store.js';

describe('numeric fields of a message', () => {
    it('lists the numeric and boolean leaves with their paths', () => {
        const m = { data: 3, pose: { position: { x: 1.5, y: -2 }, name: 'p' }, flags: [true, 'no', 4], nan: null };
        expect(numericFields(m)).toEqual(['data', 'pose.position.x', 'pose.position.y', 'flags[0]', 'flags[2]']);
        expect(numericFields(7)).toEqual(['']);
        expect(numericFields({ text: 'a' })).toEqual([]);
    });

    it('stops listing at 64 fields', () => {
        expect(numericFields({ position: new Array(500).fill(1) })).toHaveLength(64);
    });

    it('reads a field by its path', () => {
        const m = { data: 3, pose: { position: { x: 1.5 } }, a: [[0, 9]], b: false };
        expect(fieldValue(m, 'data')).toBe(3);
        expect(fieldValue(m, 'pose.position.x')).toBe(1.5);
        expect(fieldValue(m, 'a[0][1]')).toBe(9);
        expect(fieldValue(m, 'b')).toBe(0);
        expect(fieldValue(5, '')).toBe(5);
    });

    it('reads nothing at a missing, non-numeric or malformed path', () => {
        const m = { data: 'x', pose: {} };
        expect(fieldValue(m, 'data')).toBeUndefined();
        expect(fieldValue(m, 'pose.position.x')).toBeUndefined();
        expect(fieldValue(m, 'pose..x')).toBeUndefined();
        expect(fieldValue(m, '.pose')).toBeUndefined();
        expect(fieldValue(null, 'data')).toBeUndefined();
        expect(parseField('a[x]')).toBeUndefined();
        expect(parseField('a.b[2]')).toEqual(['a', 'b', 2]);
    });
});

describe('series over the store', () => {
    const store = new TimelineStore();
    store.addAll([0, 1, 2, 3, 4].map((t) => ({ t, topic: '/v', message: { data: t * 10, s: 'x' } })));

    it('gives the points of a span and the last one before it', () => {
        expect(seriesPoints(store, { topic: '/v', field: 'data' }, { t0: 1.5, t1: 3 })).toEqual([
            { t: 1, v: 10 },
            { t: 2, v: 20 },
            { t: 3, v: 30 },
        ]);
        expect(seriesPoints(store, { topic: '/v', field: 's' }, { t0: 0, t1: 4 })).toEqual([]);
        expect(seriesPoints(store, { topic: '/none', field: 'data' }, { t0: 0, t1: 4 })).toEqual([]);
    });

    it('ranges values with a margin, a flat series around its value', () => {
        expect(valueRange([[{ t: 0, v: 0 }], [{ t: 1, v: 10 }]])).toEqual({ min: -0.5, max: 10.5 });
        expect(valueRange([[{ t: 0, v: 2 }]])).toEqual({ min: 1, max: 3 });
        expect(valueRange([[], []])).toBeUndefined();
    });

    it('draws a step line that holds each value until the next and to the end of the span', () => {
        const pts = [
            { t: 0, v: 0 },
            { t: 5, v: 10 },
        ];
        expect(seriesPath(pts, { t0: 0, t1: 10 }, { min: 0, max: 10 }, 100, 50)).toBe('M 0 50 H 50 V 0 H 100');
        expect(seriesPath([], { t0: 0, t1: 10 }, { min: 0, max: 10 }, 100, 50)).toBe('');
    });

    it('collapses points that fall on the same pixel', () => {
        const pts = Array.from({ length: 1000 }, (_, i) => ({ t: i / 1000, v: 1 }));
        const path = seriesPath(pts, { t0: 0, t1: 1 }, { min: 0, max: 2 }, 10, 10);
        expect(path.split('H').length).toBeLessThan(25);
    });
});
