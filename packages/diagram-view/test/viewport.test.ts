import { describe, expect, it } from 'vitest';
import { fitViewport, READABLE_ZOOM, SMALLEST_FONT, unionBounds } from '../src/viewport.js';

const canvas = { width: 600, height: 400 };
const options = { padding: 20, maxZoom: 1.5, minZoom: 0.02 };

/** The content box in canvas pixels under a viewport. */
function onCanvas(b: { x: number; y: number; width: number; height: number }, v: { scroll: { x: number; y: number }; zoom: number }) {
    return { x: (b.x - v.scroll.x) * v.zoom, y: (b.y - v.scroll.y) * v.zoom, width: b.width * v.zoom, height: b.height * v.zoom };
}

describe('fitViewport', () => {
    it('centres a small diagram at the maximum zoom', () => {
        const content = { x: 10, y: 10, width: 100, height: 50 };
        const v = fitViewport(content, canvas, options);
        expect(v.zoom).toBe(1.5);
        const c = onCanvas(content, v);
        expect(c.x + c.width / 2).toBeCloseTo(300);
        expect(c.y + c.height / 2).toBeCloseTo(200);
    });

    it('shrinks a larger diagram until it fits within the padding', () => {
        const content = { x: 0, y: 0, width: 2000, height: 800 };
        const v = fitViewport(content, canvas, options);
        expect(v.zoom).toBeCloseTo(560 / 2000);
        const c = onCanvas(content, v);
        expect(c.x).toBeCloseTo(20);
        expect(c.x + c.width).toBeCloseTo(580);
        expect(c.y).toBeGreaterThanOrEqual(20);
        expect(c.y + c.height).toBeLessThanOrEqual(380);
    });

    it('keeps a diagram too tall for the minimum zoom on the canvas: top edge shown, centred across', () => {
        // 200 subcomponents in one layer: about 30,000 px high.
        const content = { x: 0, y: 0, width: 700, height: 30_000 };
        const v = fitViewport(content, canvas, options);
        expect(v.zoom).toBe(0.02);
        const c = onCanvas(content, v);
        expect(c.y).toBeCloseTo(20); // the top of the diagram, below the padding
        expect(c.x + c.width / 2).toBeCloseTo(300); // centred horizontally, where it fits
        expect(c.x).toBeGreaterThanOrEqual(0);
        expect(c.x + c.width).toBeLessThanOrEqual(600);
    });

    it('with a readable zoom, shows a huge diagram from its top at the zoom that fits its width', () => {
        const tall = { x: 0, y: 0, width: 267, height: 30_000 };
        const v = fitViewport(tall, canvas, { ...options, readableZoom: 0.3 });
        expect(v.zoom).toBe(1.5); // 560 / 267 would be 2.1: capped by maxZoom
        expect(onCanvas(tall, v).y).toBeCloseTo(20);
        const huge = { x: 0, y: 0, width: 20_000, height: 30_000 };
        const w = fitViewport(huge, canvas, { ...options, readableZoom: 0.3 });
        expect(w.zoom).toBe(0.3); // never below the readable zoom
        const c = onCanvas(huge, w);
        expect([c.x, c.y]).toEqual([expect.closeTo(20), expect.closeTo(20)]); // the top left corner
        // A diagram that fits at a readable zoom is fitted as without the option.
        const small = { x: 0, y: 0, width: 1000, height: 600 };
        expect(fitViewport(small, canvas, { ...options, readableZoom: 0.3 })).toEqual(fitViewport(small, canvas, options));
    });

    it('opens a diagram wider than the pane readable: the smallest text at 6px or more, from its left', () => {
        const content = { x: 0, y: 0, width: 1300, height: 500 };
        const v = fitViewport(content, canvas, { ...options, readableZoom: READABLE_ZOOM });
        expect(v.zoom).toBeCloseTo(READABLE_ZOOM);
        expect(v.zoom * SMALLEST_FONT).toBeGreaterThanOrEqual(6);
        expect(onCanvas(content, v).x).toBeCloseTo(20);
        // The example's architecture (912 px wide) in a side pane of 620 px is shown whole, readable.
        const example = { x: 0, y: 0, width: 912, height: 360 };
        const pane = fitViewport(example, { width: 620, height: 700 }, { ...options, readableZoom: READABLE_ZOOM });
        expect(pane.zoom).toBeGreaterThanOrEqual(READABLE_ZOOM);
        expect(onCanvas(example, pane).width).toBeLessThanOrEqual(620);
    });

    it('survives an empty content box and a hidden (zero-size) canvas', () => {
        const v = fitViewport({ x: 5, y: 5, width: 0, height: 0 }, { width: 0, height: 0 }, options);
        expect(Number.isFinite(v.zoom) && Number.isFinite(v.scroll.x) && Number.isFinite(v.scroll.y)).toBe(true);
        expect(v.zoom).toBe(0.02);
    });
});

describe('unionBounds', () => {
    it('spans every box and skips boxes without finite numbers', () => {
        expect(
            unionBounds([
                { x: 0, y: 10, width: 10, height: 10 },
                { x: -5, y: 0, width: 5, height: 5 },
                { x: NaN, y: 0, width: 1, height: 1 },
            ]),
        ).toEqual({ x: -5, y: 0, width: 15, height: 20 });
        expect(unionBounds([])).toBeUndefined();
    });
});
