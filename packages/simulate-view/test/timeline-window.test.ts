import { describe, expect, it } from 'vitest';
import { MIN_SPAN, TimeWindow, formatTime, tOf, timeTicks, xOf } from '../src/timeline/window.js';

describe('TimeWindow', () => {
    it('follows the newest data: the whole run while short, then the newest 10 s', () => {
        const w = new TimeWindow();
        expect(w.following).toBe(true);
        expect(w.span(0, 4)).toEqual({ t0: 0, t1: 4 });
        expect(w.span(0, 25)).toEqual({ t0: 15, t1: 25 });
        const empty = w.span(undefined, undefined);
        expect(empty.t0).toBe(0);
        expect(empty.t1).toBeGreaterThan(0);
    });

    it('zooms around the anchor and stops following', () => {
        const w = new TimeWindow();
        w.zoom({ t0: 0, t1: 10 }, 0.5, 5);
        expect(w.following).toBe(false);
        expect(w.span(0, 100)).toEqual({ t0: 2.5, t1: 7.5 });
        w.zoom({ t0: 2.5, t1: 7.5 }, 2, 2.5);
        expect(w.span(0, 100)).toEqual({ t0: 2.5, t1: 12.5 });
    });

    it('does not zoom below the smallest span or with a bad factor', () => {
        const w = new TimeWindow();
        w.zoom({ t0: 0, t1: 1 }, 1e-9, 0);
        const s = w.span(0, 1);
        expect(s.t1 - s.t0).toBeCloseTo(MIN_SPAN);
        w.zoom(s, -1, 0);
        w.zoom(s, Number.NaN, 0);
        expect(w.span(0, 1)).toEqual(s);
    });

    it('pans, and follows again keeping the zoomed width', () => {
        const w = new TimeWindow();
        w.pan({ t0: 0, t1: 4 }, 1.5);
        expect(w.span(0, 100)).toEqual({ t0: 1.5, t1: 5.5 });
        w.pan({ t0: 1.5, t1: 5.5 }, Number.NaN);
        expect(w.span(0, 100)).toEqual({ t0: 1.5, t1: 5.5 });
        w.follow();
        expect(w.following).toBe(true);
        expect(w.span(0, 100)).toEqual({ t0: 96, t1: 100 });
    });

    it('sets a span around its middle', () => {
        const w = new TimeWindow();
        w.set({ t0: 1, t1: 3 });
        expect(w.span(undefined, undefined)).toEqual({ t0: 1, t1: 3 });
    });
});

describe('time axis helpers', () => {
    it('maps times to x and back', () => {
        const span = { t0: 10, t1: 20 };
        expect(xOf(15, span, 200)).toBe(100);
        expect(tOf(100, span, 200)).toBe(15);
        expect(tOf(50, span, 0)).toBe(10);
        expect(xOf(15, { t0: 1, t1: 1 }, 200)).toBe(0);
    });

    it('puts ticks on round times', () => {
        expect(timeTicks({ t0: 0, t1: 10 }, 5)).toEqual([0, 2, 4, 6, 8, 10]);
        expect(timeTicks({ t0: 0.13, t1: 0.61 }, 4)).toEqual([0.2, 0.4, 0.6]);
        expect(timeTicks({ t0: 5, t1: 5 })).toEqual([]);
    });

    it('formats times with decimals for the span', () => {
        expect(formatTime(1.23456)).toBe('1.235 s');
        expect(formatTime(1.23456, 50)).toBe('1.2 s');
        expect(formatTime(1.23456, 0.05)).toBe('1.2346 s');
    });
});
